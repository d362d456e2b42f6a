// `filmdyn validate`: runs the built-in verification cases (published tables and closed forms)
// and prints one row each: suite, case, ours, reference, error, tolerance, pass.
#include <fmt/format.h>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "app/commands/commands.hpp"
#include "core/verification/all_suites.hpp"

namespace filmdyn::cli {

Command MakeValidateCommand() {
  Command command;
  command.name = "validate";
  command.summary = "run the built-in verification cases against published solutions";
  std::string suites;
  for (const std::string& name : verification::SuiteNames()) {
    suites += (suites.empty() ? "" : ", ") + name;
  }
  std::string groups;
  for (const std::string& name : verification::GroupNames()) {
    groups += (groups.empty() ? "" : ", ") + name;
  }
  command.options = {
      {"suite", "NAME", "only this suite (" + suites + ") or group of rows (" + groups + ")", true},
      {"json", "", "print the rows as one JSON array"}};
  command.details =
      "Exit status 0 when every row is within its tolerance, 1 otherwise. 'computed' is FilmDyn's\n"
      "value, 'reference' the published value or closed form it is compared with (in --json:\n"
      "'ours' and 'reference'). Error is relative (|computed - reference| / |reference|) unless\n"
      "the row says 'abs'.";
  command.run = [](const Args& args, Streams& streams) {
    const auto rows = verification::RunSuites(args.Values("suite"));
    int failed = 0;
    for (const auto& row : rows) failed += row.Pass() ? 0 : 1;
    if (args.Has("json")) {
      nlohmann::json array = nlohmann::json::array();
      for (const auto& row : rows) {
        array.push_back({{"suite", row.suite},
                         {"case", row.name},
                         {"reference_source", row.reference_source},
                         {"ours", row.ours},
                         {"reference", row.reference},
                         {"error", row.Error()},
                         {"relative", row.relative},
                         {"tolerance", row.tolerance},
                         {"pass", row.Pass()}});
      }
      streams.out << array.dump(2) << "\n";
    } else {
      streams.out << fmt::format("{:<12} {:<66} {:>14} {:>14} {:>11} {:>11}  {}\n", "suite", "case",
                                 "computed", "reference", "error", "tolerance", "pass");
      for (const auto& row : rows) {
        streams.out << fmt::format("{:<12} {:<66} {:>14.6g} {:>14.6g} {:>11.3g} {:>11.3g}{}  {}\n",
                                   row.suite, row.name, row.ours, row.reference, row.Error(),
                                   row.tolerance, row.relative ? "" : " abs",
                                   row.Pass() ? "pass" : "FAIL");
      }
      streams.out << rows.size() - failed << " of " << rows.size() << " cases pass\n";
    }
    return failed == 0 ? 0 : 1;
  };
  return command;
}

}  // namespace filmdyn::cli
