#include "app/cli/dispatcher.hpp"

#include <exception>
#include <iostream>
#include <sstream>

#include "app/cli/registry.hpp"
#include "core/base/input_error.hpp"
#include "core/base/version.hpp"

namespace filmdyn::cli {

namespace {

const Command* FindCommand(const std::string& name) {
  for (const auto& command : AllCommands()) {
    if (command.name == name) return &command;
  }
  return nullptr;
}

std::string CommandNames() {
  std::string names;
  for (const auto& command : AllCommands()) names += (names.empty() ? "" : ", ") + command.name;
  return names;
}

}  // namespace

Launch Classify(const std::vector<std::string>& argv) {
  Launch launch;
  if (argv.empty()) return launch;
  const std::string& first = argv.front();
  if (first == "--help" || first == "-h" || first == "help") {
    if (first == "help" && argv.size() > 1) {
      launch.kind = LaunchKind::kCommand;
      launch.command = argv[1];
      launch.args = {"--help"};
      return launch;
    }
    launch.kind = LaunchKind::kHelp;
    return launch;
  }
  if (first == "--version" || first == "-v") {
    launch.kind = LaunchKind::kVersion;
    return launch;
  }
  launch.kind = LaunchKind::kCommand;
  launch.command = first;
  launch.args.assign(argv.begin() + 1, argv.end());
  return launch;
}

std::string GlobalUsage() {
  std::ostringstream out;
  out << "FilmDyn " << Version()
      << " - engine dynamics with lubricated piston skirt and big-end bearing\n\n"
         "Usage:\n"
         "  filmdyn                      open the desktop application\n"
         "  filmdyn <command> [options]  run a command headless\n"
         "  filmdyn <command> --help     options of one command\n"
         "  filmdyn --version            version\n\nCommands:\n";
  for (const auto& command : AllCommands()) {
    std::string left = "  " + command.name;
    if (left.size() < 14) left.resize(14, ' ');
    out << left << command.summary << "\n";
  }
  out << "\nExit status: 0 on success, 2 for bad input (the reason on stderr), 1 when a run\n"
         "cannot complete (partial results kept), 3 when the skirt or bearing calculator finds\n"
         "no equilibrium (the reason on stderr).\n";
  return out.str();
}

bool CommandNeedsGuiApplication(const std::string& name) {
  const Command* command = FindCommand(name);
  return command != nullptr && command->needs_gui_application;
}

int RunCommand(const std::string& name, const std::vector<std::string>& args) {
  const Command* command = FindCommand(name);
  if (command == nullptr) {
    std::cerr << "filmdyn: error: unknown command '" << name << "'; commands: " << CommandNames()
              << " (see filmdyn --help)\n";
    return 2;
  }
  for (const auto& arg : args) {
    if (arg == "--help" || arg == "-h") {
      std::cout << CommandUsage(*command);
      return 0;
    }
  }
  Streams streams{std::cout, std::cerr};
  try {
    const Args parsed = Args::Parse(name, args, command->options, command->max_positional);
    return command->run(parsed, streams);
  } catch (const InputError& error) {
    std::cerr << "filmdyn " << name << ": error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "filmdyn " << name << ": failed: " << error.what() << "\n";
    return 1;
  }
}

}  // namespace filmdyn::cli
