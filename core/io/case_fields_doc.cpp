#include "core/io/case_fields_doc.hpp"

#include <sstream>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/case_file.hpp"

namespace filmdyn::io {

namespace {

// A default's number as the table shows it: FormatValue's digits, or every digit it needs where
// those, typed back, would fall outside the field's range (a default at a range's end, such as
// 8 pi).
std::string Shown(const engine::CaseField& field, double value) {
  return FormatOnItsSide(value, FormatValue(value), [&field](double x) { return field.Allows(x); });
}

std::string DefaultText(const engine::CaseField& field, engine::EngineCase& c) {
  switch (field.kind) {
    case engine::FieldKind::kText: {
      const std::string& text = field.text(c);
      return text.size() > 40 ? "(text)" : "\"" + text + "\"";
    }
    case engine::FieldKind::kChoice:
      return "\"" + field.ChoiceName(c) + "\"";
    case engine::FieldKind::kNumber:
    case engine::FieldKind::kInteger:
      return Shown(field, field.get(c));
    case engine::FieldKind::kNumberList: {
      std::string text = "[";
      for (double v : field.list(c)) text += (text.size() > 1 ? ", " : "") + Shown(field, v);
      return text + "]";
    }
  }
  return {};
}

std::string Escape(std::string text) {
  for (std::size_t at = 0; (at = text.find('|', at)) != std::string::npos; at += 2) {
    text.replace(at, 1, "\\|");
  }
  return text;
}

}  // namespace

std::string CaseFieldsMarkdown() {
  engine::EngineCase c = LoadCase({}).value;
  std::ostringstream out;
  out << "| field | unit | allowed | default | description |\n|---|---|---|---|---|\n";
  for (const engine::CaseField& field : engine::CaseSchema()) {
    std::string description = field.label + ": " + field.help;
    if (const auto note = c.assumed.find(field.path); note != c.assumed.end()) {
      description += ". **Assumed**: " + note->second;
    }
    out << "| `" << field.path << "` | " << (field.unit.empty() ? "" : field.unit) << " | "
        << Escape(field.RangeText()) << " | " << Escape(DefaultText(field, c)) << " | "
        << Escape(description) << " |\n";
  }
  return out.str();
}

std::string CaseFieldsText() {
  engine::EngineCase c = LoadCase({}).value;
  std::ostringstream out;
  for (const engine::CaseField& field : engine::CaseSchema()) {
    out << field.path << " [" << (field.unit.empty() ? "-" : field.unit) << "] "
        << field.RangeText() << " (default " << DefaultText(field, c) << "): " << field.label
        << "\n";
  }
  return out.str();
}

}  // namespace filmdyn::io
