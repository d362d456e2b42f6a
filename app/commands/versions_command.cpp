// `filmdyn versions`: the versions of FilmDyn and of the libraries it was built with, for bug
// reports (the same list the About box shows).
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "core/base/version.hpp"
#include "ui/about_info.hpp"

namespace filmdyn::cli {

Command MakeVersionsCommand() {
  Command command;
  command.name = "versions";
  command.summary = "print the versions of FilmDyn and its libraries (Qt, VTK, Eigen, ...)";
  command.options = {{"json", "", "print one JSON object"}};
  command.run = [](const Args& args, Streams& streams) {
    const auto versions = ui::LibraryVersions();
    if (args.Has("json")) {
      nlohmann::json object;
      for (const auto& [name, version] : versions) object[name] = version;
      streams.out << object.dump(2) << "\n";
    } else {
      for (const auto& [name, version] : versions) streams.out << name << " " << version << "\n";
    }
    return 0;
  };
  return command;
}

}  // namespace filmdyn::cli
