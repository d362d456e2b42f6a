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

}  // namespace

std::vector<std::string> SuiteNames() {
  std::vector<std::string> names;
  for (const auto& [name, run] : Suites()) names.push_back(name);
  return names;
}

std::vector<ValidationRow> RunSuites(const std::vector<std::string>& suites) {
  const auto names = SuiteNames();
  for (const auto& wanted : suites) {
    if (std::find(names.begin(), names.end(), wanted) == names.end()) {
      std::string allowed;
      for (const auto& n : names) allowed += (allowed.empty() ? "" : ", ") + n;
      throw InputError("--suite", wanted, "unknown suite; allowed: " + allowed);
    }
  }
  std::vector<ValidationRow> rows;
  for (const auto& [name, run] : Suites()) {
    if (!suites.empty() && std::find(suites.begin(), suites.end(), name) == suites.end()) continue;
    auto suite_rows = run();
    rows.insert(rows.end(), suite_rows.begin(), suite_rows.end());
  }
  return rows;
}

}  // namespace filmdyn::verification
