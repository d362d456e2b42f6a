#pragma once
/// @file Entry point logic of `filmdyn`: GUI when called alone, a subcommand otherwise.
#include <string>
#include <vector>

namespace filmdyn::cli {

/// What main() should do with the command line.
enum class LaunchKind { kGui, kCommand, kHelp, kVersion };

struct Launch {
  LaunchKind kind = LaunchKind::kGui;
  std::string command;            ///< for kCommand
  std::vector<std::string> args;  ///< arguments after the command name
};

/// Classifies argv (without the program name). Does not run anything.
Launch Classify(const std::vector<std::string>& argv);

/// `filmdyn --help`.
std::string GlobalUsage();

/// Runs a subcommand with its arguments; prints bad input as a one-line error and returns 2.
/// Unknown command names are reported the same way.
int RunCommand(const std::string& name, const std::vector<std::string>& args);

/// True when the named command needs a Qt GUI application object (plot rendering).
bool CommandNeedsGuiApplication(const std::string& name);

}  // namespace filmdyn::cli
