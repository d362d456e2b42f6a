#include "app/cli/registry.hpp"

#include "app/commands/commands.hpp"

namespace filmdyn::cli {

const std::vector<Command>& AllCommands() {
  static const std::vector<Command> commands = [] {
    std::vector<Command> list;
    // One line per subcommand; only commands that work are listed.
    list.push_back(MakeRunCommand());
    list.push_back(MakeSweepCommand());
    list.push_back(MakeStudyCommand());
    list.push_back(MakeReproduceCommand());
    list.push_back(MakeBearingCommand());
    list.push_back(MakeSkirtCommand());
    list.push_back(MakeValidateCommand());
    list.push_back(MakeCaseFieldsCommand());
    list.push_back(MakeVersionsCommand());
    return list;
  }();
  return commands;
}

}  // namespace filmdyn::cli
