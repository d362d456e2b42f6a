#pragma once
#include <vector>

#include "app/cli/command.hpp"

namespace filmdyn::cli {

/// Every working subcommand, in the order `filmdyn --help` lists them.
const std::vector<Command>& AllCommands();

}  // namespace filmdyn::cli
