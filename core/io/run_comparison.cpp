#include "core/io/run_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/engine/run_job.hpp"
#include "core/io/output_files.hpp"
#include "core/io/run_summary.hpp"

namespace filmdyn::io {

namespace {

enum class Reduce {
  kMaxAbs,
  kMin,
  kMax,
  kMeanFplSkirt,
  kMeanFplBearing,
  kFmepSkirt,
  kFmepBearing,
  kSlapEnergyMax,
  kSlapEnergySum,
  kOilSkirt,
  kOilBearing,
  kWettedSkirt,
  kWorstError
};

/// The film joint a figure describes: none where that joint is ideal (a pin joint's journal does
/// not move off centre, an ideal piston has no secondary motion — not a zero of the quantity).
enum class Film { kAny, kSkirt, kBigEnd };

struct FigureRecipe {
  ComparisonFigure figure;
  const char* column;  ///< results.csv column in the summary's extremes
  Reduce reduce;
  Film film = Film::kAny;
  /// A peak film pressure: the joint ("skirt", "big_end") whose unresolved_peak warning leaves it
  /// out (a spike between output samples, which the steps between them saw even where the
  /// samples missed it). Any extreme the summary marks a spike is left out too.
  const char* spike_joint = nullptr;
};

const std::vector<FigureRecipe>& Recipes() {
  static const std::vector<FigureRecipe> recipes = {
      {{"max_abs_piston_lateral[m]", "max abs e0 [µm]", 1e6},
       "piston_lateral[m]",
       Reduce::kMaxAbs,
       Film::kSkirt},
      {{"max_abs_piston_tilt[rad]", "max abs γ [mrad]", 1e3},
       "piston_tilt[rad]",
       Reduce::kMaxAbs,
       Film::kSkirt},
      {{"min_skirt_moft[m]", "min skirt MOFT [µm]", 1e6},
       "skirt_moft[m]",
       Reduce::kMin,
       Film::kSkirt},
      {{"max_abs_skirt_normal_force[N]", "max abs skirt F_n [kN]", 1e-3},
       "skirt_normal_force[N]",
       Reduce::kMaxAbs},
      {{"mean_skirt_fpl[W]", "mean skirt FPL [W]", 1.0}, "", Reduce::kMeanFplSkirt},
      {{"max_bearing_eps[-]", "max ε [-]", 1.0}, "bearing_eps[-]", Reduce::kMax, Film::kBigEnd},
      {{"min_bearing_moft[m]", "min bearing MOFT [µm]", 1e6},
       "bearing_moft[m]",
       Reduce::kMin,
       Film::kBigEnd},
      {{"mean_bearing_fpl[W]", "mean bearing FPL [W]", 1.0}, "", Reduce::kMeanFplBearing},
      // Friction mean effective pressure of each joint (summary.json's kpis).
      {{"skirt_fmep[Pa]", "skirt FMEP [kPa]", 1e-3}, "", Reduce::kFmepSkirt},
      {{"bearing_fmep[Pa]", "big-end FMEP [kPa]", 1e-3}, "", Reduce::kFmepBearing},
      {{"max_abs_bigend_force_x[N]", "max abs big-end F_x [kN]", 1e-3},
       "bigend_force_x[N]",
       Reduce::kMaxAbs},
      {{"max_abs_bigend_force_y[N]", "max abs big-end F_y [kN]", 1e-3},
       "bigend_force_y[N]",
       Reduce::kMaxAbs},
      {{"max_skirt_peak_pressure[Pa]", "peak skirt film pressure [MPa]", 1e-6},
       "skirt_peak_pressure[Pa]",
       Reduce::kMax,
       Film::kSkirt,
       "skirt"},
      {{"max_skirt_contact_pressure[Pa]", "peak skirt contact pressure [MPa]", 1e-6},
       "skirt_peak_contact_pressure[Pa]",
       Reduce::kMax,
       Film::kSkirt},
      {{"max_bearing_peak_pressure[Pa]", "peak big-end film pressure [MPa]", 1e-6},
       "bearing_peak_pressure[Pa]",
       Reduce::kMax,
       Film::kBigEnd,
       "big_end"},
      {{"max_bearing_contact_pressure[Pa]", "peak big-end contact pressure [MPa]", 1e-6},
       "bearing_peak_contact_pressure[Pa]",
       Reduce::kMax,
       Film::kBigEnd},
      // Piston slap (summary.json's kpis): the largest lateral kinetic energy at a change of
      // thrust side, and their sum over the cycle.
      {{"max_slap_energy[J]", "max slap energy [mJ]", 1e3}, "", Reduce::kSlapEnergyMax},
      {{"slap_energy_sum[J]", "slap energy per cycle [mJ]", 1e3}, "", Reduce::kSlapEnergySum},
      // The oil a mass-conserving film takes in over the cycle (the headline figure of that
      // key, summary.json's kpis oil_in_per_cycle); none for a Reynolds film (no oil account).
      {{"skirt_oil_per_cycle[m^3]", "skirt oil per cycle [mm³]", 1e9}, "", Reduce::kOilSkirt},
      {{"bearing_oil_per_cycle[m^3]", "big-end oil per cycle [mm³]", 1e9}, "", Reduce::kOilBearing},
      // The mean oil-covered share of a mass-conserving skirt film (summary.json's kpis
      // mean_wetted_fraction): how starved the skirt runs.
      {{"mean_skirt_wetted_fraction[-]", "mean skirt wetted fraction [%]", 100.0},
       "",
       Reduce::kWettedSkirt},
      // The largest estimated discretisation error of the run's headline figures (relative).
      {{"max_discretisation_error[-]", "max est. discretisation error [%]", 100.0},
       "",
       Reduce::kWorstError},
  };
  return recipes;
}

// "peak big-end film pressure [MPa]" → "peak big-end film pressure".
std::string WithoutUnit(const std::string& display_name) {
  const std::size_t unit = display_name.rfind(" [");
  return unit == std::string::npos ? display_name : display_name.substr(0, unit);
}

bool SpikeWarned(const RunSummary& summary, const char* joint) {
  return joint != nullptr && std::any_of(summary.warnings.begin(), summary.warnings.end(),
                                         [joint](const RunWarning& w) {
                                           return w.code == "unresolved_peak" && w.joint == joint;
                                         });
}

std::string Cell(const std::optional<double>& value, double scale, int precision) {
  if (!value) return "–";
  std::ostringstream out;
  out << std::setprecision(precision) << *value * scale;
  return out.str();
}

}  // namespace

const std::vector<ComparisonFigure>& ComparisonFigures() {
  static const std::vector<ComparisonFigure> figures = [] {
    std::vector<ComparisonFigure> list;
    for (const auto& recipe : Recipes()) list.push_back(recipe.figure);
    return list;
  }();
  return figures;
}

ComparisonRow ReadComparisonRow(const std::filesystem::path& folder) {
  const RunSummary summary = ReadSummaryJson(folder / "summary.json");
  ComparisonRow row;
  row.folder = folder.filename().string();
  row.model = summary.model;
  row.rpm = summary.rpm;
  row.status = summary.status;
  row.cycles = summary.cycles;
  row.wall_time_s = summary.wall_time_s;
  // A summary of an unknown model (none so far) keeps every figure it has.
  bool skirt_film = true, big_end_film = true;
  try {
    const engine::Model model = engine::ParseModel(summary.model);
    skirt_film = engine::SkirtLubricated(model);
    big_end_film = engine::BigEndLubricated(model);
  } catch (const std::exception&) {
  }
  for (const auto& recipe : Recipes()) {
    std::optional<double> value;
    if ((recipe.film == Film::kSkirt && !skirt_film) ||
        (recipe.film == Film::kBigEnd && !big_end_film)) {
      row.figures.push_back(value);
      continue;
    }
    bool spike = false;  // the extreme is a spike between the output samples
    if (recipe.reduce == Reduce::kMeanFplSkirt) {
      value = summary.mean_fpl_skirt_w;
    } else if (recipe.reduce == Reduce::kMeanFplBearing) {
      value = summary.mean_fpl_bearing_w;
    } else if (recipe.reduce == Reduce::kFmepSkirt) {
      if (summary.kpis.skirt) value = summary.kpis.skirt->fmep;
    } else if (recipe.reduce == Reduce::kFmepBearing) {
      if (summary.kpis.big_end) value = summary.kpis.big_end->fmep;
    } else if (recipe.reduce == Reduce::kSlapEnergyMax || recipe.reduce == Reduce::kSlapEnergySum) {
      if (summary.kpis.skirt && summary.kpis.skirt->slap) {
        const PistonSlap& slap = *summary.kpis.skirt->slap;
        value = recipe.reduce == Reduce::kSlapEnergySum ? slap.energy_sum
                                                        : slap.energy_max.value_or(0.0);
      }
    } else if (recipe.reduce == Reduce::kOilSkirt || recipe.reduce == Reduce::kOilBearing) {
      const std::optional<JointKpis>& joint =
          recipe.reduce == Reduce::kOilSkirt ? summary.kpis.skirt : summary.kpis.big_end;
      value = ReportedOilPerCycle(joint);
    } else if (recipe.reduce == Reduce::kWettedSkirt) {
      // As the oil: a Reynolds skirt's "wetted" share is its uncavitated share, another quantity.
      if (summary.kpis.skirt && summary.kpis.skirt->oil_balance)
        value = summary.kpis.skirt->mean_wetted_fraction;
    } else if (recipe.reduce == Reduce::kWorstError) {
      if (summary.error_estimate.Estimated()) value = summary.error_estimate.worst_relative;
    } else if (const auto e = summary.extremes.find(recipe.column); e != summary.extremes.end()) {
      const ColumnExtremes& x = e->second;
      switch (recipe.reduce) {
        case Reduce::kMaxAbs: {
          const bool low = std::abs(x.min) > std::abs(x.max);
          value = low ? std::abs(x.min) : std::abs(x.max);
          spike = low ? x.min_spike : x.max_spike;
          break;
        }
        case Reduce::kMin:
          value = x.min, spike = x.min_spike;
          break;
        case Reduce::kMax:
          value = x.max, spike = x.max_spike;
          break;
        default:
          break;
      }
    }
    if (value && (spike || SpikeWarned(summary, recipe.spike_joint))) {
      value.reset();
      row.notes.push_back(WithoutUnit(recipe.figure.display_name) +
                          " left out: a spike the output samples do not resolve (its sampled "
                          "height depends on the output interval)");
    }
    row.figures.push_back(value);
  }
  return row;
}

std::string NotesText(const std::vector<std::string>& notes) {
  std::string text;
  for (const std::string& note : notes) text += (text.empty() ? "" : "; ") + note;
  return text;
}

void WriteComparisonCsv(std::ostream& out, const std::vector<ComparisonRow>& rows) {
  out << "run,model,rpm[rpm],status,cycles[-],wall_time[s]";
  for (const auto& figure : ComparisonFigures()) out << "," << figure.key;
  out << ",notes\n" << std::setprecision(10);
  for (const auto& row : rows) {
    out << row.folder << "," << row.model << "," << row.rpm << "," << row.status << ","
        << row.cycles << "," << row.wall_time_s;
    for (const auto& value : row.figures) {
      out << ",";
      if (value) out << *value;
    }
    out << "," << CsvCell(NotesText(row.notes)) << "\n";
  }
}

std::string ComparisonMarkdown(const std::vector<ComparisonRow>& rows) {
  std::ostringstream out;
  out << "| model | rpm | status | cycles | wall [s]";
  for (const auto& figure : ComparisonFigures()) out << " | " << figure.display_name;
  out << " |\n|---|---|---|---|---";
  for (std::size_t i = 0; i < ComparisonFigures().size(); ++i) out << "|---";
  out << "|\n";
  for (const auto& row : rows) {
    out << "| " << row.model << " | " << row.rpm << " | " << row.status << " | " << row.cycles
        << " | " << Cell(row.wall_time_s, 1.0, 3);
    for (std::size_t i = 0; i < row.figures.size(); ++i) {
      out << " | " << Cell(row.figures[i], ComparisonFigures()[i].display_scale, 4);
    }
    out << " |\n";
  }
  bool header = false;
  for (const auto& row : rows) {
    if (row.notes.empty()) continue;
    if (!header) out << "\nNotes:\n\n";
    header = true;
    for (const std::string& note : row.notes) out << "- " << row.folder << ": " << note << "\n";
  }
  return out.str();
}

}  // namespace filmdyn::io
