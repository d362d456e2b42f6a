#include "app/commands/run_common.hpp"

#include <csignal>

#include "core/input_error.hpp"
#include "core/io/pressure_csv.hpp"
#include "ui/plots/plot_export.hpp"
#include "ui/run/sample_conversion.hpp"

namespace filmdyn::cli {

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void OnInterrupt(int) { g_interrupted = true; }
}  // namespace

engine::Model ModelFromCase(const engine::EngineCase& c) {
  const bool skirt = c.skirt.model == engine::JointModel::kLubricated;
  const bool big_end = c.big_end.model == engine::JointModel::kLubricated;
  return skirt && big_end ? engine::Model::kSkirtLbrbe
         : skirt          ? engine::Model::kOnlySkirt
         : big_end        ? engine::Model::kOnlyLbrbe
                          : engine::Model::kIdeal;
}

engine::RunConfig BuildRunConfig(const io::LoadedCase& loaded, engine::Model model, double rpm,
                                 const std::optional<std::string>& pressure_csv,
                                 double time_limit) {
  RequireInRange("--rpm", rpm, 0.0, 30000.0, true, false, "rpm");
  engine::PressureCurve pressure = pressure_csv ? io::ReadPressureCsvFile(*pressure_csv)
                                                : io::PressureCurveForSpeed(loaded, rpm);
  engine::RunConfig config = engine::MakeRunConfig(loaded.value, model, rpm, std::move(pressure));
  if (time_limit != 0.0) {
    RequirePositive("--time-limit", time_limit, "s");
    config.wall_time_limit = time_limit;
  }
  return config;
}

std::string WriteRunPlots(const std::filesystem::path& folder, const engine::RunConfig& config,
                          const std::vector<io::OutputRow>& rows) {
  QString error;
  ui::ExportStandardPlots(
      {ui::FinishedRun(1, {config.engine_case, engine::ModelName(config.model), config.rpm},
                       ui::RunSamplesFromRows(rows))},
      QString::fromStdString((folder / "plots").string()), &error);
  return error.toStdString();
}

InterruptGuard::InterruptGuard() {
  g_interrupted = false;
  previous_ = std::signal(SIGINT, OnInterrupt);
}

InterruptGuard::~InterruptGuard() { std::signal(SIGINT, previous_); }

const std::atomic<bool>* InterruptGuard::flag() const { return &g_interrupted; }

}  // namespace filmdyn::cli
