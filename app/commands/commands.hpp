#pragma once
/// @file One factory per subcommand (one file each in app/commands/). Register new ones in
/// app/cli/registry.cpp.
#include "app/cli/command.hpp"

namespace filmdyn::cli {

Command MakeVersionsCommand();
Command MakeCaseFieldsCommand();
Command MakeBearingCommand();
Command MakeSkirtCommand();
Command MakeRunCommand();
Command MakeSweepCommand();
Command MakeStudyCommand();
Command MakeReproduceCommand();
Command MakeValidateCommand();

}  // namespace filmdyn::cli
