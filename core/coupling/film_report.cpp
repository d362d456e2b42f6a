#include "core/coupling/film_report.hpp"

#include "core/lubrication/film_compliance.hpp"

#include <string>

#include "core/lubrication/reynolds_fem.hpp"
#include "core/multibody/force_element.hpp"

namespace filmdyn::coupling {

void RequireConvergedFilm(const lubrication::ReynoldsStats& stats, const char* joint,
                          lubrication::CavitationModel model,
                          const lubrication::ElasticSolveStats* elastic) {
  if (elastic != nullptr && !elastic->converged) {
    throw multibody::EvaluationFailure(std::string(joint) + " elastic film: " + elastic->message,
                                       elastic->surfaces_touch ? joint : "");
  }
  if (stats.capped_nodes > 0) {
    throw multibody::EvaluationFailure(std::string(joint) +
                                       " film beyond the pressure-viscosity "
                                       "limit at " +
                                       std::to_string(stats.capped_nodes) +
                                       " nodes (its pressure would be infinite)");
  }
  if (stats.status == lubrication::SolveStatus::kConverged) return;
  throw multibody::EvaluationFailure(std::string(joint) + " film solve " +
                                     lubrication::ToString(stats.status) + " (" +
                                     lubrication::ToString(model) + " cavitation, " +
                                     std::to_string(stats.iterations) + " iterations)");
}

}  // namespace filmdyn::coupling
