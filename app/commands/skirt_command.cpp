// `filmdyn skirt`: the steady piston-skirt calculator (docs/skirt-calculator.md). Mode 1: a
// given state (--e0, --tilt, rates). Mode 2: a given load (--side-force, --moment), the
// equilibrium found. --map: the load-capacity curve over e0. The numbers come from
// core/lubrication/skirt_calculator.hpp and the reported quantities from core/io/skirt_report.hpp;
// this file maps options, prints and writes.
#include <fmt/format.h>

#include <QDir>
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

#include "app/commands/commands.hpp"
#include "app/commands/run_common.hpp"
#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/film_joints.hpp"
#include "core/engine/run_memory.hpp"
#include "core/io/output_files.hpp"
#include "core/io/skirt_report.hpp"
#include "core/lubrication/skirt_calculator.hpp"
#include "ui/plots/skirt_map_chart.hpp"

namespace filmdyn::cli {

namespace {

// "30+2+30x40": thrust + relief + anti-thrust elements around x elements along the skirt.
lubrication::SkirtMeshSpec ParseSkirtMesh(const std::string& text) {
  const std::string allowed =
      "must be T+R+AxN with whole numbers: thrust + relief + anti-thrust elements around, N "
      "along the skirt, e.g. 30+2+30x40 (each 1 to 10000, N >= 2)";
  const auto x = text.find_first_of("xX");
  const auto p1 = text.find('+');
  const auto p2 = p1 == std::string::npos ? p1 : text.find('+', p1 + 1);
  if (x == std::string::npos || p2 == std::string::npos || p2 > x) {
    throw InputError("--mesh", text, allowed);
  }
  const std::string parts[4] = {text.substr(0, p1), text.substr(p1 + 1, p2 - p1 - 1),
                                text.substr(p2 + 1, x - p2 - 1), text.substr(x + 1)};
  int n[4];
  for (int k = 0; k < 4; ++k) {
    double v = 0.0;
    try {
      v = ParseDouble("--mesh", parts[k]);
    } catch (const InputError&) {
      throw InputError("--mesh", text, allowed);
    }
    if (v != std::floor(v) || v < (k == 3 ? 2 : 1) || v > 10000) {
      throw InputError("--mesh", text, allowed);
    }
    n[k] = static_cast<int>(v);
  }
  return {n[0], n[1], n[2], n[3]};
}

std::pair<double, double> ParseRange(const std::string& option, const std::string& text) {
  const auto colon = text.find(':');
  const std::string allowed = "must be MIN:MAX in metres with MIN < MAX, e.g. -15e-6:18e-6";
  if (colon == std::string::npos) throw InputError(option, text, allowed);
  const double lo = ParseDouble(option, text.substr(0, colon));
  const double hi = ParseDouble(option, text.substr(colon + 1));
  if (!(lo < hi)) throw InputError(option, text, allowed);
  return {lo, hi};
}

const lubrication::SkirtInputNames kOptionNames{
    "--e0", "--tilt", "--speed", "--e0-rate", "--tilt-rate", "--side-force", "--moment"};
// A map's states come from its e0 range and tilts: errors name those options.
const lubrication::SkirtInputNames kMapOptionNames{
    "--e0-range", "--tilts", "--speed", "--e0-rate", "--tilt-rate", "--side-force", "--moment"};

}  // namespace

Command MakeSkirtCommand() {
  Command command;
  command.name = "skirt";
  command.summary =
      "steady piston-skirt calculator: film force, moment and MOFT at a state or under a load";
  command.positional_usage = "[CASE.json]";
  command.max_positional = 1;
  command.needs_gui_application = true;  // --map draws its plots with Qt Charts (offscreen)
  command.options = {
      {"e0", "M",
       "mode 1: lateral displacement of the piston axis at the pin [m], + toward thrust"},
      {"tilt", "RAD", "mode 1: tilt [rad], + moves the skirt below the pin toward thrust"},
      {"e0-rate", "M/S", "mode 1: lateral velocity de0/dt [m/s] (default 0)"},
      {"tilt-rate", "RAD/S", "mode 1: tilt rate [rad/s] (default 0)"},
      {"speed", "V",
       "piston speed along the skirt axis [m/s], + toward the crank (required; results.csv's "
       "piston_velocity is + toward the head: use its negative)"},
      {"side-force", "N",
       "mode 2: lateral force the engine applies to the piston [N], + toward thrust; the film "
       "must balance it"},
      {"moment", "NM",
       "mode 2: moment applied about the pin [N m], + turns the skirt bottom "
       "toward thrust (default 0)"},
      {"map", "DIR",
       "the load-capacity curve: film force, moment and MOFT against e0 at --speed into "
       "DIR/skirt_map.csv and DIR/plots/"},
      {"e0-range", "MIN:MAX",
       "--map: e0 range [m] (default: the film at least 10 % of the clearance)"},
      {"points", "N", "--map: e0 values per curve (default 41, 2 to 2001)"},
      {"tilts", "A,B,...", "--map: one curve per tilt [rad] (default 0)"},
      {"mesh", "T+R+AxN",
       "elements: thrust + relief + anti-thrust around x along the skirt "
       "(default: the case's)"},
      {"fields", "DIR", "write the film fields of the state to DIR/skirt.h5 + skirt.xdmf"},
      CaseSetOption(),
      {"json", "", "print one JSON object"}};
  command.details =
      "Uses the case's skirt geometry, profile, ovality, surfaces and lubricant (the built-in\n"
      "default case without CASE.json). Forces and moments act on the piston, signs as in\n"
      "results.csv (skirt_normal_force, skirt_moment). Mode 2 finds the steady-sliding e0 and "
      "tilt\n"
      "(de0/dt = dtilt/dt = 0) at which the film balances the load, mixed lubrication included,\n"
      "or says that the skirt cannot carry it and what it can. Exit 2 for bad input (a state that\n"
      "puts the skirt into the liner, a load beyond what it carries), 3 when mode 2 does not\n"
      "converge. docs/skirt-calculator.md has the conventions and an example.\n"
      "Examples:\n  filmdyn skirt --e0 10e-6 --tilt 2e-4 --speed 12\n"
      "  filmdyn skirt --side-force 1500 --moment 5 --speed -8 --json\n"
      "  filmdyn skirt --map /tmp/map --speed 10 --tilts -5e-4,0,5e-4";
  command.run = [](const Args& args, Streams& streams) {
    const io::LoadedCase loaded = LoadCaseArgument(args, &streams.err);
    lubrication::SkirtConfig config = engine::SkirtConfigFromCase(loaded.value, loaded.directory);
    if (const auto mesh = args.Value("mesh")) {
      config.mesh = ParseSkirtMesh(*mesh);
      // As the case's own mesh would be checked: each count in its field's range, the film's
      // unknowns within an engine run's limit (a larger film took the machine's memory first).
      engine::EngineCase meshed = loaded.value;
      meshed.skirt.mesh_thrust = config.mesh.n_thrust;
      meshed.skirt.mesh_relief = config.mesh.n_relief;
      meshed.skirt.mesh_anti = config.mesh.n_anti;
      meshed.skirt.mesh_axial = config.mesh.n_axial;
      try {
        for (const auto& [field, count] : {std::pair{"skirt.mesh_thrust", meshed.skirt.mesh_thrust},
                                           {"skirt.mesh_relief", meshed.skirt.mesh_relief},
                                           {"skirt.mesh_anti", meshed.skirt.mesh_anti},
                                           {"skirt.mesh_axial", meshed.skirt.mesh_axial}})
          engine::FindCaseField(field)->Check(count, field);
        engine::CheckFilmMeshSizes(meshed);
      } catch (const InputError& e) {
        throw InputError("--mesh", *mesh + " (" + e.field() + " " + e.value() + ")", e.allowed());
      }
    }
    const auto speed = args.Double("speed");
    if (!speed) throw InputError("--speed", "(missing)", "give the piston speed [m/s]");
    const bool load_mode = args.Has("side-force") || args.Has("moment");
    const bool map_mode = args.Has("map");
    std::string state_option;  // the first state option given, as typed
    for (const char* name : {"e0", "tilt", "e0-rate", "tilt-rate"})
      if (state_option.empty() && args.Has(name)) state_option = std::string("--") + name;
    const bool state_given = !state_option.empty();
    if (load_mode && (state_given || map_mode)) {
      throw InputError(state_given ? state_option : "--map",
                       std::string("(given with ") +
                           (args.Has("side-force") ? "--side-force" : "--moment") + ")",
                       "a load (mode 2) finds e0 and tilt itself: give either a state, a load or "
                       "--map");
    }
    if (map_mode && (args.Has("e0") || args.Has("e0-rate") || args.Has("tilt-rate"))) {
      throw InputError(args.Has("e0")        ? "--e0"
                       : args.Has("e0-rate") ? "--e0-rate"
                                             : "--tilt-rate",
                       "(given with --map)",
                       "the map sweeps e0 at steady sliding; set its tilts with --tilts");
    }
    // The folders first: one that cannot be made is said before the film is solved.
    if (map_mode) io::CreateFolder(*args.Value("map"), "--map");
    if (const auto dir = args.Value("fields")) io::CreateFolder(*dir, "--fields");
    lubrication::SkirtCalculator calc(config, map_mode ? kMapOptionNames : kOptionNames);
    const bool json = args.Has("json");

    if (map_mode) {
      const std::vector<double> tilts = args.Value("tilts")
                                            ? ParseDoubleList("--tilts", *args.Value("tilts"))
                                            : std::vector<double>{0.0};
      const long n = args.Integer("points").value_or(41);
      if (n < 2 || n > 2001) {
        throw InputError("--points", std::to_string(n), "must be a whole number in [2, 2001]");
      }
      std::vector<lubrication::SkirtPoint> points;
      for (double tilt : tilts) {
        std::pair<double, double> range;
        if (const auto text = args.Value("e0-range")) {
          range = ParseRange("--e0-range", *text);
        } else {
          range = calc.E0Range(tilt, 0.1 * config.geometry.radial_clearance);
          if (!(range.first < range.second)) {
            throw InputError("--tilts", FormatValue(tilt),
                             "leaves no e0 with a film of 10 % of the clearance everywhere");
          }
        }
        std::vector<double> e0s;
        for (long i = 0; i < n; ++i) {
          e0s.push_back(range.first + (range.second - range.first) * double(i) / double(n - 1));
        }
        for (auto& p : calc.Map(e0s, tilt, *speed)) points.push_back(std::move(p));
      }
      const std::filesystem::path dir = *args.Value("map");
      io::WriteFileAtomically(dir / "skirt_map.csv", io::SkirtMapCsv(points));
      QString error;
      const QStringList plots =
          ui::ExportSkirtMapPlots(points, QString::fromStdString((dir / "plots").string()), &error);
      if (!error.isEmpty()) {
        streams.err << "filmdyn skirt: plots not written: " << error.toStdString() << "\n";
      }
      streams.err << fmt::format("filmdyn skirt: map of {} points ({} tilt{}) in {}\n",
                                 points.size(), tilts.size(), tilts.size() == 1 ? "" : "s",
                                 dir.string());
      return error.isEmpty() ? 0 : 1;
    }

    lubrication::SkirtPoint point;
    nlohmann::json j;
    if (load_mode) {
      const lubrication::SkirtLoad load{args.Double("side-force").value_or(0.0),
                                        args.Double("moment").value_or(0.0), *speed};
      const lubrication::SkirtEquilibrium eq = calc.AtLoad(load);
      point = eq.point;
      j = io::SkirtPointJson(point);
      j["mode"] = "load";
      j["applied_side_force"] = load.side_force;
      j["applied_moment"] = load.moment;
      j["force_residual"] = eq.force_residual;
      j["moment_residual"] = eq.moment_residual;
      j["newton_iterations"] = eq.iterations;
      j["reynolds_solves"] = eq.reynolds_solves;
      j["converged"] = eq.converged;
      j["status"] = eq.status;
      if (!json) {
        streams.out << fmt::format(
            "equilibrium under a side force of {:g} N and a moment of {:g} N·m at {:g} m/s: {}\n"
            "({} iterations, {} skirt solves; residual {:.3g} N, {:.3g} N·m)\n",
            load.side_force, load.moment, load.piston_velocity, eq.status, eq.iterations,
            eq.reynolds_solves, eq.force_residual, eq.moment_residual);
      }
      if (!eq.converged) {
        if (json) streams.out << j.dump(2) << "\n";
        streams.err << "filmdyn skirt: " << eq.status << "\n";
        return 3;
      }
    } else {
      lubrication::SkirtState s;
      s.e0 = args.Double("e0").value_or(0.0);
      s.gamma = args.Double("tilt").value_or(0.0);
      s.e0_dot = args.Double("e0-rate").value_or(0.0);
      s.gamma_dot = args.Double("tilt-rate").value_or(0.0);
      s.piston_velocity = *speed;
      point = calc.AtState(s);
      j = io::SkirtPointJson(point);
      j["mode"] = "state";
      j["converged"] = point.film.stats.status == lubrication::SolveStatus::kConverged;
      j["status"] = j["converged"].get<bool>() ? "converged" : "the film solve did not converge";
    }
    j["case"] = loaded.value.name;
    j["mesh"] = fmt::format("{}+{}+{}x{}", config.mesh.n_thrust, config.mesh.n_relief,
                            config.mesh.n_anti, config.mesh.n_axial);
    j["complementarity_residual"] = point.film.stats.complementarity_residual;
    if (const auto dir = args.Value("fields")) {
      io::WriteSkirtFields(*dir, calc.solver());
      j["fields"] = (std::filesystem::path(*dir) / "skirt.xdmf").string();
    }
    if (json) {
      streams.out << j.dump(2) << "\n";
    } else {
      streams.out << fmt::format("case {}, skirt mesh {} elements\n", loaded.value.name,
                                 j["mesh"].get<std::string>());
      streams.out << io::SkirtPointTable(point);
      if (j.contains("fields")) {
        streams.out << "fields written to " << j["fields"].get<std::string>() << "\n";
      }
    }
    if (!j["converged"].get<bool>()) {
      streams.err << "filmdyn skirt: " << j["status"].get<std::string>() << "\n";
      return 3;
    }
    return 0;
  };
  return command;
}

}  // namespace filmdyn::cli
