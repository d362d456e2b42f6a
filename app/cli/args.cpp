#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "app/cli/command.hpp"
#include "core/base/input_error.hpp"

namespace filmdyn::cli {

namespace {

const OptionSpec* FindSpec(const std::vector<OptionSpec>& specs, const std::string& name) {
  for (const auto& spec : specs) {
    if (spec.name == name) return &spec;
  }
  return nullptr;
}

std::string AllowedOptions(const std::vector<OptionSpec>& specs) {
  if (specs.empty()) return "this command takes no options";
  std::string list = "allowed:";
  for (const auto& spec : specs) list += " --" + spec.name;
  return list + " --help";
}

}  // namespace

Args Args::Parse(const std::string& command, const std::vector<std::string>& argv,
                 const std::vector<OptionSpec>& specs, int max_positional) {
  Args args;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& token = argv[i];
    if (token.size() > 2 && token.rfind("--", 0) == 0) {
      std::string name = token.substr(2);
      std::optional<std::string> inline_value;
      if (const auto eq = name.find('='); eq != std::string::npos) {
        inline_value = name.substr(eq + 1);
        name = name.substr(0, eq);
      }
      const OptionSpec* spec = FindSpec(specs, name);
      if (spec == nullptr) {
        throw InputError("option --" + name, "'" + token + "'",
                         "unknown option for '" + command + "'; " + AllowedOptions(specs));
      }
      if (!spec->repeatable && args.Has(name)) {
        throw InputError("option --" + name, "'" + token + "'", "may be given only once");
      }
      std::string value;
      if (spec->value_name.empty()) {
        if (inline_value) {
          throw InputError("option --" + name, "'" + token + "'", "is a flag and takes no value");
        }
      } else if (inline_value) {
        value = *inline_value;
      } else {
        if (i + 1 >= argv.size()) {
          throw InputError("option --" + name, "(missing)",
                           "needs a value: --" + name + " " + spec->value_name);
        }
        value = argv[++i];
      }
      args.options_.emplace_back(name, value);
    } else {
      if (static_cast<int>(args.positional_.size()) >= max_positional) {
        throw InputError("argument", "'" + token + "'",
                         max_positional == 0
                             ? "'" + command + "' takes no positional arguments"
                             : "'" + command + "' takes at most " + std::to_string(max_positional) +
                                   " positional argument(s)");
      }
      args.positional_.push_back(token);
    }
  }
  return args;
}

bool Args::Has(const std::string& name) const {
  for (const auto& [key, value] : options_) {
    if (key == name) return true;
  }
  return false;
}

std::optional<std::string> Args::Value(const std::string& name) const {
  std::optional<std::string> result;
  for (const auto& [key, value] : options_) {
    if (key == name) result = value;
  }
  return result;
}

std::vector<std::string> Args::Values(const std::string& name) const {
  std::vector<std::string> result;
  for (const auto& [key, value] : options_) {
    if (key == name) result.push_back(value);
  }
  return result;
}

std::optional<double> Args::Double(const std::string& name) const {
  const auto text = Value(name);
  if (!text) return std::nullopt;
  return ParseDouble("--" + name, *text);
}

std::optional<long> Args::Integer(const std::string& name) const {
  const auto text = Value(name);
  if (!text) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text->c_str(), &end, 10);
  if (text->empty() || end != text->c_str() + text->size() || errno == ERANGE) {
    throw InputError("--" + name, "'" + *text + "'", "must be an integer");
  }
  return value;
}

double ParseDouble(const std::string& field, const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE ||
      !std::isfinite(value)) {
    throw InputError(field, "'" + text + "'", "must be a finite number");
  }
  return value;
}

std::vector<double> ParseDoubleList(const std::string& field, const std::string& text) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) values.push_back(ParseDouble(field, item));
  if (values.empty()) {
    throw InputError(field, "'" + text + "'", "must be a comma-separated list of numbers");
  }
  return values;
}

std::string CommandUsage(const Command& command) {
  std::ostringstream out;
  out << "Usage: filmdyn " << command.name;
  if (!command.options.empty()) out << " [options]";
  if (!command.positional_usage.empty()) out << " " << command.positional_usage;
  out << "\n\n" << command.summary << "\n";
  if (!command.details.empty()) out << "\n" << command.details << "\n";
  if (!command.options.empty()) {
    out << "\nOptions:\n";
    for (const auto& spec : command.options) {
      std::string left = "  --" + spec.name;
      if (!spec.value_name.empty()) left += " " + spec.value_name;
      if (left.size() < 28)
        left.resize(28, ' ');
      else
        left += "  ";
      out << left << spec.help << (spec.repeatable ? " (repeatable)" : "") << "\n";
    }
  }
  out << "  --help                    this text\n";
  return out.str();
}

}  // namespace filmdyn::cli
