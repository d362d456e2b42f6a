#pragma once
/// @file The subcommand framework of the one executable `filmdyn`.
///
/// A subcommand is a `Command`: a name, a one-line summary, its options and a run function.
/// Commands live one per file in app/commands/<name>_command.cpp, expose
/// `cli::Command Make<Name>Command();` (declared in app/commands/commands.hpp) and are listed
/// once in app/cli/registry.cpp. Only commands that work are registered, so `--help` never
/// advertises something that does not exist.
///
/// Bad input (unknown option, missing value, a number that is not one, a value out of range)
/// throws filmdyn::InputError; the dispatcher prints it on one line and exits with code 2.
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace filmdyn::cli {

/// One `--name [VALUE]` option. An empty value_name makes it a flag.
struct OptionSpec {
  std::string name;        ///< without the leading dashes, e.g. "rpm"
  std::string value_name;  ///< e.g. "N"; empty for flags
  std::string help;
  bool repeatable = false;  ///< may be given several times (e.g. --set)
};

/// The parsed command line of one subcommand.
class Args {
 public:
  /// Parses argv (after the subcommand name). Accepts `--name value` and `--name=value`.
  /// Throws InputError naming the option for unknown options, a missing value, a repeated
  /// non-repeatable option, or more than max_positional positional arguments.
  static Args Parse(const std::string& command, const std::vector<std::string>& argv,
                    const std::vector<OptionSpec>& specs, int max_positional);

  bool Has(const std::string& name) const;
  /// The (last) value of an option, if given.
  std::optional<std::string> Value(const std::string& name) const;
  /// All values of a repeatable option, in order.
  std::vector<std::string> Values(const std::string& name) const;
  /// Numeric values; throw InputError("--name", text, "must be a number ...") when not numeric.
  std::optional<double> Double(const std::string& name) const;
  std::optional<long> Integer(const std::string& name) const;
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::vector<std::pair<std::string, std::string>> options_;  // in command-line order
  std::vector<std::string> positional_;
};

/// Parses a whole string as a finite double; throws InputError(field, text, allowed) otherwise.
double ParseDouble(const std::string& field, const std::string& text);
/// Parses a comma-separated list of doubles ("1000,2000"); throws InputError naming the field.
std::vector<double> ParseDoubleList(const std::string& field, const std::string& text);

/// Where a command writes: normal output and progress/errors.
struct Streams {
  std::ostream& out;
  std::ostream& err;
};

struct Command {
  std::string name;
  std::string summary;           ///< one line for `filmdyn --help`
  std::string positional_usage;  ///< e.g. "[CASE.json]"; empty when none
  int max_positional = 0;
  std::vector<OptionSpec> options;
  std::string details;  ///< optional paragraph for `filmdyn <name> --help`
  /// Needs a Qt GUI application object (plot export): created on the offscreen platform when
  /// there is no display.
  bool needs_gui_application = false;
  std::function<int(const Args&, Streams&)> run;
};

/// Usage text of one command, as printed by `filmdyn <name> --help`.
std::string CommandUsage(const Command& command);

}  // namespace filmdyn::cli
