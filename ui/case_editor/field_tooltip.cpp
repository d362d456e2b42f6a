#include "ui/case_editor/field_tooltip.hpp"

#include <QCoreApplication>
#include <QLocale>
#include <QStringList>
#include <cmath>
#include <exception>

#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"

namespace filmdyn::ui {

namespace {

QString Tr(const char* text) { return QCoreApplication::translate("FieldToolTip", text); }

// The display unit as shown after a number ("" for dimensionless values, shown as "–").
QString UnitSuffix(const engine::CaseField& field) {
  const QString unit = QString::fromStdString(field.display_unit);
  return unit.isEmpty() || unit == QStringLiteral("–") ? QString() : " " + unit;
}

QString DisplayNumber(double si, const engine::CaseField& field) {
  return QLocale::c().toString(field.ToDisplay(si), 'g', 6);
}

// The default case as File → New opens it: the embedded default.json (both joints lubricated),
// read once; the built-in struct defaults if it cannot be read.
const engine::EngineCase& DefaultCase() {
  static const engine::EngineCase c = [] {
    try {
      return io::LoadCase({}).value;
    } catch (const std::exception&) {
      return engine::EngineCase{};
    }
  }();
  return c;
}

}  // namespace

std::string DisplayOnItsSide(double si, const engine::CaseField& field, const std::string& shown) {
  return FormatOnItsSide(field.ToDisplay(si), shown, [&field](double display) {
    return field.Allows(field.FromDisplay(display));
  });
}

QString DisplayTypable(double si, const engine::CaseField& field) {
  return QString::fromStdString(
      DisplayOnItsSide(si, field, DisplayNumber(si, field).toStdString()));
}

QString DisplayRangeText(const engine::CaseField& field) {
  using engine::FieldKind;
  switch (field.kind) {
    case FieldKind::kText:
      return Tr("any text");
    case FieldKind::kChoice:
      return QString::fromStdString(field.ChoicesText(true));
    case FieldKind::kInteger:
      return Tr("whole number from %1 to %2")
          .arg(QLocale::c().toString(field.range.lo, 'g', 10),
               QLocale::c().toString(field.range.hi, 'g', 10));
    case FieldKind::kNumber:
    case FieldKind::kNumberList:
      break;
  }
  const engine::FieldRange& r = field.range;
  const QString unit = UnitSuffix(field);
  auto Bound = [&field](double bound, bool open) {
    return open ? DisplayNumber(bound, field) : DisplayTypable(bound, field);
  };
  QString text;
  if (std::isinf(r.lo) && std::isinf(r.hi)) {
    text = Tr("any finite number");
  } else if (std::isinf(r.hi)) {
    text = (r.lo_open ? "> " : "≥ ") + Bound(r.lo, r.lo_open) + unit;
  } else {
    text = QString("%1%2, %3%4%5")
               .arg(r.lo_open ? "(" : "[", Bound(r.lo, r.lo_open), Bound(r.hi, r.hi_open),
                    r.hi_open ? ")" : "]", unit);
  }
  return field.kind == FieldKind::kNumberList ? Tr("each %1").arg(text) : text;
}

QString DisplayDefaultText(const engine::CaseField& field) {
  using engine::FieldKind;
  auto& c = const_cast<engine::EngineCase&>(DefaultCase());  // the accessors only locate members
  switch (field.kind) {
    case FieldKind::kText: {
      const QString text = QString::fromStdString(field.text(c));
      return text.size() > 40 ? QString() : "\"" + text + "\"";
    }
    case FieldKind::kChoice:
      return QString::fromStdString(field.ChoiceTitle(std::size_t(field.choice(c))));
    case FieldKind::kNumber:
    case FieldKind::kInteger:
      return DisplayTypable(field.get(c), field) + UnitSuffix(field);
    case FieldKind::kNumberList: {
      const std::vector<double>& values = field.list(c);
      if (values.empty()) return Tr("none");
      QStringList parts;
      for (double v : values) parts << DisplayTypable(v, field);
      return parts.join(", ") + UnitSuffix(field);
    }
  }
  return {};
}

QString FieldToolTip(const engine::CaseField& field, const QString& first) {
  QStringList facts;
  const QString unit = QString::fromStdString(field.display_unit);
  if (!unit.isEmpty()) facts << Tr("Unit: %1").arg(unit.toHtmlEscaped());
  facts << Tr("Allowed: %1").arg(DisplayRangeText(field).toHtmlEscaped());
  if (const QString value = DisplayDefaultText(field); !value.isEmpty()) {
    facts << Tr("Default: %1").arg(value.toHtmlEscaped());
  }
  QString tip = "<qt>";
  if (!first.isEmpty()) tip += "<p>" + first.toHtmlEscaped() + "</p>";
  tip += "<b>" + QString::fromStdString(field.label).toHtmlEscaped() + "</b>";
  if (!field.description.empty()) {
    tip += "<p>" + QString::fromStdString(field.description).toHtmlEscaped() + "</p>";
  }
  tip += "<p>" + facts.join(" &nbsp;·&nbsp; ") + "</p>";
  if (!field.help.empty()) {
    tip += "<p>" + Tr("Note: %1").arg(QString::fromStdString(field.help).toHtmlEscaped()) + "</p>";
  }
  tip += "<p style='color:#666666'>" +
         Tr("In the case file: %1").arg(QString::fromStdString(field.path).toHtmlEscaped()) +
         "</p></qt>";
  return tip;
}

}  // namespace filmdyn::ui
