#include "core/verification/all_suites.hpp"

#include <algorithm>
#include <functional>
#include <utility>

#include "core/base/input_error.hpp"
#include "core/engine/validation_cases.hpp"
#include "core/lubrication/cavitation_validation.hpp"
#include "core/lubrication/ehd_validation.hpp"
#include "core/lubrication/oil_validation.hpp"
#include "core/lubrication/skirt_validation.hpp"
#include "core/lubrication/validation_cases.hpp"
#include "core/multibody/validation_cases.hpp"

namespace filmdyn::verification {

namespace {

const std::vector<std::pair<std::string, std::function<std::vector<ValidationRow>()>>>& Suites() {
  static const std::vector<std::pair<std::string, std::function<std::vector<ValidationRow>()>>>
      suites = {{"lubrication", [] { return lubrication::LubricationValidationRows(); }},
                {"cavitation", [] { return lubrication::CavitationValidationRows(); }},
                {"multibody",
                 [] {
                   auto rows = engine::CrankTrainValidationRows();
                   for (auto& row : multibody::MultibodyValidationRows()) rows.push_back(row);
                   return rows;
                 }},
                {"skirt", [] { return lubrication::SkirtValidationRows(); }},
                {"lubricant", [] { return lubrication::LubricantValidationRows(); }},
                {"ehd", [] { return lubrication::EhdValidationRows(); }}};
  return suites;
}

// Groups of rows inside a suite, each printed in its rows' suite column (the lubrication suite's
// finite-bearing rows say "bearing", its pocketed-slider rows "jfo"): a name the output shows is
// a name --suite takes.
const std::vector<std::pair<std::string, std::string>>& Groups() {
  static const std::vector<std::pair<std::string, std::string>> groups = {
      {"bearing", "lubrication"}, {"jfo", "lubrication"}};
  return groups;
}

}  // namespace

std::vector<std::string> SuiteNames() {
  std::vector<std::string> names;
  for (const auto& [name, run] : Suites()) names.push_back(name);
  return names;
}

std::vector<std::string> GroupNames() {
  std::vector<std::string> names;
  for (const auto& [group, suite] : Groups()) names.push_back(group);
  return names;
}

std::vector<ValidationRow> RunSuites(const std::vector<std::string>& suites) {
  const auto names = SuiteNames();
  const auto groups = GroupNames();
  const auto named = [&suites](const std::string& name) {
    return std::find(suites.begin(), suites.end(), name) != suites.end();
  };
  for (const auto& wanted : suites) {
    if (std::find(names.begin(), names.end(), wanted) == names.end() &&
        std::find(groups.begin(), groups.end(), wanted) == groups.end()) {
      std::string allowed;
      for (const auto& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
      for (const auto& [group, suite] : Groups()) allowed += ", " + group + " (of " + suite + ")";
      throw InputError("--suite", wanted, "unknown suite; allowed: " + allowed);
    }
  }
  std::vector<ValidationRow> rows;
  for (const auto& [name, run] : Suites()) {
    // The whole suite, or the rows of its groups named.
    const bool whole = suites.empty() || named(name);
    bool some = false;
    for (const auto& [group, suite] : Groups()) some = some || (suite == name && named(group));
    if (!whole && !some) continue;
    for (ValidationRow& row : run())
      if (whole || named(row.suite)) rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace filmdyn::verification
