// `filmdyn reproduce`: the paper's section 4 study from our solver — the three coupled models at
// 6000 rpm and Skirt-LBRBE at 1000, 2000, 4000 and 6000 rpm — with its figures redrawn from our
// results (PNG + SVG) and an index (figures.md) naming, for every figure of the section, the file
// that shows it or why it is not drawn.
#include <fmt/format.h>

#include <QChart>
#include <QLineSeries>
#include <QValueAxis>
#include <fstream>
#include <numbers>

#include "app/commands/commands.hpp"
#include "app/commands/run_common.hpp"
#include "core/base/angles.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/case_file.hpp"
#include "ui/charts/chart_export.hpp"

namespace filmdyn::cli {

namespace {

constexpr double kModelsRpm = 6000.0;
constexpr double kSpeeds[] = {1000.0, 2000.0, 4000.0, 6000.0};

// Fig. 5: the cylinder pressure at the four speeds (our synthetic curves or the case's own).
std::string WritePressureFigure(const io::LoadedCase& loaded, const std::filesystem::path& dir) {
  QChart chart;
  chart.setTitle(QObject::tr("Cylinder pressure (paper Fig. 5)"));
  auto* x = new QValueAxis;
  auto* y = new QValueAxis;
  x->setTitleText(QObject::tr("crank angle [°CA]"));
  x->setRange(0, 720);
  x->setTickCount(9);
  y->setTitleText(QObject::tr("pressure [MPa]"));
  chart.addAxis(x, Qt::AlignBottom);
  chart.addAxis(y, Qt::AlignLeft);
  double peak = 0.0;
  for (double rpm : kSpeeds) {
    const engine::PressureCurve curve = io::PressureCurveForSpeed(loaded, rpm);
    auto* series = new QLineSeries;
    series->setName(QString::fromStdString(RpmText(rpm) + " rpm"));
    for (int k = 0; k <= 1440; ++k) {
      const double deg = 0.5 * k;
      const double p = curve.Pressure(deg * kRadiansPerDegree) * 1e-6;
      series->append(deg, p);
      peak = std::max(peak, p);
    }
    chart.addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
  }
  y->setRange(0, 1.05 * peak);
  y->applyNiceNumbers();
  QString error;
  for (const auto& [suffix, format] :
       {std::pair{".png", ui::ImageFormat::kPng}, std::pair{".svg", ui::ImageFormat::kSvg}}) {
    const std::filesystem::path path = dir / (std::string("cylinder_pressure") + suffix);
    if (!ui::ExportChart(&chart, QString::fromStdString(path.string()), format, QSize(960, 600),
                         &error)) {
      return error.toStdString();
    }
  }
  return {};
}

// Which of our files shows each figure of the paper's section 4.
std::string FiguresIndex(const std::string& models_dir, const std::string& speeds_dir,
                         const std::string& skirt_lbrbe_6000) {
  const std::string m = models_dir + "/plots/", s = speeds_dir + "/plots/";
  std::string t;
  t += "# The paper's section 4, redrawn from FilmDyn's results\n\n";
  t += "Runs: `runs/` (one folder each, as `filmdyn run` writes them). Models at 6000 rpm: `" +
       models_dir + "/` (Only-Skirt, Only-LBRBE, Skirt-LBRBE overlaid); speeds: `" + speeds_dir +
       "/` (Skirt-LBRBE at 1000, 2000, 4000, 6000 rpm overlaid). Every plot as PNG and SVG; the "
       "comparison tables are `comparison.md` in each folder.\n\n";
  t += "| paper figure | what | our file(s) |\n|---|---|---|\n";
  t += "| Fig. 5 | cylinder pressure at the four speeds | `figures/cylinder_pressure.png` |\n";
  t += "| Fig. 6 | piston and rod kinematics, models | `" + m + "piston_lateral.png`, `" + m +
       "piston_tilt.png`, `" + m + "piston_lateral_velocity.png`, `" + m +
       "piston_tilt_rate.png` (displacements and rates; accelerations are not an output) |\n";
  t += "| Fig. 7 | film forces on the skirt and at the LBRBE, models | `" + m +
       "liner_forces.png`, `" + m + "bigend_forces.png` |\n";
  t += "| Fig. 8 | MOFT and FPL of both joints, models | `" + m + "moft.png`, `" + m +
       "fpl.png` |\n";
  t += "| Fig. 9 | journal centre trajectory, models | `" + m +
       "journal_orbit.png` (the load diagram beside it: `" + m + "bigend_load_polar.png`) |\n";
  t += "| Fig. 10 | asperity contact pressure and friction stresses of the LBRBE at 62 and 562 "
       "°CA | contact pressure field: `runs/" +
       skirt_lbrbe_6000 +
       "/fields/` (`bearing.xdmf` with `bearing.h5`, one frame per output step: open the XDMF in ParaView and go to 62 and 562 °CA); the friction-stress "
       "fields are not an output |\n";
  t += "| Fig. 11 | piston secondary motion, speeds | `" + s + "piston_lateral.png`, `" + s +
       "piston_tilt.png`, `" + s + "piston_lateral_velocity.png`, `" + s +
       "piston_tilt_rate.png` |\n";
  t += "| Fig. 12 | skirt thrust force, MOFT, friction force, FPL, speeds | `" + s +
       "liner_forces.png`, `" + s + "moft.png`, `" + s + "fpl.png` |\n";
  t += "| Fig. 13 | inertia forces of piston and rod, speeds | not drawn: inertia forces are not "
       "an output (the big-end force `" +
       s + "bigend_forces.png` carries them) |\n";
  t += "| Fig. 14 | LBRBE phase portraits ε, ε̇, γ̇_b, speeds | `" + s +
       "phase_eps.png` (ε / ε̇; the paper's 3D portrait is drawn as its ε–ε̇ projection) |\n";
  t += "| Fig. 15 | LBRBE reaction forces, MOFT, FPL, speeds | `" + s + "bigend_forces.png`, `" +
       s + "moft.png`, `" + s + "fpl.png` |\n";
  return t;
}

}  // namespace

Command MakeReproduceCommand() {
  Command command;
  command.name = "reproduce";
  command.summary =
      "section 4 of Zhao & Shen's coupling-model paper (3 models at 6000 rpm, 4 speeds), figures";
  command.positional_usage = "[CASE.json]";
  command.max_positional = 1;
  command.needs_gui_application = true;  // figures are rendered with Qt Charts (offscreen)
  command.options = {
      {"out", "DIR", "output folder (default: ./results/reproduce-<case>)"},
      {"jobs", "N", "runs computed at the same time (default: number of cores)"},
      CaseSetOption(),
      {"time-limit", "S", "wall-time limit of each run [s], keeping what was computed"},
      {"no-fields", "", "do not write the runs' fields/ (Fig. 10 then has no data)"},
      {"paper-meshes", "", "the paper's film meshes (Table II) instead of the case's"},
      {"overwrite", "", "--out may hold an earlier reproduction: FilmDyn's files are replaced"},
      {"quiet", "", "no progress on stderr"}};
  command.details =
      "The paper: Zhao & Shen, \"A numerical coupling model for a multibody system with multiple\n"
      "lubricated clearance joints\" (docs/equations.md).\n"
      "Six runs: only-skirt, only-lbrbe and skirt-lbrbe at 6000 rpm; skirt-lbrbe at 1000, 2000\n"
      "and 4000 rpm. Writes <DIR>/runs/<case>-<model>-<rpm>/ (as `filmdyn run`),\n"
      "<DIR>/models-6000rpm/ and <DIR>/speeds-skirt-lbrbe/ (overlay plots, comparison tables),\n"
      "<DIR>/figures/cylinder_pressure.{png,svg} and <DIR>/figures.md, the index from each of\n"
      "the paper's figures 5-15 to the files written here. Without CASE.json the built-in default\n"
      "case (the paper's Table I) is used. The film meshes are the case's (--set overrides\n"
      "them) or, with --paper-meshes, the paper's (skirt 30 + 2 + 30 x 40, big end 50 x 10\n"
      "uniform; about 20 % low on the minimum big-end film at 6000 rpm); figures.md states them.\n"
      "Example:\n  filmdyn reproduce --out /tmp/paper";
  command.run = [](const Args& args, Streams& streams) {
    // The plan sets the speeds and the models of its runs: a --set of them would be replaced.
    RefuseSets(args, {"operating.rpm", "skirt.model", "big_end.model"},
               "is set by the paper's plan of runs (its speeds and models)");
    std::vector<std::string> sets;
    if (args.Has("paper-meshes")) {
      engine::EngineCase paper;
      engine::UsePaperMeshes(&paper);
      for (const char* path : {"skirt.mesh_thrust", "skirt.mesh_relief", "skirt.mesh_anti",
                               "skirt.mesh_axial", "big_end.mesh_theta", "big_end.mesh_z",
                               "big_end.mesh_theta_grading", "big_end.mesh_z_grading"}) {
        sets.push_back(fmt::format("{}={:g}", path, engine::FindCaseField(path)->get(paper)));
      }
    }
    for (const std::string& set : args.Values("set")) sets.push_back(set);  // the user's last
    const std::string case_path = args.positional().empty() ? "" : args.positional()[0];
    const io::LoadedCase loaded = io::LoadCase(case_path, sets);
    for (const std::string& note : loaded.notes) streams.err << "reproduce: note: " << note << "\n";
    const engine::EngineCase& c = loaded.value;
    const std::string meshes = engine::DescribeMeshes(c);
    if (!args.Has("quiet")) streams.err << "reproduce: meshes: " << meshes << "\n";
    const int jobs = JobsOption(args);
    const double time_limit = TimeLimitOption(args);
    const std::filesystem::path out =
        args.Value("out") ? std::filesystem::path(*args.Value("out"))
                          : std::filesystem::path("results") / ("reproduce-" + io::SafeFolderName(c.name));

    // Job order: the three models at 6000 rpm (indices 0-2, Skirt-LBRBE last), then Skirt-LBRBE
    // at the other speeds (3-5).
    const std::vector<std::pair<engine::Model, double>> plan = {
        {engine::Model::kOnlySkirt, kModelsRpm},  {engine::Model::kOnlyLbrbe, kModelsRpm},
        {engine::Model::kSkirtLbrbe, kModelsRpm}, {engine::Model::kSkirtLbrbe, kSpeeds[0]},
        {engine::Model::kSkirtLbrbe, kSpeeds[1]}, {engine::Model::kSkirtLbrbe, kSpeeds[2]}};
    std::vector<batch::SweepJob> run_jobs;  // every configuration checked before any run
    for (const auto& [model, rpm] : plan) {
      run_jobs.push_back(
          SweepJobFor(loaded, model, rpm, time_limit, !args.Has("no-fields"), out / "runs"));
    }
    const auto folder = PrepareBatchFolders(out, run_jobs, args.Value("out").has_value(),
                                            args.Has("overwrite"), "the plan");
    std::filesystem::create_directories(out / "figures");
    if (const std::string error = WritePressureFigure(loaded, out / "figures"); !error.empty()) {
      streams.err << "reproduce: Fig. 5 not written: " << error << "\n";
    }

    const BatchOutcome batch =
        RunBatch(std::move(run_jobs), jobs, args.Has("quiet"), "reproduce", streams);
    const std::string models_dir = "models-6000rpm", speeds_dir = "speeds-skirt-lbrbe";
    const std::string models_table =
        WriteComparison(out / models_dir, batch, "Paper §4: the three models at 6000 rpm",
                        "reproduce", streams, {0, 1, 2});
    const std::string speeds_table =
        WriteComparison(out / speeds_dir, batch, "Paper §4: Skirt-LBRBE at four speeds",
                        "reproduce", streams, {3, 4, 5, 2});
    const std::string skirt_lbrbe_6000 = batch.jobs[2].output_folder.filename().string();
    io::WriteFileAtomically(
        out / "figures.md",
        FiguresIndex(models_dir, speeds_dir, skirt_lbrbe_6000) +
            "\nFilm meshes of every run: " + meshes +
            (args.Has("paper-meshes") ? " (the paper's Table II)" : " (the case's)") + "." +
            (args.Values("set").empty() ? std::string()
                                        : " Changed in the case for every run: " +
                                              io::OverridesText(args.Values("set")) + ".") +
            (c.solver.error_estimate != 0
                 ? " Each run's `summary.json` holds the estimated discretisation error of its "
                   "headline figures (`discretisation_error`).\n"
                 : " The discretisation error was not estimated (solver.error_estimate = 0).\n"));
    streams.out << "## The three models at 6000 rpm\n\n"
                << models_table << "\n## Skirt-LBRBE at four speeds\n\n"
                << speeds_table;
    streams.err << "reproduce: " << batch.runs.size() << " runs, " << batch.incomplete
                << " incomplete; figures indexed in " << (out / "figures.md").string() << "\n";
    return batch.incomplete == 0 ? 0 : 1;
  };
  return command;
}

}  // namespace filmdyn::cli
