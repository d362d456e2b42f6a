#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string_view>

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

// Whether a token is an option ("--name" or "--name=value"), and its name.
bool IsOption(const std::string& token) { return token.size() > 2 && token.rfind("--", 0) == 0; }
std::string OptionName(const std::string& token) {
  const auto eq = token.find('=');
  return token.substr(2, eq == std::string::npos ? eq : eq - 2);
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
  // Before CLI11 sees them: an unknown option is named as such (CLI11 would take its value for
  // a surplus positional argument and blame that), and a flag given a value ("--json=1") is
  // refused (CLI11 would take it as a flag override; FilmDyn's flags take none).
  std::map<std::string, int> given;
  for (std::size_t k = 0; k < argv.size(); ++k) {
    const std::string& token = argv[k];
    if (!IsOption(token)) continue;
    const auto eq = token.find('=');
    const std::string name = OptionName(token);
    const OptionSpec* spec = FindSpec(specs, name);
    if (spec == nullptr) {
      throw InputError("option --" + name, "'" + token + "'",
                       "unknown option for '" + command + "'; " + AllowedOptions(specs));
    }
    if (spec->value_name.empty() && eq != std::string::npos) {
      throw InputError("option --" + spec->name, "'" + token + "'", "is a flag and takes no value");
    }
    std::string value = token;  // a flag's "value" is itself
    if (!spec->value_name.empty()) {
      if (eq != std::string::npos)
        value = token.substr(eq + 1);
      else if (k + 1 < argv.size() && IsOption(argv[k + 1]) &&
               FindSpec(specs, OptionName(argv[k + 1])) != nullptr)
        // The next token is one of the command's options: this one's value is missing (taken
        // as its value, "--out --overwrite" wrote into a folder named "--overwrite").
        throw InputError("option --" + spec->name, "(missing)",
                         "needs a value: --" + spec->name + " " + spec->value_name +
                             " (the next argument, " + argv[k + 1] + ", is an option)");
      else if (k + 1 < argv.size())
        value = argv[++k];  // its value, whatever it is
      else
        value.clear();
    }
    if (!spec->repeatable && ++given[spec->name] > 1) {
      throw InputError("option --" + spec->name, "'" + value + "'",
                       "may be given only once (it was given before)");
    }
  }
  CLI::App app{"", command};
  app.set_help_flag();  // the dispatcher answers --help before parsing
  app.allow_extras();   // unknown options and surplus arguments are reported below, by name
  std::vector<std::pair<const OptionSpec*, CLI::Option*>> options;
  for (const OptionSpec& spec : specs) {
    CLI::Option* option = nullptr;
    if (spec.value_name.empty()) {
      option = app.add_flag("--" + spec.name, spec.help);
    } else {
      option = app.add_option("--" + spec.name, spec.help)->type_name(spec.value_name)->expected(1);
    }
    option->multi_option_policy(spec.repeatable ? CLI::MultiOptionPolicy::TakeAll
                                                : CLI::MultiOptionPolicy::Throw);
    options.emplace_back(&spec, option);
  }
  Args args;
  if (max_positional > 0) {
    app.add_option("positional", args.positional_)->expected(0, max_positional);
  }
  std::vector<std::string> reversed(argv.rbegin(), argv.rend());  // CLI11 pops from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ArgumentMismatch& error) {
    const std::string what = error.what();
    const std::string name = what.substr(0, what.find(':'));
    if (name == "positional") {
      throw InputError("argument", "'" + argv.back() + "'",
                       "'" + command + "' takes at most " + std::to_string(max_positional) +
                           " positional argument(s)");
    }
    const std::string bare = name.rfind("--", 0) == 0 ? name.substr(2) : name;
    const OptionSpec* spec = FindSpec(specs, bare);
    if (spec != nullptr && what.find("missing") != std::string::npos) {
      throw InputError("option --" + bare, "(missing)",
                       "needs a value: --" + bare + " " + spec->value_name);
    }
    throw InputError("option --" + bare, "'" + name + "'", "may be given only once");
  } catch (const CLI::ParseError& error) {
    throw InputError("command line", "'" + command + "'", error.what());
  }
  for (const std::string& extra : app.remaining()) {
    if (IsOption(extra)) {
      const std::string name = OptionName(extra);
      throw InputError("option --" + name, "'" + extra + "'",
                       "unknown option for '" + command + "'; " + AllowedOptions(specs));
    }
    throw InputError("argument", "'" + extra + "'",
                     max_positional == 0
                         ? "'" + command + "' takes no positional arguments"
                         : "'" + command + "' takes at most " + std::to_string(max_positional) +
                               " positional argument(s)");
  }
  // The options in command-line order, each occurrence with its value (flags: empty).
  std::map<const CLI::Option*, std::size_t> taken;
  for (const CLI::Option* option : app.parse_order()) {
    for (const auto& [spec, registered] : options) {
      if (registered != option) continue;
      std::string value;
      if (!spec->value_name.empty()) {
        const std::size_t k = taken[option]++;
        if (k < option->results().size()) value = option->results()[k];
      }
      args.options_.emplace_back(spec->name, value);
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
  // Decimal only (strtod also read "0x1770" as 6000), an optional leading '+', in any locale.
  double value = 0.0;
  if (!ParseNumber(text, value) || !std::isfinite(value)) {
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
