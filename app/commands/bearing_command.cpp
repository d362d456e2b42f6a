// `filmdyn bearing`: steady journal-bearing calculator. Mode 1:
// --eps given (dimensionless results need only --ld). Mode 2: --load and --rpm given, the
// equilibrium eccentricity is found (mixed lubrication when a roughness is given). The numbers
// come from core/lubrication/bearing_calculator.hpp; this file only maps options and prints.
#include <fmt/format.h>

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "app/commands/commands.hpp"
#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/run_memory.hpp"
#include "core/lubrication/bearing_calculator.hpp"
#include "core/lubrication/oil_catalogue.hpp"

namespace filmdyn::cli {

namespace {

lubrication::BearingMeshSpec ParseMesh(const std::string& text) {
  const auto x = text.find_first_of("xX");
  const std::string allowed =
      "must be NthetaxNz with integers, e.g. 240x40 (8 <= Ntheta <= 20000, 2 <= Nz <= 5000)";
  if (x == std::string::npos) throw InputError("--mesh", text, allowed);
  double nt = 0.0, nz = 0.0;
  try {  // either count not a number ("240x", "240x40x3"): the whole value and the form
    nt = ParseDouble("--mesh", text.substr(0, x));
    nz = ParseDouble("--mesh", text.substr(x + 1));
  } catch (const InputError&) {
    throw InputError("--mesh", text, allowed);
  }
  if (nt != std::floor(nt) || nz != std::floor(nz) || nt < 8 || nz < 2 || nt > 20000 || nz > 5000) {
    throw InputError("--mesh", text, allowed);
  }
  // The pressure unknowns (a node per element around, per node line across) within an engine
  // run's limit: a larger film would take the machine's memory before it said anything.
  if (const long unknowns = long(nt) * long(nz + 1); unknowns > engine::kMaxFilmUnknowns) {
    throw InputError("--mesh", fmt::format("{}: {} unknowns", text, unknowns),
                     fmt::format("at most {} pressure unknowns (the limit of an engine run's film)",
                                 engine::kMaxFilmUnknowns));
  }
  return {static_cast<int>(nt), static_cast<int>(nz), false};
}

}  // namespace

Command MakeBearingCommand() {
  Command command;
  command.name = "bearing";
  command.summary =
      "steady journal-bearing calculator: Sommerfeld number, attitude, friction, side flow";
  command.options = {
      {"ld", "L/D", "length-to-diameter ratio (default 0.5; not with --length)"},
      {"eps", "E", "mode 1: eccentricity ratio in [0, 1)"},
      {"load", "N", "mode 2: radial load [N] (with --rpm): finds the equilibrium eccentricity"},
      {"rpm", "R", "journal speed [rev/min] (default 3000; bearing at rest)"},
      {"radius", "M", "journal radius [m] (default 0.025)"},
      {"length", "M", "bearing width [m] (default 2 * radius * L/D)"},
      {"clearance", "M", "radial clearance [m] (default 25e-6)"},
      {"viscosity", "PAS", "dynamic viscosity [Pa s] (default 0.01)"},
      {"vogel", "A,B,C",
       "viscosity from Vogel's law mu = A exp(B / (T - C)): A [Pa s], B and C [K], T in kelvin "
       "(with --temperature; instead of --viscosity)"},
      {"grade", "NAME",
       "a catalogue oil of an SAE grade (0w-20, 5w-30, 10w-40, 15w-40; with --temperature; "
       "instead of --viscosity): Vogel's law fitted to its published 40/100 °C viscosities"},
      {"temperature", "C", "oil temperature [°C] for --vogel or --grade"},
      {"barus", "ALPHA", "pressure-viscosity coefficient of Barus' law mu0 exp(alpha p) [1/Pa]"},
      {"roelands", "Z", "pressure-viscosity index z of Roelands' law (typically 0.4-0.8)"},
      {"cross", "R,M[,RATE]",
       "shear thinning by Cross' law mu1 [R + (1 - R) / (1 + (rate / RATE)^M)] at the Couette "
       "rate |U| / h: R = mu2/mu1 in (0,1), exponent M, critical rate RATE [1/s] at 150 °C "
       "(shifted to --temperature by mu1(150 °C)/mu1(T) with --vogel or --grade); RATE, or "
       "--hths, or with --grade R,M alone (the grade's HTHS)"},
      {"hths", "PAS",
       "HTHS viscosity [Pa s] (150 °C, 1e6 1/s): sets RATE of --cross (which then takes R,M)"},
      {"cavitation", "MODEL", "reynolds (Swift-Stieber, default) or jfo (mass-conserving)"},
      {"mesh", "NTxNZ", "elements around x across the full width (default 240x40)"},
      {"sigma1", "M", "rms roughness of the journal [m] (enables mixed lubrication)"},
      {"sigma2", "M", "rms roughness of the bearing [m]"},
      {"peklenik", "G", "Peklenik number of the composite surface (default 1)"},
      {"E1", "PA", "Young's modulus of the journal [Pa] (default 210e9)"},
      {"E2", "PA", "Young's modulus of the bearing [Pa] (default 110e9)"},
      {"nu1", "NU", "Poisson ratio of the journal (default 0.3)"},
      {"nu2", "NU", "Poisson ratio of the bearing (default 0.33)"},
      {"boundary-friction", "MU", "asperity friction coefficient (default 0.13)"},
      {"elastic-layer", "T,E,NU",
       "elastic bearing lining of thickness T [m], Young's modulus E [Pa] and Poisson ratio NU "
       "on a rigid backing: the film and the lining's deformation solved together"},
      {"compliance", "FILE.mtx",
       "the bearing's compliance exported by a finite-element code: a Matrix Market matrix [m/N] "
       "of the surface nodes listed in FILE.nodes.csv (x[m] = R psi around the bearing from its "
       "reference axis, y[m] across the width; docs/compliance-files.md)"},
      {"half-space", "",
       "elastic journal and bearing as half-spaces (moduli --E1/--E2, ratios --nu1/--nu2): the "
       "film and the surfaces' deformation solved together"},
      {"json", "", "print one JSON object (SI; \"units\" names each dimensional figure's unit)"}};
  command.details =
      "Outputs follow Raimondi & Boyd (1958): S = (mu N / P)(R/c)^2 with N in rev/s and "
      "P = W/(2 R L); friction variable (R/c) f; side_flow_variable = Q_s/(R c N L), Q_s the "
      "leakage through both edges [m^3/s]. The film starts at the maximum film thickness "
      "(p = 0 there), as in the published tables.";
  command.run = [](const Args& args, Streams& streams) {
    lubrication::BearingCalcInput in;
    if (auto v = args.Double("radius")) in.radius = *v;
    RequirePositive("--radius", in.radius, "m");
    if (args.Has("ld") && args.Has("length"))
      throw InputError("--ld", *args.Value("ld"), "either --ld or --length, not both");
    if (auto v = args.Double("length")) {
      in.length = *v;
    } else {
      const double ld = args.Double("ld").value_or(0.5);
      RequirePositive("--ld", ld);
      in.length = 2.0 * in.radius * ld;
    }
    if (auto v = args.Double("clearance")) in.radial_clearance = *v;
    if (auto v = args.Double("viscosity")) in.viscosity = *v;
    // The oil, resolved by its own rules (OilSpec::At), so that the calculator and an engine run
    // fit, calibrate and shift it alike: a constant, Vogel's law or a catalogue grade, and Cross'
    // shear thinning.
    lubrication::OilSpec oil;
    oil.viscosity = in.viscosity;
    std::optional<double> temperature;
    const lubrication::OilGrade* grade = nullptr;
    if (args.Has("vogel") && args.Has("grade"))
      throw InputError("--grade", *args.Value("grade"), "either --grade or --vogel, not both");
    for (const char* law : {"vogel", "grade"}) {
      if (args.Has(law) && args.Has("viscosity")) {
        throw InputError(std::string("--") + law, *args.Value(law),
                         std::string("either --") + law + " or --viscosity, not both");
      }
    }
    if (args.Has("vogel")) {
      const std::vector<double> abc = ParseDoubleList("--vogel", *args.Value("vogel"));
      if (abc.size() != 3) throw InputError("--vogel", *args.Value("vogel"), "three numbers A,B,C");
      const lubrication::VogelLaw law{abc[0], abc[1], abc[2]};
      law.Validate("--vogel.");
      oil.model = lubrication::ViscosityModel::kVogel;
      oil.vogel_a = law.a;
      oil.vogel_b = law.b;
      oil.vogel_c = law.c;
    }
    if (args.Has("grade")) {
      grade = &lubrication::FindOilGrade(*args.Value("grade"), "--grade");
      oil.model = lubrication::ViscosityModel::kGrade;
      oil.grade = static_cast<int>(grade - lubrication::OilCatalogue().data());
    }
    if (oil.model != lubrication::ViscosityModel::kConstant) {
      if (!args.Has("temperature")) {
        throw InputError("--temperature", "(missing)",
                         "the oil temperature [°C] for --vogel or --grade");
      }
      temperature = *args.Double("temperature");
    } else if (args.Has("temperature")) {
      throw InputError("--temperature", *args.Value("temperature"),
                       "only with a temperature law (--vogel or --grade)");
    }
    if (args.Has("hths") && !args.Has("cross"))
      throw InputError("--hths", *args.Value("hths"), "with --cross R,M");
    if (args.Has("cross")) {
      const std::vector<double> rmr = ParseDoubleList("--cross", *args.Value("cross"));
      const bool from_hths = args.Has("hths") || (grade != nullptr && rmr.size() == 2);
      const size_t want = from_hths ? 2 : 3;
      if (rmr.size() != want) {
        throw InputError("--cross", *args.Value("cross"),
                         want == 2 ? "two numbers R,M with --hths"
                                   : "three numbers R,M,RATE (or R,M with --hths or --grade)");
      }
      if (!(rmr[0] > 0.0 && rmr[0] < 1.0))
        throw InputError("--cross", *args.Value("cross"), "R between 0 and 1");
      if (!(rmr[1] > 0.0)) throw InputError("--cross", *args.Value("cross"), "M > 0");
      if (want == 3 && !(rmr[2] > 0.0))
        throw InputError("--cross", *args.Value("cross"), "RATE > 0 [1/s]");
      oil.shear_thinning =
          from_hths ? lubrication::ShearThinning::kHths : lubrication::ShearThinning::kCross;
      oil.cross_ratio = rmr[0];
      oil.cross_exponent = rmr[1];
      if (want == 3) oil.cross_rate = rmr[2];
      if (auto v = args.Double("hths")) oil.hths = *v;
    }
    const lubrication::OilSpec::AtTemperature oil_at =
        oil.At(temperature ? *temperature + lubrication::kZeroCelsius : 0.0, "--", "--temperature");
    in.viscosity = oil_at.viscosity;
    in.shear_thinning = oil_at.shear;
    if (oil_at.extrapolated) {
      streams.err << "filmdyn bearing: warning: " << *temperature
                  << " °C is outside the 40–150 °C the catalogue oil " << grade->key
                  << " was fitted over: its viscosity is extrapolated\n";
    }
    if (args.Has("barus") && args.Has("roelands"))
      throw InputError("--barus", *args.Value("barus"), "either --barus or --roelands, not both");
    if (auto v = args.Double("barus")) {
      in.pressure_law = lubrication::PressureLaw::kBarus;
      in.barus_alpha = *v;
    }
    if (auto v = args.Double("roelands")) {
      in.pressure_law = lubrication::PressureLaw::kRoelands;
      in.roelands_z = *v;
    }
    if (auto v = args.Double("rpm")) in.speed_rpm = *v;
    in.eps = args.Double("eps");
    in.load = args.Double("load");
    const std::string cav = args.Value("cavitation").value_or("reynolds");
    if (cav == "reynolds")
      in.cavitation = lubrication::CavitationModel::kReynolds;
    else if (cav == "jfo")
      in.cavitation = lubrication::CavitationModel::kJfo;
    else
      throw InputError("--cavitation", cav, "must be reynolds or jfo");
    in.mesh = ParseMesh(args.Value("mesh").value_or("240x40"));
    // Options that describe the asperity contact or the surfaces' deformation mean nothing without
    // it: refused rather than ignored (a forgotten --sigma1 would silently compute smooth
    // surfaces).
    const bool rough = args.Has("sigma1") || args.Has("sigma2");
    for (const char* option : {"peklenik", "boundary-friction"}) {
      if (args.Has(option) && !rough) {
        throw InputError(
            std::string("--") + option, *args.Value(option),
            "only with a roughness (--sigma1, --sigma2): it sets the asperity contact");
      }
    }
    for (const char* option : {"E1", "E2", "nu1", "nu2"}) {
      if (args.Has(option) && !rough && !args.Has("half-space")) {
        throw InputError(std::string("--") + option, *args.Value(option),
                         "only with a roughness (--sigma1, --sigma2: the asperity contact) or "
                         "--half-space (the deformation)");
      }
    }
    if (args.Has("sigma1") || args.Has("sigma2")) {
      lubrication::SurfacePair pair;
      pair.sigma1 = args.Double("sigma1").value_or(0.0);
      pair.sigma2 = args.Double("sigma2").value_or(0.0);
      pair.peklenik = args.Double("peklenik").value_or(1.0);
      pair.E1 = args.Double("E1").value_or(210e9);
      pair.E2 = args.Double("E2").value_or(110e9);
      pair.nu1 = args.Double("nu1").value_or(0.3);
      pair.nu2 = args.Double("nu2").value_or(0.33);
      pair.boundary_friction = args.Double("boundary-friction").value_or(0.13);
      in.surfaces = pair;
    }
    {
      std::vector<std::string> surfaces;
      for (const char* option : {"elastic-layer", "half-space", "compliance"})
        if (args.Has(option)) surfaces.push_back(std::string("--") + option);
      if (surfaces.size() > 1) {
        throw InputError(surfaces[1], "given with " + surfaces[0],
                         "one of --elastic-layer, --half-space or --compliance at a time");
      }
    }
    if (args.Has("compliance")) {
      in.compliance.model = lubrication::ComplianceModel::kImported;
      in.compliance.imported = std::make_shared<const lubrication::ImportedCompliance>(
          lubrication::ReadImportedCompliance(*args.Value("compliance")));
    }
    if (args.Has("elastic-layer")) {
      const std::string text = *args.Value("elastic-layer");
      const std::vector<double> ten = ParseDoubleList("--elastic-layer", text);
      if (ten.size() != 3) throw InputError("--elastic-layer", text, "three numbers T,E,NU");
      in.compliance.model = lubrication::ComplianceModel::kElasticLayer;
      in.compliance.layer_thickness = ten[0];
      in.compliance.layer_modulus = ten[1];
      in.compliance.layer_poisson = ten[2];
    }
    if (args.Has("half-space")) {
      in.compliance.model = lubrication::ComplianceModel::kHalfSpace;
      in.compliance.modulus1 = args.Double("E1").value_or(210e9);
      in.compliance.modulus2 = args.Double("E2").value_or(110e9);
      in.compliance.poisson1 = args.Double("nu1").value_or(0.3);
      in.compliance.poisson2 = args.Double("nu2").value_or(0.33);
    }
    lubrication::ValidateCompliance(in.compliance, {.layer_thickness = "--elastic-layer T",
                                                    .layer_modulus = "--elastic-layer E",
                                                    .layer_poisson = "--elastic-layer NU",
                                                    .modulus1 = "--E1",
                                                    .poisson1 = "--nu1",
                                                    .modulus2 = "--E2",
                                                    .poisson2 = "--nu2",
                                                    .tolerance = "elastic tolerance",
                                                    .max_iterations = "elastic iterations",
                                                    .imported = "--compliance"});
    // Each number within the range the case allows for the quantity it is (one definition of
    // each range: the case schema), named by its option. A value far outside them (a viscosity
    // of 1e300 Pa s) gave NaN figures reported as converged.
    const auto within = [&args](const char* option, const char* field, double value) {
      if (args.Has(option)) engine::FindCaseField(field)->Check(value, std::string("--") + option);
    };
    within("radius", "big_end.journal_radius", in.radius);
    if (args.Has("length")) {
      within("length", "big_end.width", in.length);
    } else {
      engine::FindCaseField("big_end.width")->Check(in.length, "--ld (the width 2 R L/D)");
    }
    within("viscosity", "lubricant.viscosity", in.viscosity);
    if (temperature) {
      // The case's temperatures are in kelvin; the option in °C.
      const engine::FieldRange& t = engine::FindCaseField("big_end.oil.temperature")->range;
      RequireInRange("--temperature", *temperature, t.lo - lubrication::kZeroCelsius,
                     t.hi - lubrication::kZeroCelsius, t.lo_open, t.hi_open, "°C");
      engine::FindCaseField("lubricant.viscosity")
          ->Check(in.viscosity, "--temperature (the viscosity there)");
    }
    within("rpm", "operating.rpm", in.speed_rpm);
    within("barus", "lubricant.barus_alpha", in.barus_alpha);
    within("roelands", "lubricant.roelands_z", in.roelands_z);
    if (args.Has("cross")) {
      engine::FindCaseField("lubricant.cross_exponent")->Check(oil.cross_exponent, "--cross M");
      if (oil.shear_thinning == lubrication::ShearThinning::kCross)
        engine::FindCaseField("lubricant.cross_rate")->Check(oil.cross_rate, "--cross RATE");
    }
    within("hths", "lubricant.hths", oil.hths);
    if (in.surfaces) {
      within("sigma1", "big_end.roughness_journal", in.surfaces->sigma1);
      within("sigma2", "big_end.roughness_bearing", in.surfaces->sigma2);
      within("peklenik", "big_end.peklenik", in.surfaces->peklenik);
      within("boundary-friction", "big_end.boundary_friction", in.surfaces->boundary_friction);
    }
    within("E1", "big_end.modulus_journal", args.Double("E1").value_or(0.0));
    within("E2", "big_end.modulus_bearing", args.Double("E2").value_or(0.0));
    within("nu1", "big_end.poisson_journal", args.Double("nu1").value_or(0.0));
    within("nu2", "big_end.poisson_bearing", args.Double("nu2").value_or(0.0));
    // The calculator names its inputs by their own fields; here the options that set them (the
    // checks of the film's own configuration run when it is built, in RunBearingCalculator).
    lubrication::BearingCalcResult r;
    try {
      in.Validate();
      r = lubrication::RunBearingCalculator(in);
    } catch (const InputError& e) {
      static const std::pair<const char*, const char*> kOptions[] = {
          {"bearing.radius", "--radius"},
          {"bearing.length", "--length"},
          {"bearing.radial_clearance", "--clearance"},
          {"bearing.viscosity", "--viscosity"},
          {"bearing.speed_rpm", "--rpm"},
          {"bearing.eps", "--eps"},
          {"bearing.load", "--load"},
          {"bearing.mode", "--eps / --load"},
          {"bearing.barus_alpha", "--barus"},
          {"bearing.roelands_z", "--roelands"},
          {"bearing.surface.sigma1", "--sigma1"},
          {"bearing.surface.sigma2", "--sigma2"},
          {"bearing.surface.peklenik", "--peklenik"},
          {"bearing.surface.boundary_friction", "--boundary-friction"},
          {"bearing.surface.E1", "--E1"},
          {"bearing.surface.E2", "--E2"},
          {"bearing.surface.nu1", "--nu1"},
          {"bearing.surface.nu2", "--nu2"},
          {"bearing.mesh.n_theta", "--mesh"},
          {"bearing.mesh.n_z", "--mesh"},
          {"bearing.compliance", "--half-space"}};
      // The film's own names in the allowed text too ("coarsen bearing.mesh").
      std::string allowed = e.allowed();
      for (const auto& [name, option] :
           {std::pair<std::string, std::string>{"bearing.mesh", "--mesh"},
            {"\"elastic_layer\"", "--elastic-layer"}}) {
        for (auto at = allowed.find(name); at != std::string::npos; at = allowed.find(name, at))
          allowed.replace(at, name.size(), option);
      }
      for (const auto& [field, option] : kOptions)
        if (e.field() == field) throw InputError(option, e.value(), allowed);
      throw;
    }
    // A centred journal (--eps 0) carries no load: no direction to measure the attitude from,
    // and S and (R/c) f, both per unit load, are unbounded. Its friction (Petroff's) and flows
    // are what it reports.
    const bool unloaded = !(r.load > 0.0);
    static constexpr const char* kUnloaded = "no load: the journal is centred";
    // Smooth surfaces carry any load on a thin enough film (its load grows without bound as
    // eps -> 1): a film thinner than real bearing surfaces are rough is an answer of the model,
    // not of a bearing. 0.1 um: the composite roughness of finely finished journal and shell
    // (the default case's skirt 0.615 um and liner 0.815 um are rougher still).
    static constexpr double kSmoothFilmFloor = 0.1e-6;  // [m]
    std::vector<std::string> warnings;
    if (!in.surfaces && r.moft < kSmoothFilmFloor) {
      warnings.push_back(fmt::format(
          "the minimum film {:.3g} um is thinner than the roughness of real bearing surfaces "
          "(0.1 um and more): smooth surfaces carry any load on a thin enough film; give "
          "--sigma1/--sigma2 for the asperity contact (mixed lubrication)",
          r.moft * 1e6));
    }
    for (const std::string& w : warnings) streams.err << "filmdyn bearing: warning: " << w << "\n";
    if (args.Has("json")) {
      nlohmann::json j;
      j["mode"] = in.eps ? "eccentricity" : "load";
      j["eps"] = r.eps;
      if (unloaded) {
        j["attitude_deg"] = j["sommerfeld"] = j["friction_variable"] = nullptr;
        j["undefined"] = {"attitude_deg", "sommerfeld", "friction_variable"};
        j["undefined_reason"] = kUnloaded;
      } else {
        j["attitude_deg"] = r.attitude_deg;
        j["sommerfeld"] = r.sommerfeld;
        j["friction_variable"] = r.friction_variable;
      }
      j["side_flow"] = r.side_flow;
      j["side_flow_unit"] = "m^3/s, both edges";
      j["side_flow_variable"] = r.side_flow_variable;
      j["side_flow_variable_definition"] = "Q_s/(R c N L), N in rev/s";
      j["inlet_flow"] = r.inlet_flow;
      j["inlet_flow_variable"] = r.inlet_flow_variable;
      j["moft"] = r.moft;
      j["friction_torque"] = r.friction_torque;
      j["friction_power_loss"] = r.friction_power_loss;
      j["load"] = r.load;
      j["contact_load"] = r.contact_load;
      j["max_pressure"] = r.max_pressure;
      j["cavitated_fraction"] = r.cavitated_fraction;
      j["cavitation"] = lubrication::ToString(in.cavitation);
      j["viscosity_used"] = in.viscosity;
      j["viscosity_used_definition"] = "Pa*s, at zero gauge pressure and the temperature used";
      if (temperature) j["temperature"] = *temperature;
      if (grade != nullptr) {
        j["grade"] = std::string(grade->key);
        j["grade_product"] = std::string(grade->product);
        j["grade_extrapolated"] = oil_at.extrapolated;
      }
      j["pressure_viscosity"] = lubrication::ToString(in.pressure_law);
      if (in.pressure_law != lubrication::PressureLaw::kNone)
        j["pressure_viscosity_coefficient"] =
            lubrication::PressureViscosityOf(in).InitialCoefficient();
      const lubrication::CrossLaw& cross = in.shear_thinning;
      j["shear_thinning"] = cross.active() ? "cross" : "none";
      if (cross.active()) {
        j["cross_ratio"] = cross.ratio;
        j["cross_exponent"] = cross.exponent;
        j["cross_critical_rate"] = cross.critical_rate;
        j["cross_critical_rate_definition"] = "1/s, at the temperature used";
      }
      j["compliance"] = lubrication::ToString(in.compliance.model);
      j["max_deformation"] = r.max_deformation;
      j["max_deformation_unit"] = "m, largest opening of the film by the surfaces' deformation";
      if (!in.compliance.rigid()) {
        j["elastic_iterations"] = r.elastic.iterations;
        j["elastic_film_solves"] = r.elastic.film_solves;
        j["elastic_residual"] = r.elastic.residual;
        j["elastic_tolerance"] = r.elastic.tolerance;
      }
      // Every dimensional figure's unit (the others are ratios, counts or texts).
      nlohmann::json units = {{"attitude_deg", "deg"},
                              {"side_flow", "m^3/s"},
                              {"inlet_flow", "m^3/s"},
                              {"moft", "m"},
                              {"friction_torque", "N*m"},
                              {"friction_power_loss", "W"},
                              {"load", "N"},
                              {"contact_load", "N"},
                              {"max_pressure", "Pa"},
                              {"viscosity_used", "Pa*s"},
                              {"max_deformation", "m"}};
      if (temperature) units["temperature"] = "degC";
      if (j.contains("pressure_viscosity_coefficient"))
        units["pressure_viscosity_coefficient"] = "1/Pa";
      if (cross.active()) units["cross_critical_rate"] = "1/s";
      if (j.contains("elastic_residual"))
        units["elastic_residual"] = units["elastic_tolerance"] = "m";
      j["units"] = units;
      j["mesh"] = std::to_string(in.mesh.n_theta) + "x" + std::to_string(in.mesh.n_z);
      j["l_over_d"] = in.length / (2.0 * in.radius);
      j["reynolds_solves"] = r.reynolds_solves;
      j["lcp_iterations"] = r.last_stats.iterations;
      j["complementarity_residual"] = r.last_stats.complementarity_residual;
      j["converged"] = r.converged;
      j["status"] = r.status;
      j["warnings"] = warnings;
      streams.out << j.dump(2) << "\n";
    } else {
      auto& o = streams.out;
      o << std::setprecision(6);
      o << "L/D                      " << in.length / (2.0 * in.radius) << "\n";
      o << "viscosity used [Pa s]    " << in.viscosity << "\n";
      o << "eccentricity ratio       " << r.eps << "\n";
      if (unloaded) {
        o << "attitude angle [deg]     undefined (" << kUnloaded << ")\n";
        o << "Sommerfeld number S      infinite (" << kUnloaded << ")\n";
        o << "friction variable (R/c)f infinite (" << kUnloaded << ")\n";
      } else {
        o << "attitude angle [deg]     " << r.attitude_deg << "\n";
        o << "Sommerfeld number S      " << r.sommerfeld << "\n";
        o << "friction variable (R/c)f " << r.friction_variable << "\n";
      }
      o << "side flow Qs/(R c N L)   " << r.side_flow_variable << "\n";
      o << "side flow [m^3/s]        " << r.side_flow << "\n";
      o << "inlet flow Q/(R c N L)   " << r.inlet_flow_variable << "\n";
      o << "load [N]                 " << r.load << "\n";
      o << "MOFT [m]                 " << r.moft << "\n";
      o << "friction torque [N m]    " << r.friction_torque << "\n";
      o << "friction power [W]       " << r.friction_power_loss << "\n";
      o << "max pressure [Pa]        " << r.max_pressure << "\n";
      if (!in.compliance.rigid()) o << "max deformation [m]      " << r.max_deformation << "\n";
      o << "status                   " << r.status << "\n";
    }
    if (!r.converged) {
      streams.err << "filmdyn bearing: " << r.status << "\n";
      return 3;
    }
    return 0;
  };
  return command;
}

}  // namespace filmdyn::cli
