#include "core/engine/case_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <type_traits>

#include "core/base/angles.hpp"
#include "core/base/input_error.hpp"
#include "core/engine/film_joints.hpp"
#include "core/engine/pressure_curve.hpp"
#include "core/engine/run_memory.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/oil_catalogue.hpp"

namespace filmdyn::engine {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;
constexpr double kMm = 1e-3, kUm = 1e-6, kMPa = 1e6, kGPa = 1e9;

// A length of the mechanism: up to 100 m (the largest engines' strokes are ~3.5 m) — a value
// near the double range would only fail later, inside the solver's assembly.
FieldRange Length() { return {0.0, 100.0, true, false}; }
// Upper bounds far beyond any engine, so that a value near the double range is an input error
// naming the field instead of a failure inside the solver.
FieldRange Mass() { return {0.0, 1e5, true, false}; }       // [kg]; the largest marine pistons ~5 t
FieldRange Inertia() { return {0.0, 1e5, true, false}; }    // [kg·m²]
FieldRange Offset() { return {0.0, 100.0, false, false}; }  // a non-negative length [m]
FieldRange Roughness() { return {0.0, 1e-4, true, false}; }  // RMS [m]; engine surfaces < 2 µm
FieldRange Gap() { return {0.0, 0.01, false, false}; }       // profile/ovality gap [m]
// A radial clearance [m]: > 0, at most 10 mm (large marine pistons run about 1 mm); the
// cross-field rule adds < liner radius.
FieldRange Clearance() { return {0.0, 0.01, true, false}; }
FieldRange GaugePressure() { return {0.0, 1e9, false, false}; }  // [Pa], as the pressure curves
// The oil layer left on the liner [m]: at least 1 nm (a molecular layer of oil; below it the
// starved skirt would run on nothing the film model describes), at most 1 mm.
FieldRange LinerOilFilm() { return {1e-9, 1e-3, false, false}; }
FieldRange Viscosity() { return {0.0, 1e3, true, false}; }  // [Pa·s]; cold engine oil ~10 Pa·s
FieldRange Between(double lo, double hi) { return {lo, hi, false, false}; }
FieldRange Open(double lo, double hi, bool lo_open, bool hi_open) {
  return {lo, hi, lo_open, hi_open};
}
// Elastic constants of one surface: E' = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] needs E > 0, ν in (−1, 0.5).
FieldRange YoungsModulus() { return {0.0, 1e13, true, false}; }
FieldRange PoissonRatio() { return {-1.0, 0.5, true, true}; }

// What a row of the table says besides its accessor.
struct Info {
  FieldGroup group;
  const char* label;
  const char* unit;
  const char* display_unit;
  double display_scale;
  FieldRange range;
  const char* help;
};

CaseField Base(std::string path, FieldKind kind, const Info& i) {
  CaseField f;
  f.path = std::move(path);
  f.kind = kind;
  f.group = i.group;
  f.label = i.label;
  f.unit = i.unit;
  f.display_unit = i.display_unit;
  f.display_scale = i.display_scale;
  f.range = i.range;
  f.help = i.help;
  return f;
}

// A scalar member (double or int) of a section of the case.
template <typename Section, typename Value>
CaseField Scalar(std::string path, Section EngineCase::*section, Value Section::*member,
                 const Info& info) {
  CaseField f = Base(std::move(path),
                     std::is_integral_v<Value> ? FieldKind::kInteger : FieldKind::kNumber, info);
  f.get = [section, member](const EngineCase& c) { return double(c.*section.*member); };
  f.set = [section, member](EngineCase& c, double v) {
    if constexpr (std::is_integral_v<Value>) {
      c.*section.*member = std::isfinite(v) ? Value(std::lround(v)) : Value(-1);
    } else {
      c.*section.*member = v;
    }
  };
  return f;
}

template <typename Section>
CaseField List(std::string path, Section EngineCase::*section, std::vector<double> Section::*member,
               const Info& info) {
  CaseField f = Base(std::move(path), FieldKind::kNumberList, info);
  f.list = [section, member](EngineCase& c) -> std::vector<double>& { return c.*section.*member; };
  return f;
}

// A choice among `names`, the enumerators of Enum in order (0, 1, ...).
template <typename Section, typename Enum>
CaseField Choice(std::string path, Section EngineCase::*section, Enum Section::*member,
                 std::vector<std::string> names, const Info& info) {
  CaseField f = Base(std::move(path), FieldKind::kChoice, info);
  f.choices = std::move(names);
  f.choice = [section, member](const EngineCase& c) {
    return static_cast<int>(c.*section.*member);
  };
  f.set_choice = [section, member](EngineCase& c, int k) { c.*section.*member = Enum(k); };
  return f;
}

template <typename Section>
CaseField Model(std::string path, Section EngineCase::*section, JointModel Section::*member,
                const Info& info) {
  return Choice(std::move(path), section, member,
                {JointModelName(JointModel::kIdeal), JointModelName(JointModel::kLubricated)},
                info);
}

// A joint's cavitation model.
template <typename Section>
CaseField Cavitation(std::string path, Section EngineCase::*section,
                     lubrication::CavitationModel Section::*member, FieldGroup group) {
  using lubrication::CavitationModel;
  return Choice(std::move(path), section, member,
                {ToString(CavitationModel::kReynolds), ToString(CavitationModel::kJfo)},
                {group,
                 "Cavitation model",
                 "",
                 "",
                 1.0,
                 {},
                 "\"reynolds\" (Swift–Stieber, the paper's) or \"jfo\" (mass-conserving, "
                 "the film's oil content carried from step to step; a run takes some 4–6× as "
                 "long as with \"reynolds\" where the big end is fed by the engine's supply, up to "
                 "20× on a starved film-start line at low speed: docs/performance.md)"});
}

// The fields of one oil (lubrication::OilSpec) named prefix + "viscosity_model", ...: the case's
// (prefix "lubricant.") or a joint's own ("skirt.oil.", "big_end.oil."). `whose` ends each help.
using OilOf = lubrication::OilSpec& (*)(EngineCase&);
void AddOilFields(std::vector<CaseField>& f, const std::string& prefix, FieldGroup group, OilOf oil,
                  const std::string& whose, const std::string& symbol_prefix) {
  using lubrication::OilSpec;
  static const std::map<std::string_view, const char*> kSymbol = {
      {"viscosity_model", "oil model"},
      {"viscosity", "μ"},
      {"vogel_a", "Vogel a"},
      {"vogel_b", "Vogel b"},
      {"vogel_c", "Vogel c"},
      {"grade", "grade"},
      {"pressure_viscosity", "pressure law"},
      {"barus_alpha", "α"},
      {"roelands_z", "z"},
      {"shear_thinning", "shear thinning"},
      {"cross_ratio", "Cross r"},
      {"cross_exponent", "Cross m"},
      {"cross_rate", "Cross rate"},  // γ̇c: the combining dot is lost in many fonts
      {"hths", "HTHS"},
      {"bulk_modulus", "β"},
      {"density_law", "density law"}};
  auto number = [&](const char* name, double OilSpec::*member, const Info& info,
                    std::string description) {
    CaseField field = Base(prefix + name, FieldKind::kNumber, info);
    field.symbol = symbol_prefix + kSymbol.at(name);
    field.get = [oil, member](const EngineCase& c) {
      return oil(const_cast<EngineCase&>(c)).*member;
    };
    field.set = [oil, member](EngineCase& c, double v) { oil(c).*member = v; };
    field.description = std::move(description);
    f.push_back(std::move(field));
  };
  auto choice = [&](const char* name, auto OilSpec::*member, std::vector<std::string> names,
                    const Info& info, std::string description) {
    CaseField field = Base(prefix + name, FieldKind::kChoice, info);
    field.symbol = symbol_prefix + kSymbol.at(name);
    field.choices = std::move(names);
    field.choice = [oil, member](const EngineCase& c) {
      return static_cast<int>(oil(const_cast<EngineCase&>(c)).*member);
    };
    field.set_choice = [oil, member](EngineCase& c, int k) {
      using Enum = std::remove_reference_t<decltype(oil(c).*member)>;
      oil(c).*member = static_cast<Enum>(k);
    };
    field.description = std::move(description);
    f.push_back(std::move(field));
  };
  using lubrication::PressureLaw;
  using lubrication::ViscosityModel;
  choice("viscosity_model", &OilSpec::model,
         {ToString(ViscosityModel::kConstant), ToString(ViscosityModel::kVogel),
          ToString(ViscosityModel::kGrade)},
         {group,
          "Viscosity model",
          "",
          "",
          1.0,
          {},
          "\"constant\", \"vogel\" (temperature) or \"grade\" (a catalogue oil)"},
         "How the viscosity follows the film temperature: a constant, Vogel's law with the "
         "constants below, or Vogel's law fitted to a catalogue oil of an SAE grade " +
             whose);
  {
    std::vector<std::string> grades;
    static const std::string products = [] {
      std::string list = "with the model \"grade\": ";
      for (const lubrication::OilGrade& g : lubrication::OilCatalogue())
        list += std::string(g.key) + " = " + std::string(g.product) + "; ";
      return list.substr(0, list.size() - 2);
    }();
    for (const lubrication::OilGrade& g : lubrication::OilCatalogue()) grades.emplace_back(g.key);
    choice("grade", &OilSpec::grade, std::move(grades),
           {group, "Oil grade (catalogue)", "", "", 1.0, {}, products.c_str()},
           "The catalogue oil (an SAE grade's representative product, fitted from its published "
           "40 and 100 °C viscosities and density; valid 40–150 °C, outside a warning) " +
               whose);
  }
  number(
      "viscosity", &OilSpec::viscosity,
      {group, "Dynamic viscosity μ", "Pa*s", "mPa·s", 1e-3, Viscosity(),
       "with the constant model; Table I: 0.02 Pa·s"},
      "Dynamic viscosity of the oil at its running temperature, with the constant model " + whose);
  number("vogel_a", &OilSpec::vogel_a,
         {group,
          "Vogel's law: factor a",
          "Pa*s",
          "mPa·s",
          1e-3,
          {0.0, 1e3, false, false},
          "μ = a exp(b / (T − c)), T in kelvin; > 0"},
         "Vogel's law μ = a·exp(b / (T − c)): the factor a " + whose);
  number("vogel_b", &OilSpec::vogel_b,
         {group, "Vogel's law: b", "K", "K", 1.0, {0.0, 1e5, false, false}, "> 0"},
         "Vogel's law: the constant b in the exponent " + whose);
  number("vogel_c", &OilSpec::vogel_c,
         {group, "Vogel's law: pole c", "K", "K", 1.0, Between(-1e4, 1e4),
          "the pole: temperatures must stay above it"},
         "Vogel's law: the pole temperature c (in kelvin; a constant given in °C plus 273.15) " +
             whose);
  choice("pressure_viscosity", &OilSpec::pressure_law,
         {ToString(PressureLaw::kNone), ToString(PressureLaw::kBarus),
          ToString(PressureLaw::kRoelands)},
         {group, "Pressure–viscosity law", "", "", 1.0, {}, "\"none\", \"barus\" or \"roelands\""},
         "How the viscosity rises with the film pressure: not at all, Barus' exponential or "
         "Roelands' law " +
             whose);
  number("barus_alpha", &OilSpec::barus_alpha,
         {group,
          "Barus coefficient α",
          "1/Pa",
          "1/GPa",
          1e-9,
          {0.0, 1e-6, false, false},
          "μ₀ exp(α p); mineral oils of engine-oil viscosity: 16–26 1/GPa at 60–100 °C "
          "(Stachowiak & Batchelor, Engineering Tribology, Table 2.3)"},
         "Pressure–viscosity coefficient α of Barus' law μ = μ₀·exp(α p) " + whose);
  number("roelands_z", &OilSpec::roelands_z,
         {group,
          "Roelands index z",
          "-",
          "–",
          1.0,
          {0.0, 2.0, false, false},
          "pressure–viscosity index; about 0.6 for mineral oils"},
         "Pressure–viscosity index z of Roelands' law " + whose);
  using lubrication::ShearThinning;
  choice("shear_thinning", &OilSpec::shear_thinning,
         {ToString(ShearThinning::kNone), ToString(ShearThinning::kCross),
          ToString(ShearThinning::kHths)},
         {group,
          "Shear thinning",
          "",
          "",
          1.0,
          {},
          "\"none\", \"cross\" (critical shear rate given) or \"hths\" (from the HTHS "
          "viscosity)"},
         "How the viscosity falls with the film's shear rate (polymer-thickened multigrades): "
         "not at all, or Cross' law μ = μ₁ [r + (1 − r) / (1 + (γ̇/γ̇c)^m)] with γ̇ = |ΔU| / h, "
         "its critical rate given or set by the HTHS viscosity " +
             whose);
  number("cross_ratio", &OilSpec::cross_ratio,
         {group,
          "Cross: second Newtonian ratio r",
          "-",
          "–",
          1.0,
          {0.0, 1.0, false, false},
          "μ₂ / μ₁, the fully sheared viscosity over the low-shear one; 0 < r < 1 (assumed 0.7)"},
         "Cross' law: the ratio r of the second Newtonian viscosity to the low-shear one " + whose);
  number("cross_exponent", &OilSpec::cross_exponent,
         {group,
          "Cross: exponent m",
          "-",
          "–",
          1.0,
          {0.0, 10.0, false, false},
          "> 0 (assumed 1, Cross' own)"},
         "Cross' law: the exponent m " + whose);
  number("cross_rate", &OilSpec::cross_rate,
         {group,
          "Cross: critical shear rate at 150 °C",
          "1/s",
          "1/s",
          1.0,
          {0.0, 1e12, false, false},
          "with shear thinning \"cross\"; shifted to the film temperature by μ₁(150 °C)/μ₁(T)"},
         "Cross' law: the critical shear rate at 150 °C (the HTHS temperature) " + whose);
  number("hths", &OilSpec::hths,
         {group,
          "HTHS viscosity (150 °C, 10⁶ 1/s)",
          "Pa*s",
          "mPa·s",
          1e-3,
          {0.0, 1.0, false, false},
          "with shear thinning \"hths\": ASTM D4683 / CEC L-36; between r μ₁ and μ₁ at 150 °C; "
          "0 with a catalogue oil: its own"},
         "The oil's high-temperature high-shear viscosity, which sets Cross' critical shear rate "
         "(μ(150 °C, 10⁶ 1/s) = HTHS) " +
             whose);
  number("bulk_modulus", &OilSpec::bulk_modulus,
         {group, "Bulk modulus β (mass-conserving films)", "Pa", "GPa", 1e9,
          Between(0.0, OilSpec::kMaxBulkModulus),
          "0 = incompressible, else at least 0.01 GPa; mineral oils about 1.7 GPa "
          "(Dowson–Higginson's density law at low pressure); a JFO film's full zone then stores "
          "oil as its pressure rises; not with a pressure–viscosity law"},
         "Bulk modulus of the oil in the full zone of a mass-conserving (JFO) film, at low "
         "pressure: the film stores oil as its pressure rises (density_law) and a collapsing "
         "void is cushioned; 0 keeps the oil incompressible (Reynolds films always are) " +
             whose);
  using lubrication::DensityLaw;
  choice("density_law", &OilSpec::density_law,
         {ToString(DensityLaw::kLinear), ToString(DensityLaw::kDowsonHigginson)},
         {group,
          "Density law (compressible oil)",
          "",
          "",
          1.0,
          {},
          "\"linear\": ρ/ρ₀ = 1 + p/β, for p/β of a few per cent; \"dowson_higginson\": "
          "ρ/ρ₀ = 1 + (p/β)/(1 + p/(0.353 β)), stiffening with pressure (at most 35 % "
          "denser), for film pressures of 0.1 GPa and more"},
         "How a compressible oil's density rises with the film pressure: linearly with the bulk "
         "modulus β, or by Dowson and Higginson's law ρ/ρ₀ = 1 + 0.6p/(1 + 1.7p) (p in GPa) with "
         "its low-pressure slope set to 1/β " +
             whose);
}

lubrication::OilSpec& LubricantOil(EngineCase& c) { return c.lubricant; }
lubrication::OilSpec& SkirtOil(EngineCase& c) { return c.skirt.oil.own; }
lubrication::OilSpec& BigEndOil(EngineCase& c) { return c.big_end.oil.own; }

// A joint's oil: its source and film temperature, then its own oil's fields.
template <typename Section>
void AddJointOilFields(std::vector<CaseField>& f, const std::string& joint,
                       Section EngineCase::*section, FieldGroup group, OilOf own) {
  CaseField source = Base(joint + ".oil.source", FieldKind::kChoice,
                          {group, "Oil", "", "", 1.0, {}, "\"lubricant\" (the case's) or \"own\""});
  source.choices = {"lubricant", "own"};
  source.choice = [section](const EngineCase& c) {
    return static_cast<int>((c.*section).oil.source);
  };
  source.set_choice = [section](EngineCase& c, int k) {
    (c.*section).oil.source = static_cast<OilSource>(k);
  };
  source.description = "Which oil this film carries: the case's lubricant, or its own (the " +
                       joint + ".oil.* fields below).";
  f.push_back(std::move(source));
  CaseField temperature = Base(joint + ".oil.temperature", FieldKind::kNumber,
                               {group,
                                "Film temperature",
                                "K",
                                "°C",
                                1.0,
                                {0.0, 1000.0, true, false},
                                "used where the viscosity follows temperature (Vogel's law)"});
  temperature.display_offset = lubrication::kZeroCelsius;  // shown in °C
  temperature.get = [section](const EngineCase& c) { return (c.*section).oil.temperature; };
  temperature.set = [section](EngineCase& c, double v) { (c.*section).oil.temperature = v; };
  temperature.description =
      "Temperature of this joint's oil film (one value over the film and the cycle); with a "
      "Vogel viscosity it sets the viscosity.";
  f.push_back(std::move(temperature));
  CaseField mode =
      Base(joint + ".oil.temperature_mode", FieldKind::kChoice,
           {group, "Film temperature from", "", "", 1.0, {}, "\"given\" or \"heat_balance\""});
  mode.choices = {"given", "heat_balance"};
  mode.choice = [section](const EngineCase& c) {
    return static_cast<int>((c.*section).oil.temperature_mode);
  };
  mode.set_choice = [section](EngineCase& c, int k) {
    (c.*section).oil.temperature_mode = static_cast<FilmTemperature>(k);
  };
  mode.description =
      "Given: the film temperature above. Heat balance: the run is repeated until the film's "
      "temperature is the supply temperature plus the share of its friction power that its "
      "leaving oil carries away (the temperature above is the first guess).";
  f.push_back(std::move(mode));
  CaseField share = Base(joint + ".oil.heat_share", FieldKind::kNumber,
                         {group,
                          "Heat balance: share of the friction power",
                          "-",
                          "–",
                          1.0,
                          {0.0, 1.0, true, false},
                          "carried away by the oil leaving the film; 1 = all (the hottest)"});
  share.get = [section](const EngineCase& c) { return (c.*section).oil.heat_share; };
  share.set = [section](EngineCase& c, double v) { (c.*section).oil.heat_share = v; };
  share.description =
      "In the heat balance, the share of the joint's friction power that heats the oil leaving "
      "the film; the rest goes into the parts.";
  f.push_back(std::move(share));
  const size_t first = f.size();
  const std::string who = joint == "skirt" ? "skirt" : "big-end";
  AddOilFields(f, joint + ".oil.", group, own, "(this joint's own oil).", who + " ");
  for (size_t k = first; k < f.size(); ++k) f[k].label = "Own oil: " + f[k].label;
  f[first - 4].symbol = who + " oil";
  f[first - 3].symbol = who + " film T";
  f[first - 2].symbol = who + " film T from";
  f[first - 1].symbol = who + " heat share";
}

// A temperature in K, shown in °C.
template <typename Section>
void AddTemperatureField(std::vector<CaseField>& f, const std::string& path,
                         Section EngineCase::*section, double Section::*member, FieldGroup group,
                         const char* label, const char* symbol, const char* description) {
  CaseField field = Scalar(path, section, member,
                           {group,
                            label,
                            "K",
                            "°C",
                            1.0,
                            {0.0, 1000.0, true, false},
                            "the cold dimensions are at 20 °C"});
  field.display_offset = lubrication::kZeroCelsius;
  field.symbol = symbol;
  field.description = description;
  f.push_back(std::move(field));
}

CaseField Text(std::string path, std::string EngineCase::*member, const Info& info) {
  CaseField f = Base(std::move(path), FieldKind::kText, info);
  f.text = [member](EngineCase& c) -> std::string& { return c.*member; };
  return f;
}

template <class Section>
CaseField Text(std::string path, Section EngineCase::*section, std::string Section::*member,
               const Info& info) {
  CaseField f = Base(std::move(path), FieldKind::kText, info);
  f.text = [section, member](EngineCase& c) -> std::string& { return c.*section.*member; };
  return f;
}

// The short label of every field (CaseField::symbol): the paper's symbol where it has one, a
// few words otherwise; those of the two joints say which joint where the symbol alone does not.
void SetSymbols(std::vector<CaseField>& fields) {
  static const std::map<std::string_view, const char*> kSymbols = {
      {"name", "name"},
      {"description", "description"},
      {"geometry.crank_radius", "L₁"},
      {"geometry.rod_length", "L₂"},
      {"geometry.crank_com_radius", "L_r"},
      {"geometry.crank_mass", "m₁"},
      {"geometry.crank_inertia", "J₁"},
      {"geometry.rod_com_from_big_end", "L_c"},
      {"geometry.rod_mass", "m₂"},
      {"geometry.rod_inertia", "J₂"},
      {"geometry.piston_mass", "m₃"},
      {"geometry.piston_inertia", "J₃"},
      {"geometry.pin_offset", "C_p"},
      {"geometry.piston_com_lateral_offset", "c_g"},
      {"geometry.skirt_top_to_pin", "a_p"},
      {"geometry.skirt_top_to_com", "b_p"},
      {"geometry.liner_radius", "R_l"},
      {"geometry.compression_ratio", "compression ratio"},
      {"geometry.gravity", "g"},
      {"skirt.model", "skirt joint"},
      {"skirt.cold_clearance", "c_skirt"},
      {"skirt.length", "L_skirt"},
      {"skirt.thrust_half_width", "α₁"},
      {"skirt.anti_thrust_half_width", "α₂"},
      {"skirt.roughness_skirt", "σ_skirt"},
      {"skirt.roughness_liner", "σ_liner"},
      {"skirt.peklenik", "γ skirt"},
      {"skirt.modulus_skirt", "E_skirt"},
      {"skirt.poisson_skirt", "ν_skirt"},
      {"skirt.modulus_liner", "E_liner"},
      {"skirt.poisson_liner", "ν_liner"},
      {"skirt.compliance", "skirt surfaces"},
      {"skirt.layer_thickness", "t_skirt layer"},
      {"skirt.compliance_file", "skirt compliance file"},
      {"skirt.boundary_friction", "μ_f skirt"},
      {"skirt.cavitation", "skirt cavitation"},
      {"skirt.piston_expansion", "α piston"},
      {"lubricant.density", "ρ oil"},
      {"lubricant.heat_capacity", "c_p oil"},
      {"skirt.liner_expansion", "α liner"},
      {"big_end.journal_expansion", "α journal"},
      {"big_end.bearing_expansion", "α bearing"},
      {"skirt.supply", "skirt oil supply"},
      {"skirt.oil_film", "h_oil"},
      {"skirt.oil_film_positions", "liner oil film"},
      {"skirt.oil_film_values", "liner oil film"},
      {"skirt.mesh_thrust", "skirt mesh Ω₁"},
      {"skirt.mesh_relief", "skirt mesh Ω₂"},
      {"skirt.mesh_anti", "skirt mesh Ω₃"},
      {"skirt.mesh_axial", "skirt mesh axial"},
      {"skirt.profile_y", "skirt profile"},
      {"skirt.profile_h", "skirt profile"},
      {"skirt.ovality_alpha", "skirt ovality"},
      {"skirt.ovality_h", "skirt ovality"},
      {"big_end.model", "big-end joint"},
      {"big_end.bearing_radius", "R_b"},
      {"big_end.journal_radius", "R_j"},
      {"big_end.width", "b"},
      {"big_end.roughness_journal", "σ_j"},
      {"big_end.roughness_bearing", "σ_b"},
      {"big_end.peklenik", "γ big end"},
      {"big_end.modulus_journal", "E_j"},
      {"big_end.poisson_journal", "ν_j"},
      {"big_end.modulus_bearing", "E_b"},
      {"big_end.poisson_bearing", "ν_b"},
      {"big_end.boundary_friction", "μ_f big end"},
      {"big_end.cavitation", "big-end cavitation"},
      {"big_end.mesh_theta", "big-end mesh around"},
      {"big_end.mesh_theta_grading", "big-end grading around"},
      {"big_end.mesh_z", "big-end mesh across"},
      {"big_end.mesh_z_grading", "big-end grading across"},
      {"big_end.oil_feed_pressure", "p_feed"},
      {"big_end.supply", "big-end oil supply"},
      {"big_end.compliance", "big-end surfaces"},
      {"big_end.layer_thickness", "t_lining"},
      {"big_end.compliance_file", "big-end compliance file"},
      {"big_end.supply_pressure_angles", "supply-pressure curve"},
      {"big_end.supply_pressure_values", "supply-pressure curve"},
      {"big_end.supply_hole_angles", "supply-hole angles"},
      {"big_end.supply_hole_diameter", "supply-hole diameter"},
      {"big_end.groove_start_angle", "groove start"},
      {"big_end.groove_end_angle", "groove end"},
      {"big_end.groove_width", "groove width"},
      {"lubricant.viscosity", "μ"},
      {"lubricant.greenwood_tripp_k", "K"},
      {"operating.rpm", ""},
      {"operating.crankcase_pressure", "p_cc"},
      {"operating.start_crank_angle", "start angle"},
      {"solver.baumgarte_alpha", "G"},  // the paper's script G (𝒢), which many fonts lack
      {"solver.baumgarte_beta", "ζ"},
      {"solver.relative_tolerance", "rel. tolerance"},
      {"solver.position_tolerance", "position tolerance"},
      {"solver.output_interval", "output interval"},
      {"solver.steady_state_tolerance", "steady-state tolerance"},
      {"solver.max_cycles", "max cycles"},
      {"solver.run_in_angle", "run-in"},
      {"solver.jfo_run_in_angle", "run-in (JFO)"},
      {"solver.error_estimate", "error estimate"},
  };
  for (CaseField& field : fields) {
    const auto found = kSymbols.find(field.path);
    // A new field without a short label still reads sensibly: its full label.
    if (found != kSymbols.end())
      field.symbol = found->second;
    else if (field.symbol.empty())
      field.symbol = field.label;
  }
}

// What every field is, in plain words (CaseField::description): the first line of the case
// editor's tooltip. A test requires one for every field.
void SetDescriptions(std::vector<CaseField>& fields) {
  static const std::map<std::string_view, const char*> kDescriptions = {
      {"name",
       "A short name for this case; it names the folders that runs write their results to."},
      {"description", "Free text about the case: where its values come from, what was changed."},
      {"geometry.crank_radius",
       "Distance from the main-bearing axis to the crank-pin axis: half the stroke."},
      {"geometry.rod_length",
       "Distance between the big-end and small-end (piston pin) centres of the connecting rod."},
      {"geometry.crank_com_radius",
       "Distance from the main-bearing axis to the crank's centre of mass."},
      {"geometry.crank_mass",
       "Mass of the crank. The crank turns at an imposed speed, so it only changes the "
       "main-bearing force and the drive torque."},
      {"geometry.crank_inertia",
       "Moment of inertia of the crank about its centre of mass; it only changes the drive "
       "torque."},
      {"geometry.rod_com_from_big_end",
       "Where the connecting rod's centre of mass lies, measured along the rod from the big-end "
       "centre."},
      {"geometry.rod_mass", "Mass of the connecting rod."},
      {"geometry.rod_inertia", "Moment of inertia of the connecting rod about its centre of mass."},
      {"geometry.piston_mass",
       "Mass of the piston with its pin and rings: what the skirt film has to guide."},
      {"geometry.piston_inertia",
       "Moment of inertia of the piston about its centre of mass: resists the piston's tilt."},
      {"geometry.pin_offset",
       "Sideways offset of the piston-pin axis from the bore axis, positive toward the major "
       "thrust side."},
      {"geometry.piston_com_lateral_offset",
       "Sideways offset of the piston's centre of mass from the bore axis, positive toward the "
       "major thrust side."},
      {"geometry.skirt_top_to_pin",
       "Axial distance from the top of the skirt down to the piston-pin axis."},
      {"geometry.skirt_top_to_com",
       "Axial distance from the top of the skirt down to the piston's centre of mass (negative: "
       "above the skirt top)."},
      {"geometry.liner_radius",
       "Radius of the cylinder bore. The gas pressure acts on the piston crown over this "
       "circle."},
      {"geometry.compression_ratio",
       "Compression ratio; used only to build the synthetic cylinder-pressure curves."},
      {"geometry.gravity", "Acceleration of gravity, along the cylinder axis toward the crank."},
      {"skirt.model",
       "How the piston is guided in the bore: ideally (no clearance) or on a lubricated oil "
       "film with asperity contact."},
      {"skirt.cold_clearance",
       "Radial gap between the piston skirt and the bore at the skirt's largest diameter, "
       "measured cold. The piston radius is the bore radius minus this gap; the barrel profile "
       "and ovality add to it."},
      {"skirt.length", "Axial length of the piston skirt, the part that carries the oil film."},
      {"skirt.thrust_half_width",
       "Half the angle that the skirt panel on the major thrust side covers around the bore."},
      {"skirt.anti_thrust_half_width",
       "Half the angle that the skirt panel on the anti-thrust side covers; between the panels "
       "lies the pin-boss relief, which carries no film."},
      {"skirt.roughness_skirt",
       "Root-mean-square surface roughness of the skirt; with the liner's it sets when "
       "asperities touch."},
      {"skirt.roughness_liner", "Root-mean-square surface roughness of the liner (bore)."},
      {"skirt.peklenik",
       "Orientation of the roughness pattern: 1 for isotropic surfaces, below 1 for grooves "
       "along the sliding direction, above 1 across it."},
      {"skirt.modulus_skirt",
       "Young's modulus of the skirt material; with the liner's it sets how hard touching "
       "asperities press."},
      {"skirt.poisson_skirt", "Poisson ratio of the skirt material."},
      {"skirt.modulus_liner", "Young's modulus of the liner material."},
      {"skirt.poisson_liner", "Poisson ratio of the liner material."},
      {"skirt.compliance",
       "Whether the skirt and liner surfaces deform under the film pressure. \"rigid\": they do "
       "not (as in the paper). \"elastic_layer\": the skirt's surface layer, of the given "
       "thickness, is squeezed point by point against a rigid body (its Young's modulus and "
       "Poisson ratio are the skirt's). \"half_space\": skirt and liner deform as elastic "
       "half-spaces under each panel's film. \"imported\": the skirt deforms as a finite-element "
       "model of it says (the compliance file). The film and the deformation are then solved "
       "together at every step."},
      {"skirt.layer_thickness",
       "Thickness of the skirt's surface layer that deforms with the elastic-layer model (the "
       "piston behind it is taken as rigid)."},
      {"skirt.compliance_file",
       "The skirt's compliance computed by a finite-element program, for the \"imported\" "
       "model: a Matrix Market file beside the case (its nodes in the file of the same name "
       "ending .nodes.csv, placed by their angle from the thrust axis and their distance from "
       "the skirt top; the format is described in the documentation's compliance-files page)."},
      {"skirt.boundary_friction",
       "Friction coefficient where skirt and liner asperities touch (boundary lubrication)."},
      {"skirt.cavitation",
       "How the oil film breaks up where the gap widens and refills where it narrows. "
       "\"reynolds\": the pressure is simply kept from falling below the cavitation pressure, "
       "as the paper does; oil is not conserved where the film reforms. \"jfo\": the film's "
       "oil content is tracked from one time step to the next, so a film that broke up earlier "
       "in the cycle refills only as oil arrives (mass-conserving; somewhat slower)."},
      {"skirt.supply",
       "How oil reaches the skirt. \"flooded\": as much as the film can take, always (the "
       "paper's assumption). \"starved\": only the oil film the piston rings leave on the "
       "liner; the skirt then runs partly dry. Needs the \"jfo\" cavitation model. Its "
       "figures converge more slowly with the mesh than a flooded skirt's, and the side-force "
       "peak where the skirt runs from the starved onto the full film needs a finer skirt mesh "
       "than the default (it grew 2.6× from the default mesh to one four times as fine in a "
       "measured case)."},
      {"skirt.oil_film",
       "Thickness of the oil layer left on the liner that feeds a starved skirt, the same over "
       "the whole stroke."},
      {"skirt.oil_film_positions",
       "Positions along the liner (from where the skirt top is at top dead centre, toward the "
       "crank) at which the liner's oil film is given; leave empty for a constant film."},
      {"skirt.oil_film_values", "Thickness of the liner's oil film at each of those positions."},
      {"skirt.piston_expansion",
       "Linear thermal expansion coefficient of the piston skirt's material."},
      {"lubricant.density", "Density of the oil, for the joints' heat balances."},
      {"lubricant.heat_capacity",
       "Specific heat of the oil, for the joints' heat balances: the heat a kilogram takes per "
       "kelvin."},
      {"skirt.liner_expansion", "Linear thermal expansion coefficient of the liner's material."},
      {"big_end.journal_expansion",
       "Linear thermal expansion coefficient of the crank pin's material."},
      {"big_end.bearing_expansion",
       "Linear thermal expansion coefficient of the bearing housing (the rod's big-end eye)."},
      {"skirt.mesh_thrust",
       "Number of elements around the thrust panel in the film calculation; more is finer and "
       "slower."},
      {"skirt.mesh_relief", "Number of elements around the pin-boss relief between the panels."},
      {"skirt.mesh_anti",
       "Number of elements around the anti-thrust panel in the film calculation."},
      {"skirt.mesh_axial", "Number of elements along the skirt in the film calculation."},
      {"skirt.profile_y",
       "Positions down the skirt, from its top, at which the barrel profile is given."},
      {"skirt.profile_h",
       "Barrel profile: how much the skirt radius drops below its largest diameter at each "
       "position, adding to the clearance."},
      {"skirt.ovality_alpha",
       "Angles from the thrust axis at which the skirt's ovality is given (leave empty for a "
       "round skirt)."},
      {"skirt.ovality_h", "Ovality: the extra radial gap at each angle, adding to the clearance."},
      {"big_end.model",
       "How the connecting rod's big end turns on the crank pin: ideally (no clearance) or on a "
       "lubricated oil film with asperity contact."},
      {"big_end.bearing_radius", "Inner radius of the big-end bearing shells."},
      {"big_end.journal_radius",
       "Radius of the crank-pin journal; the bearing radius minus this is the radial clearance."},
      {"big_end.width", "Axial width of the big-end bearing, the length of the oil film."},
      {"big_end.roughness_journal", "Root-mean-square surface roughness of the crank-pin journal."},
      {"big_end.roughness_bearing", "Root-mean-square surface roughness of the bearing lining."},
      {"big_end.peklenik",
       "Orientation of the roughness pattern in the big end: 1 for isotropic surfaces."},
      {"big_end.modulus_journal", "Young's modulus of the crank-pin journal material."},
      {"big_end.poisson_journal", "Poisson ratio of the crank-pin journal material."},
      {"big_end.modulus_bearing", "Young's modulus of the bearing lining material."},
      {"big_end.poisson_bearing", "Poisson ratio of the bearing lining material."},
      {"big_end.boundary_friction",
       "Friction coefficient where journal and bearing asperities touch (boundary lubrication)."},
      {"big_end.cavitation",
       "How the oil film breaks up where the gap widens and refills where it narrows. "
       "\"reynolds\": the pressure is simply kept from falling below the cavitation pressure, "
       "as the paper does; oil is not conserved where the film reforms. \"jfo\": the film's "
       "oil content is tracked from one time step to the next, so a film that broke up earlier "
       "in the cycle refills only as oil arrives (mass-conserving; somewhat slower)."},
      {"big_end.mesh_theta",
       "Number of elements around the bearing in the film calculation; more is finer and "
       "slower."},
      {"big_end.mesh_theta_grading",
       "How much finer the elements are where the film is thinnest than elsewhere around the "
       "bearing (1: all equal)."},
      {"big_end.mesh_z", "Number of elements across the bearing width in the film calculation."},
      {"big_end.mesh_z_grading",
       "How much finer the elements are at the bearing edges than at its middle (1: all equal)."},
      {"big_end.compliance",
       "Whether the big-end surfaces deform under the film pressure. \"rigid\": they do not (as in "
       "the paper). \"elastic_layer\": the bearing lining, of the given thickness, is squeezed "
       "point by point against a rigid backing (its Young's modulus and Poisson ratio are the "
       "bearing's). \"half_space\": journal and bearing deform as elastic half-spaces, each "
       "point under the pressure of the whole film (a model for a loaded zone small against the "
       "radius: round a whole bearing it gives way far more than a shell, and engine runs of the "
       "default case end in their run-in: use the elastic layer or an imported compliance "
       "there). The film and the deformation are then solved "
       "together at every step."},
      {"big_end.layer_thickness",
       "Thickness of the bearing lining that deforms with the elastic-layer model (the backing "
       "behind it is taken as rigid)."},
      {"big_end.compliance_file",
       "The bearing's compliance computed by a finite-element program, for the \"imported\" "
       "model: a Matrix Market file beside the case (its nodes in the file of the same name "
       "ending .nodes.csv; the format is described in the documentation's compliance-files "
       "page)."},
      {"big_end.supply",
       "Where oil enters the big-end film. \"line_of_centres\": no supply modelled, the film "
       "simply starts where the gap is widest (as the paper and the classic bearing tables do). "
       "\"shell_holes\": holes through the bearing shell, fixed in the rod. \"pin_holes\": "
       "drillings in the crank pin that turn with the crank. \"groove\": a groove in the shell, "
       "part of the way round or all the way. \"pin_holes_and_groove\": both, the pin's "
       "drillings passing under the shell's groove as the crank turns, fed at one pressure."},
      {"big_end.oil_feed_pressure",
       "Gauge pressure of the oil at the supply holes or groove (constant over the cycle unless a "
       "supply-pressure curve is given)."},
      {"big_end.supply_pressure_angles",
       "Crank angles at which the supply pressure is given, over the 720° cycle; leave empty for "
       "a constant supply pressure."},
      {"big_end.supply_pressure_values",
       "Supply gauge pressure at each of those crank angles (smoothly interpolated, repeating "
       "every cycle)."},
      {"big_end.supply_hole_angles",
       "Where the supply holes are: shell holes measured from the rod axis toward the small "
       "end, crank-pin holes from the crank web's axis, counter-clockwise. One angle per hole."},
      {"big_end.supply_hole_diameter",
       "Diameter of each supply hole. The film holds the supply pressure inside the hole, its "
       "edge placed where it cuts the mesh lines; the film around it needs elements smaller "
       "than the hole: with 10 elements across (one node row in a 4 mm hole) the oil a "
       "crank-pin hole feeds a mass-conserving film was 7 % low, with 20 across within 2 % "
       "(big-end mesh); a run on a mesh too coarse for the hole warns."},
      {"big_end.groove_start_angle",
       "Where the shell groove starts, from the rod axis toward the small end, "
       "counter-clockwise."},
      {"big_end.groove_end_angle", "Where the shell groove ends (a full circle: start + 360°)."},
      {"big_end.groove_width", "Axial width of the shell groove, centred on the bearing width."},
      {"lubricant.greenwood_tripp_k",
       "Constant of the asperity contact model: scales the contact pressure of touching rough "
       "surfaces."},
      {"operating.rpm", "Crank speed of the run; the crank turns at this constant speed."},
      {"operating.crankcase_pressure",
       "Absolute gas pressure below the piston; the gas force is the cylinder pressure minus "
       "this, times the bore area."},
      {"operating.start_crank_angle",
       "Crank angle at which the first monitored cycle starts (a run-in starts that much "
       "earlier); results, fields and plots label crank angles in [0, 720) whatever it is."},
      {"solver.baumgarte_alpha",
       "Stabilisation of the joint constraints against drift: how strongly position errors are "
       "pulled back."},
      {"solver.baumgarte_beta",
       "Stabilisation of the joint constraints against drift: how strongly velocity errors are "
       "damped."},
      {"solver.relative_tolerance",
       "Accuracy of the time integration of velocities, relative to each velocity's size "
       "(positions and angles are held at absolute tolerances); smaller is more accurate and "
       "slower."},
      {"solver.position_tolerance",
       "Accuracy of the time integration for positions, as an absolute length."},
      {"solver.output_interval", "Crank angle between two rows of results."},
      {"solver.steady_state_tolerance",
       "A run is steady when no monitored quantity changes from one cycle to the next by more "
       "than this fraction of its range."},
      {"solver.max_cycles",
       "Most engine cycles computed before a run stops without a steady state."},
      {"solver.run_in_angle",
       "Crank angle computed before the first monitored cycle, so that the start from rest has "
       "died out."},
      {"solver.jfo_run_in_angle",
       "The run-in when a film conserves mass (JFO): its film starts full of oil and drains over "
       "about two cycles, which the run-in computes more cheaply than monitored cycles."},
      {"solver.error_estimate",
       "1: a second run on meshes with half the elements estimates how accurate the main "
       "figures are; 0: off."},
  };
  for (CaseField& field : fields) {
    const auto found = kDescriptions.find(field.path);
    if (found != kDescriptions.end()) field.description = found->second;
  }
}

std::vector<CaseField> MakeSchema() {
  using G = FieldGroup;
  const auto geo = &EngineCase::geometry;
  const auto sk = &EngineCase::skirt;
  const auto be = &EngineCase::big_end;
  const auto lub = &EngineCase::lubricant;
  const auto op = &EngineCase::operating;
  const auto sol = &EngineCase::solver;
  using CG = CrankTrainGeometry;
  using S = SkirtCase;
  using B = BigEndCase;
  std::vector<CaseField> f;
  f.push_back(Text("name", &EngineCase::name,
                   {G::kCase, "Case name", "", "", 1.0, {}, "names the run folders"}));
  f.push_back(Text("description", &EngineCase::description,
                   {G::kCase, "Description", "", "", 1.0, {}, "free text"}));
  // Geometry and masses (Table I of Zhao & Shen).
  f.push_back(Scalar("geometry.crank_radius", geo, &CG::crank_radius,
                     {G::kGeometry, "Crank radius L₁", "m", "mm", kMm, Length(),
                      "main journal to crank pin; Table I: 39.93 mm"}));
  f.push_back(Scalar("geometry.rod_length", geo, &CG::rod_length,
                     {G::kGeometry, "Connecting-rod length L₂", "m", "mm", kMm, Length(),
                      "big-end to small-end centre, > crank_radius + |pin_offset|; Table I: "
                      "129.5 mm"}));
  f.push_back(Scalar("geometry.crank_com_radius", geo, &CG::crank_com_radius,
                     {G::kGeometry, "Crank CoM radius L_r", "m", "mm", kMm, Offset(),
                      "main journal to the crank's centre of mass; Table I: 20 mm"}));
  f.push_back(Scalar("geometry.crank_mass", geo, &CG::crank_mass,
                     {G::kMasses, "Crank mass m₁", "kg", "kg", 1.0, Mass(),
                      "the crank speed is imposed: changes only the main-bearing force and "
                      "drive torque"}));
  f.push_back(Scalar("geometry.crank_inertia", geo, &CG::crank_inertia,
                     {G::kMasses, "Crank inertia J₁ (CoM)", "kg*m^2", "kg·m²", 1.0, Inertia(),
                      "about the crank's centre of mass"}));
  f.push_back(Scalar("geometry.rod_com_from_big_end", geo, &CG::rod_com_from_big_end,
                     {G::kGeometry, "Rod CoM from big end L_c", "m", "mm", kMm, Offset(),
                      "on the rod, ≤ rod_length; Table I: 28.49 mm, read as from the big-end "
                      "centre"}));
  f.push_back(Scalar("geometry.rod_mass", geo, &CG::rod_mass,
                     {G::kMasses, "Rod mass m₂", "kg", "kg", 1.0, Mass(), "Table I: 0.345 kg"}));
  f.push_back(Scalar("geometry.rod_inertia", geo, &CG::rod_inertia,
                     {G::kMasses, "Rod inertia J₂ (CoM)", "kg*m^2", "kg·m²", 1.0, Inertia(),
                      "about the rod's centre of mass; Table I: 9.67e-4 kg·m²"}));
  f.push_back(Scalar("geometry.piston_mass", geo, &CG::piston_mass,
                     {G::kMasses, "Piston mass m₃", "kg", "kg", 1.0, Mass(), "Table I: 0.264 kg"}));
  f.push_back(Scalar("geometry.piston_inertia", geo, &CG::piston_inertia,
                     {G::kMasses, "Piston inertia J₃ (CoM)", "kg*m^2", "kg·m²", 1.0, Inertia(),
                      "about the piston's centre of mass; Table I: 1.29e-4 kg·m²"}));
  f.push_back(
      Scalar("geometry.pin_offset", geo, &CG::pin_offset,
             {G::kGeometry, "Pin offset C_p (+ thrust)", "m", "mm", kMm, Between(-0.01, 0.01),
              "pin axis from the bore axis, + toward the major thrust side; Table I: "
              "0.7 mm"}));
  f.push_back(Scalar(
      "geometry.piston_com_lateral_offset", geo, &CG::piston_com_lateral_offset,
      {G::kGeometry, "Piston CoM offset c_g (+ thrust)", "m", "mm", kMm, Between(-0.01, 0.01),
       "piston centre of mass from the bore axis, + toward thrust; Table I: "
       "0.13 mm"}));
  f.push_back(Scalar("geometry.skirt_top_to_pin", geo, &CG::skirt_top_to_pin,
                     {G::kGeometry, "Skirt top to pin a_p", "m", "mm", kMm, Between(-0.2, 0.2),
                      "+ toward the crank; Table I: 11.8 mm"}));
  f.push_back(Scalar("geometry.skirt_top_to_com", geo, &CG::skirt_top_to_com,
                     {G::kGeometry, "Skirt top to CoM b_p", "m", "mm", kMm, Between(-0.2, 0.2),
                      "+ toward the crank; Table I: −1.737 mm (CoM above the skirt top)"}));
  f.push_back(Scalar("geometry.liner_radius", geo, &CG::liner_radius,
                     {G::kGeometry, "Liner (bore) radius R_l", "m", "mm", kMm, Length(),
                      "> skirt.cold_clearance; the gas force acts on π R_l²; Table I: 36.50 mm"}));
  f.push_back(
      Scalar("geometry.compression_ratio", geo, &CG::compression_ratio,
             {G::kOperating, "Compression ratio (synthetic pressure model)", "-", "–", 1.0,
              Open(1.0, 40.0, true, false), "used only by the synthetic cylinder-pressure model"}));
  f.push_back(Scalar("geometry.gravity", geo, &CG::gravity,
                     {G::kGeometry, "Gravity g", "m/s^2", "m/s²", 1.0, Between(0.0, 100.0),
                      "along −Y (cylinder axis vertical, head up)"}));
  // Skirt–liner joint.
  f.push_back(Model("skirt.model", sk, &S::model,
                    {G::kSkirt,
                     "Skirt joint model",
                     "",
                     "",
                     1.0,
                     {},
                     "\"ideal\" (prismatic joint) or \"lubricated\" (mixed-lubrication film)"}));
  f.push_back(Scalar("skirt.cold_clearance", sk, &S::cold_clearance,
                     {G::kSkirt, "Cold skirt clearance c (radial)", "m", "µm", kUm, Clearance(),
                      "< liner_radius; piston radius R = R_l − c; Table I: 25 µm "
                      "(R_l − R = 36.50 − 36.475 mm)"}));
  f.push_back(
      Scalar("skirt.length", sk, &S::length,
             {G::kSkirt, "Skirt length L_skirt", "m", "mm", kMm, Length(), "Table I: 28 mm"}));
  f.push_back(Scalar("skirt.thrust_half_width", sk, &S::thrust_half_width,
                     {G::kSkirt, "Thrust panel half-width α₁", "rad", "°", kRadiansPerDegree,
                      Open(0.0, kPi / 2, true, false),
                      "half-width of the thrust panel; α₁ + α₂ < π; Table I: 46°"}));
  f.push_back(Scalar("skirt.anti_thrust_half_width", sk, &S::anti_thrust_half_width,
                     {G::kSkirt, "Anti-thrust panel half-width α₂", "rad", "°", kRadiansPerDegree,
                      Open(0.0, kPi / 2, true, false),
                      "half-width of the anti-thrust panel; the relief lies between α₁ and "
                      "π − α₂; Table I: 46°"}));
  f.push_back(Scalar("skirt.roughness_skirt", sk, &S::roughness_skirt,
                     {G::kSkirt, "Skirt roughness σ_skirt", "m", "µm", kUm, Roughness(),
                      "RMS roughness; Table I: 0.615 µm"}));
  f.push_back(Scalar("skirt.roughness_liner", sk, &S::roughness_liner,
                     {G::kSkirt, "Liner roughness σ_liner", "m", "µm", kUm, Roughness(),
                      "RMS roughness; Table I: 0.815 µm"}));
  f.push_back(Scalar("skirt.peklenik", sk, &S::peklenik,
                     {G::kSkirt, "Peklenik number γ", "-", "–", 1.0, Between(1.0 / 9.0, 9.0),
                      "surface pattern of the composite roughness (1 = isotropic)"}));
  f.push_back(Scalar("skirt.modulus_skirt", sk, &S::modulus_skirt,
                     {G::kSkirt, "Skirt Young's modulus E_skirt", "Pa", "GPa", kGPa,
                      YoungsModulus(), "of the piston skirt (Al-Si alloy: 75 GPa)"}));
  f.push_back(Scalar("skirt.poisson_skirt", sk, &S::poisson_skirt,
                     {G::kSkirt, "Skirt Poisson ratio ν_skirt", "-", "–", 1.0, PoissonRatio(),
                      "of the piston skirt"}));
  f.push_back(
      Scalar("skirt.modulus_liner", sk, &S::modulus_liner,
             {G::kSkirt, "Liner Young's modulus E_liner", "Pa", "GPa", kGPa, YoungsModulus(),
              "of the liner (grey cast iron: 110 GPa); with the skirt's forms E'"}));
  f.push_back(Scalar(
      "skirt.poisson_liner", sk, &S::poisson_liner,
      {G::kSkirt, "Liner Poisson ratio ν_liner", "-", "–", 1.0, PoissonRatio(), "of the liner"}));
  {
    using lubrication::ComplianceModel;
    f.push_back(
        Choice("skirt.compliance", sk, &S::compliance,
               {ToString(ComplianceModel::kRigid), ToString(ComplianceModel::kElasticLayer),
                ToString(ComplianceModel::kHalfSpace), ToString(ComplianceModel::kImported)},
               {G::kSkirt,
                "Surface compliance",
                "",
                "",
                1.0,
                {},
                "\"rigid\" (the paper's), \"elastic_layer\" (the skirt's surface on a "
                "rigid body), \"half_space\" (skirt and liner) or \"imported\" (a "
                "finite-element compliance file)"}));
  }
  f.push_back(Scalar("skirt.layer_thickness", sk, &S::layer_thickness,
                     {G::kSkirt, "Surface layer thickness (elastic layer)", "m", "mm", kMm,
                      Open(0.0, 1.0, true, false), "of the skirt's deforming surface layer"}));
  f.push_back(Text("skirt.compliance_file", sk, &S::compliance_file,
                   {G::kSkirt,
                    "Compliance file (imported)",
                    "",
                    "",
                    1.0,
                    {},
                    "Matrix Market file beside the case; nodes in <name>.nodes.csv"}));
  f.push_back(Scalar("skirt.boundary_friction", sk, &S::boundary_friction,
                     {G::kSkirt, "Boundary friction μ_f", "-", "–", 1.0, Between(0.0, 1.0),
                      "friction coefficient of asperity contact; Table I: 0.13"}));
  f.push_back(Cavitation("skirt.cavitation", sk, &S::cavitation, G::kSkirt));
  f.push_back(Choice(
      "skirt.supply", sk, &S::supply,
      {ToString(lubrication::SkirtSupply::kFlooded), ToString(lubrication::SkirtSupply::kStarved)},
      {G::kSkirt,
       "Oil supply",
       "",
       "",
       1.0,
       {},
       "\"flooded\" (the paper's) or \"starved\" (from the liner's oil film; "
       "needs cavitation \"jfo\")"}));
  f.push_back(Scalar("skirt.oil_film", sk, &S::oil_film,
                     {G::kSkirt, "Oil film on the liner h_oil", "m", "µm", kUm, LinerOilFilm(),
                      "starved supply: the oil layer the ring pack leaves on the liner"}));
  f.push_back(List("skirt.oil_film_positions", sk, &S::oil_film_positions,
                   {G::kSkirt, "Liner oil film: position", "m", "mm", kMm, Between(-1.0, 100.0),
                    "liner positions from the skirt top at top dead centre, + toward the crank; "
                    "outside the table its end values hold (empty: the constant oil_film)"}));
  f.push_back(List("skirt.oil_film_values", sk, &S::oil_film_values,
                   {G::kSkirt, "Liner oil film: thickness", "m", "µm", kUm, LinerOilFilm(),
                    "the oil film at each position"}));
  AddJointOilFields(f, "skirt", sk, G::kSkirt, SkirtOil);
  AddTemperatureField(f, "skirt.piston_temperature", sk, &S::piston_temperature, G::kSkirt,
                      "Piston skirt temperature", "skirt piston T",
                      "Running temperature of the piston skirt: with its expansion coefficient "
                      "it sets the hot piston radius and so the running clearance.");
  AddTemperatureField(f, "skirt.liner_temperature", sk, &S::liner_temperature, G::kSkirt,
                      "Liner temperature", "liner T",
                      "Running temperature of the cylinder liner: with its expansion "
                      "coefficient it sets the hot bore radius and so the running clearance.");
  f.push_back(Scalar("skirt.piston_expansion", sk, &S::piston_expansion,
                     {G::kSkirt, "Piston expansion coefficient", "1/K", "1e-6/K", 1e-6,
                      Between(0.0, 1e-4), "linear; Al–Si piston alloys about 20–22e-6/K"}));
  f.push_back(Scalar("skirt.liner_expansion", sk, &S::liner_expansion,
                     {G::kSkirt, "Liner expansion coefficient", "1/K", "1e-6/K", 1e-6,
                      Between(0.0, 1e-4), "linear; grey cast iron about 10–12e-6/K"}));
  f.push_back(Scalar("skirt.mesh_thrust", sk, &S::mesh_thrust,
                     {G::kSolver, "Skirt mesh: elements over Ω₁ (thrust)", "-", "–", 1.0,
                      Between(2, 2000), "circumferential elements of the thrust panel"}));
  f.push_back(Scalar("skirt.mesh_relief", sk, &S::mesh_relief,
                     {G::kSolver, "Skirt mesh: elements over Ω₂ (relief)", "-", "–", 1.0,
                      Between(1, 2000), "circumferential elements of the pin-boss relief"}));
  f.push_back(Scalar("skirt.mesh_anti", sk, &S::mesh_anti,
                     {G::kSolver, "Skirt mesh: elements over Ω₃ (anti-thrust)", "-", "–", 1.0,
                      Between(2, 2000), "circumferential elements of the anti-thrust panel"}));
  f.push_back(Scalar("skirt.mesh_axial", sk, &S::mesh_axial,
                     {G::kSolver, "Skirt mesh: elements axially", "-", "–", 1.0, Between(2, 2000),
                      "elements along the skirt (Table II: 30, 2, 30 × 40)"}));
  f.push_back(List("skirt.profile_y", sk, &S::profile_y,
                   {G::kSkirt, "Skirt profile: axial position y", "m", "mm", kMm, Offset(),
                    "from the skirt top, strictly increasing, within the skirt; same length as "
                    "profile_h (≥ 2)"}));
  f.push_back(List("skirt.profile_h", sk, &S::profile_h,
                   {G::kSkirt, "Skirt profile: radial drop h", "m", "µm", kUm, Gap(),
                    "barrel profile: extra radial gap at y, linear between rows"}));
  f.push_back(
      List("skirt.ovality_alpha", sk, &S::ovality_alpha,
           {G::kSkirt, "Skirt ovality: angle α", "rad", "°", kRadiansPerDegree, Between(0.0, kPi),
            "from the thrust axis, strictly increasing; empty with ovality_h = round"}));
  f.push_back(List("skirt.ovality_h", sk, &S::ovality_h,
                   {G::kSkirt, "Skirt ovality: extra gap h", "m", "µm", kUm, Gap(),
                    "extra radial gap at α, linear between rows, constant beyond the ends"}));
  // Big-end bearing.
  f.push_back(Model("big_end.model", be, &B::model,
                    {G::kBigEnd,
                     "Big-end joint model",
                     "",
                     "",
                     1.0,
                     {},
                     "\"ideal\" (revolute joint) or \"lubricated\" (mixed-lubrication film)"}));
  f.push_back(Scalar("big_end.bearing_radius", be, &B::bearing_radius,
                     {G::kBigEnd, "Bearing radius R_b", "m", "mm", kMm, Length(),
                      "bore of the rod's big end; Table I: 15.00 mm"}));
  f.push_back(Scalar("big_end.journal_radius", be, &B::journal_radius,
                     {G::kBigEnd, "Journal radius R_j", "m", "mm", kMm, Length(),
                      "< bearing_radius; R_b − R_j = 50 µm radial (Table I's c_b = 0.1 mm is "
                      "diametral)"}));
  f.push_back(Scalar("big_end.width", be, &B::width,
                     {G::kBigEnd, "Bearing width b", "m", "mm", kMm, Length(), "Table I: 22 mm"}));
  f.push_back(Scalar("big_end.roughness_journal", be, &B::roughness_journal,
                     {G::kBigEnd, "Journal roughness σ_j", "m", "µm", kUm, Roughness(),
                      "RMS roughness; Table I: 0.308 µm"}));
  f.push_back(Scalar("big_end.roughness_bearing", be, &B::roughness_bearing,
                     {G::kBigEnd, "Bearing roughness σ_b", "m", "µm", kUm, Roughness(),
                      "RMS roughness; Table I: 0.408 µm"}));
  f.push_back(Scalar("big_end.peklenik", be, &B::peklenik,
                     {G::kBigEnd, "Peklenik number γ", "-", "–", 1.0, Between(1.0 / 9.0, 9.0),
                      "surface pattern of the composite roughness (1 = isotropic)"}));
  f.push_back(Scalar("big_end.modulus_journal", be, &B::modulus_journal,
                     {G::kBigEnd, "Journal Young's modulus E_j", "Pa", "GPa", kGPa, YoungsModulus(),
                      "of the crank-pin journal (steel: 210 GPa)"}));
  f.push_back(Scalar(
      "big_end.poisson_journal", be, &B::poisson_journal,
      {G::kBigEnd, "Journal Poisson ratio ν_j", "-", "–", 1.0, PoissonRatio(), "of the journal"}));
  f.push_back(Scalar("big_end.modulus_bearing", be, &B::modulus_bearing,
                     {G::kBigEnd, "Bearing Young's modulus E_b", "Pa", "GPa", kGPa, YoungsModulus(),
                      "of the bearing lining (Al-Sn: 70 GPa); with the journal's forms E'"}));
  f.push_back(Scalar("big_end.poisson_bearing", be, &B::poisson_bearing,
                     {G::kBigEnd, "Bearing Poisson ratio ν_b", "-", "–", 1.0, PoissonRatio(),
                      "of the bearing lining"}));
  f.push_back(Scalar("big_end.boundary_friction", be, &B::boundary_friction,
                     {G::kBigEnd, "Boundary friction μ_f", "-", "–", 1.0, Between(0.0, 1.0),
                      "friction coefficient of asperity contact; Table I: 0.13"}));
  f.push_back(Cavitation("big_end.cavitation", be, &B::cavitation, G::kBigEnd));
  f.push_back(Scalar("big_end.mesh_theta", be, &B::mesh_theta,
                     {G::kSolver, "Big-end mesh: elements around 360°", "-", "–", 1.0,
                      Between(8, 5000), "circumferential elements (Table II: 50)"}));
  f.push_back(Scalar(
      "big_end.mesh_theta_grading", be, &B::mesh_theta_grading,
      {G::kSolver, "Big-end mesh: circumferential grading", "-", "–", 1.0, Between(1.0, 100.0),
       "largest / smallest element around, the finest at the minimum film "
       "(1 = uniform, the paper's)"}));
  f.push_back(Scalar("big_end.mesh_z", be, &B::mesh_z,
                     {G::kSolver, "Big-end mesh: elements across the width", "-", "–", 1.0,
                      Between(2, 2000), "axial elements (Table II: 10)"}));
  f.push_back(Scalar("big_end.mesh_z_grading", be, &B::mesh_z_grading,
                     {G::kSolver, "Big-end mesh: axial grading", "-", "–", 1.0, Between(1.0, 100.0),
                      "largest (mid-plane) / smallest (edges) element across the width (1 = "
                      "uniform, the paper's)"}));
  {
    using lubrication::OilFeedKind;
    f.push_back(Choice("big_end.supply", be, &B::supply,
                       {ToString(OilFeedKind::kLineOfCentres), ToString(OilFeedKind::kShellHoles),
                        ToString(OilFeedKind::kPinHoles), ToString(OilFeedKind::kGroove),
                        ToString(OilFeedKind::kPinHolesAndGroove)},
                       {G::kBigEnd,
                        "Oil supply",
                        "",
                        "",
                        1.0,
                        {},
                        "\"line_of_centres\" (the film starts at the line of centres, the "
                        "paper's), \"shell_holes\", \"pin_holes\", \"groove\" or "
                        "\"pin_holes_and_groove\" (both, at the one supply pressure)"}));
  }
  {
    using lubrication::ComplianceModel;
    f.push_back(
        Choice("big_end.compliance", be, &B::compliance,
               {ToString(ComplianceModel::kRigid), ToString(ComplianceModel::kElasticLayer),
                ToString(ComplianceModel::kHalfSpace), ToString(ComplianceModel::kImported)},
               {G::kBigEnd,
                "Surface compliance",
                "",
                "",
                1.0,
                {},
                "\"rigid\" (the paper's), \"elastic_layer\" (the lining on a rigid "
                "backing), \"half_space\" (journal and bearing) or \"imported\" (a finite-element "
                "compliance file)"}));
  }
  f.push_back(Scalar("big_end.layer_thickness", be, &B::layer_thickness,
                     {G::kBigEnd, "Lining thickness (elastic layer)", "m", "mm", kMm,
                      Open(0.0, 1.0, true, false), "of the bearing lining on its rigid backing"}));
  f.push_back(Text("big_end.compliance_file", be, &B::compliance_file,
                   {G::kBigEnd,
                    "Compliance file (imported)",
                    "",
                    "",
                    1.0,
                    {},
                    "Matrix Market file beside the case; nodes in <name>.nodes.csv"}));
  f.push_back(Scalar("big_end.oil_feed_pressure", be, &B::oil_feed_pressure,
                     {G::kBigEnd, "Oil-supply pressure (gauge)", "Pa", "MPa", kMPa, GaugePressure(),
                      "at the holes or groove (constant; see supply_pressure_* for a curve)"}));
  f.push_back(List("big_end.supply_pressure_angles", be, &B::supply_pressure_angles,
                   {G::kBigEnd, "Supply pressure curve: crank angle", "rad", "°CA",
                    kRadiansPerDegree, Open(0.0, 4.0 * kPi, false, true),
                    "crank angles of the supply-pressure curve (empty: constant pressure): at "
                    "least 8, increasing, covering the cycle with gaps of at most 10 °CA "
                    "(counting the one from the last round to the first)"}));
  f.push_back(List("big_end.supply_pressure_values", be, &B::supply_pressure_values,
                   {G::kBigEnd, "Supply pressure curve: gauge pressure", "Pa", "MPa", kMPa,
                    GaugePressure(), "the supply pressure at each angle"}));
  f.push_back(List("big_end.supply_hole_angles", be, &B::supply_hole_angles,
                   {G::kBigEnd, "Supply holes: angles", "rad", "°", kRadiansPerDegree,
                    Between(-2.0 * kPi, 2.0 * kPi),
                    "shell holes from the rod axis toward the small end, pin holes from the crank "
                    "web axis, counter-clockwise"}));
  f.push_back(
      Scalar("big_end.supply_hole_diameter", be, &B::supply_hole_diameter,
             {G::kBigEnd, "Supply holes: diameter", "m", "mm", kMm, Open(0.0, 1.0, true, false),
              "of each hole; less than the bearing width and than half its circumference"}));
  f.push_back(Scalar("big_end.groove_start_angle", be, &B::groove_start_angle,
                     {G::kBigEnd, "Groove: start angle", "rad", "°", kRadiansPerDegree,
                      Between(-2.0 * kPi, 2.0 * kPi),
                      "from the rod axis toward the small end, counter-clockwise"}));
  f.push_back(Scalar("big_end.groove_end_angle", be, &B::groove_end_angle,
                     {G::kBigEnd, "Groove: end angle", "rad", "°", kRadiansPerDegree,
                      Between(-2.0 * kPi, 4.0 * kPi),
                      "after the start angle by at most 360° (a whole-circle groove)"}));
  f.push_back(
      Scalar("big_end.groove_width", be, &B::groove_width,
             {G::kBigEnd, "Groove: axial width", "m", "mm", kMm, Open(0.0, 1.0, true, false),
              "centred on the bearing's mid-width; less than the bearing width"}));
  AddJointOilFields(f, "big_end", be, G::kBigEnd, BigEndOil);
  AddTemperatureField(f, "big_end.journal_temperature", be, &B::journal_temperature, G::kBigEnd,
                      "Journal temperature", "journal T",
                      "Running temperature of the crank-pin journal: with its expansion "
                      "coefficient it sets the hot journal radius and so the running clearance.");
  AddTemperatureField(f, "big_end.bearing_temperature", be, &B::bearing_temperature, G::kBigEnd,
                      "Bearing temperature", "bearing T",
                      "Running temperature of the bearing (rod eye and shell): with its "
                      "expansion coefficient it sets the hot bearing radius.");
  f.push_back(Scalar("big_end.journal_expansion", be, &B::journal_expansion,
                     {G::kBigEnd, "Journal expansion coefficient", "1/K", "1e-6/K", 1e-6,
                      Between(0.0, 1e-4), "linear; steel about 11–13e-6/K"}));
  f.push_back(Scalar(
      "big_end.bearing_expansion", be, &B::bearing_expansion,
      {G::kBigEnd, "Bearing expansion coefficient", "1/K", "1e-6/K", 1e-6, Between(0.0, 1e-4),
       "linear; the rod eye's: steel about 11–13e-6/K, aluminium about 23e-6/K"}));
  AddOilFields(f, "lubricant.", G::kLubricant, LubricantOil,
               "(the case's oil, both joints' unless a joint has its own).", "");
  AddTemperatureField(f, "lubricant.supply_temperature", lub, &LubricantCase::supply_temperature,
                      G::kLubricant, "Oil supply temperature", "supply T",
                      "Temperature of the oil fed to the joints: where a joint's film "
                      "temperature comes from its heat balance, the film heats up from it.");
  f.push_back(Scalar(
      "lubricant.density", lub, &LubricantCase::density,
      {G::kLubricant, "Oil density ρ", "kg/m^3", "kg/m³", 1.0, Open(0.0, 5000.0, true, false),
       "for the heat balance; engine oils 840–880 kg/m³ at 15 °C"}));
  f.push_back(Scalar("lubricant.heat_capacity", lub, &LubricantCase::heat_capacity,
                     {G::kLubricant, "Oil specific heat c_p", "J/(kg*K)", "J/(kg·K)", 1.0,
                      Open(0.0, 1e5, true, false),
                      "for the heat balance; mineral oils about 1 900–2 100 J/(kg·K)"}));
  f.push_back(Scalar(
      "lubricant.greenwood_tripp_k", lub, &LubricantCase::greenwood_tripp_k,
      {G::kLubricant, "Greenwood–Tripp constant K", "-", "–", 1.0, Open(0.0, 1.0, true, false),
       "Greenwood–Tripp asperity contact pressure K·E'·F_5/2: 1.198e-4"}));
  f.push_back(Scalar("operating.rpm", op, &OperatingCase::rpm,
                     {G::kOperating, "Crank speed", "rpm", "rpm", 1.0,
                      Open(0.0, 30000.0, true, false), "imposed crank speed"}));
  f.push_back(Scalar("operating.crankcase_pressure", op, &OperatingCase::crankcase_pressure,
                     {G::kOperating, "Crankcase pressure (absolute)", "Pa", "MPa", kMPa,
                      GaugePressure(), "acts under the crown: gas force (p − p_cc) π R_l²"}));
  f.push_back(Scalar(
      "operating.start_crank_angle", op, &OperatingCase::start_crank_angle,
      {G::kOperating, "Start crank angle", "rad", "°CA", kRadiansPerDegree, Between(0.0, 4 * kPi),
       "where the first monitored cycle starts (a run-in starts before it)"}));
  f.push_back(
      Scalar("solver.baumgarte_alpha", sol, &SolverCase::baumgarte_alpha,
             {G::kSolver, "Baumgarte velocity feedback G", "1/s", "1/s", 1.0, Between(0.0, 1e9),
              "constraint stabilisation, the term −2G·Φ̇ of eq. 39 (the paper's script "
              "G); Table II: 1e4"}));
  f.push_back(
      Scalar("solver.baumgarte_beta", sol, &SolverCase::baumgarte_beta,
             {G::kSolver, "Baumgarte position feedback ζ", "1/s", "1/s", 1.0, Between(0.0, 1e9),
              "constraint stabilisation, the term −ζ²·Φ of eq. 39; Table II: 1e4"}));
  f.push_back(Scalar("solver.relative_tolerance", sol, &SolverCase::relative_tolerance,
                     {G::kSolver, "Relative tolerance", "-", "–", 1.0, Between(1e-14, 1e-2),
                      "local error of the implicit integrator's velocities, relative (positions: "
                      "absolute)"}));
  f.push_back(
      Scalar("solver.position_tolerance", sol, &SolverCase::position_tolerance,
             {G::kSolver, "Absolute position tolerance", "m", "µm", kUm, Between(1e-16, 1e-3),
              "absolute local error of positions (angles ×10 rad/m, velocities scaled: "
              "docs/performance.md)"}));
  f.push_back(Scalar("solver.output_interval", sol, &SolverCase::output_interval,
                     {G::kSolver, "Output interval", "rad", "°CA", kRadiansPerDegree,
                      Between(1e-4, 0.2), "crank angle between output steps (1 °CA)"}));
  f.push_back(
      Scalar("solver.steady_state_tolerance", sol, &SolverCase::steady_state_tolerance,
             {G::kSolver, "Steady-state tolerance", "-", "–", 1.0, Open(0.0, 1.0, true, false),
              "cycle-to-cycle change of each monitored quantity, relative to its range"}));
  f.push_back(Scalar("solver.max_cycles", sol, &SolverCase::max_cycles,
                     {G::kSolver, "Maximum cycles", "-", "–", 1.0, Between(1, 10000),
                      "cycles before a run stops as not converged"}));
  f.push_back(Scalar(
      "solver.run_in_angle", sol, &SolverCase::run_in_angle,
      {G::kSolver, "Run-in before the first cycle", "rad", "°CA", kRadiansPerDegree,
       Between(0.0, 8 * kPi),
       "integrated at 10× looser tolerances before the first monitored cycle; below 1e-9 rad, "
       "none"}));
  f.push_back(Scalar(
      "solver.jfo_run_in_angle", sol, &SolverCase::jfo_run_in_angle,
      {G::kSolver, "Run-in with a mass-conserving film", "rad", "°CA", kRadiansPerDegree,
       Between(0.0, 8 * kPi),
       "instead of the run-in above when a lubricated film is JFO: its oil "
       "content drains from the flooded start over about two cycles; below 1e-9 rad, none"}));
  f.push_back(
      Scalar("solver.error_estimate", sol, &SolverCase::error_estimate,
             {G::kSolver, "Discretisation-error estimate (1 = on)", "-", "–", 1.0, Between(0, 1),
              "1: a companion run on meshes with half the elements estimates the error "
              "of the headline figures; 0: off"}));
  SetSymbols(f);
  SetDescriptions(f);
  return f;
}

// "1 value", "3 values": a list's length in an error.
std::string Values(std::size_t n) { return std::to_string(n) + (n == 1 ? " value" : " values"); }

}  // namespace

std::string FieldGroupTitle(FieldGroup group) {
  switch (group) {
    case FieldGroup::kCase:
      return "Case";
    case FieldGroup::kGeometry:
      return "Geometry";
    case FieldGroup::kMasses:
      return "Masses and inertias";
    case FieldGroup::kSkirt:
      return "Piston skirt";
    case FieldGroup::kBigEnd:
      return "Big-end bearing";
    case FieldGroup::kLubricant:
      return "Lubricant";
    case FieldGroup::kOperating:
      return "Operating point";
    case FieldGroup::kSolver:
      return "Solver";
  }
  return {};
}

void CaseField::Check(double value, const std::string& field) const {
  const std::string& name = field.empty() ? path : field;
  const FieldRange& r = range;
  if (kind == FieldKind::kInteger) {
    if (!std::isfinite(value) || value != std::floor(value) || value < r.lo || value > r.hi) {
      throw InputError(name, FormatValue(value),
                       "must be an integer in [" + std::to_string(static_cast<long>(r.lo)) + ", " +
                           std::to_string(static_cast<long>(r.hi)) + "]");
    }
    return;
  }
  if (r.lo == -kInf && r.hi == kInf) {
    RequireFinite(name, value, unit);
  } else if (r.hi == kInf && r.lo == 0.0) {
    r.lo_open ? RequirePositive(name, value, unit) : RequireNonNegative(name, value, unit);
  } else {
    RequireInRange(name, value, r.lo, r.hi, r.lo_open, r.hi_open, unit);
  }
}

bool CaseField::SameListTable(const CaseField& other) const {
  if (&other == this) return true;
  return kind == FieldKind::kNumberList && other.kind == FieldKind::kNumberList &&
         !symbol.empty() && group == other.group && symbol == other.symbol;
}

bool CaseField::SameValue(const EngineCase& a, const EngineCase& b, double relative) const {
  auto same = [relative](double x, double y) {
    return x == y || (std::isnan(x) && std::isnan(y)) ||
           std::abs(x - y) <= relative * std::max(std::abs(x), std::abs(y));
  };
  // The list and text accessors take a mutable case to locate the member; nothing is changed.
  auto& ma = const_cast<EngineCase&>(a);
  auto& mb = const_cast<EngineCase&>(b);
  switch (kind) {
    case FieldKind::kNumber:
    case FieldKind::kInteger:
      return get && same(get(a), get(b));
    case FieldKind::kNumberList: {
      if (!list) return false;
      const std::vector<double>& x = list(ma);
      const std::vector<double>& y = list(mb);
      return std::equal(x.begin(), x.end(), y.begin(), y.end(), same);
    }
    case FieldKind::kText:
      return text && text(ma) == text(mb);
    case FieldKind::kChoice:
      return choice && choice(a) == choice(b);
  }
  return false;
}

bool CaseField::Allows(double si_value) const {
  try {
    Check(si_value);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

std::string CaseField::AllowedText() const {
  try {
    Check(std::numeric_limits<double>::quiet_NaN());  // refused by every number field's check
  } catch (const InputError& e) {
    return e.allowed();
  }
  return "must be a finite number";
}

std::string CaseField::RangeText() const {
  switch (kind) {
    case FieldKind::kText:
      return "text";
    case FieldKind::kChoice:
      return ChoicesText();
    case FieldKind::kInteger:
      return "integer in [" + std::to_string(static_cast<long>(range.lo)) + ", " +
             std::to_string(static_cast<long>(range.hi)) + "]";
    case FieldKind::kNumber:
    case FieldKind::kNumberList:
      break;
  }
  std::string text;
  if (range.lo == -kInf && range.hi == kInf) {
    text = "finite";
  } else if (range.hi == kInf) {
    text = (range.lo_open ? "> " : "≥ ") + FormatBound(range.lo, false, range.lo_open);
  } else {
    text = std::string(range.lo_open ? "(" : "[") + FormatBound(range.lo, false, range.lo_open) +
           ", " + FormatBound(range.hi, true, range.hi_open) + (range.hi_open ? ")" : "]");
  }
  return kind == FieldKind::kNumberList ? "each " + text : text;
}

const std::vector<CaseField>& CaseSchema() {
  static const std::vector<CaseField> schema = MakeSchema();
  return schema;
}

const CaseField* FindCaseField(std::string_view path) {
  for (const CaseField& f : CaseSchema()) {
    if (f.path == path) return &f;
  }
  return nullptr;
}

namespace {
// Edits (insertions, deletions, substitutions, swaps of neighbours) from a to b.
std::size_t EditDistance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

std::string_view LastName(std::string_view path) {
  const std::size_t dot = path.rfind('.');
  return dot == std::string_view::npos ? path : path.substr(dot + 1);
}
}  // namespace

std::string SimilarFieldsText(std::string_view path) {
  if (path.empty() || FindCaseField(path) != nullptr) return {};
  std::vector<std::string> near;
  std::size_t best = 3;
  for (const CaseField& f : CaseSchema()) {
    std::size_t d = EditDistance(path, f.path);
    if (d > 2 || 3 * d > f.path.size()) d = 3;
    // The same name in another section counts as one slip.
    if (d == 3 && LastName(path) == LastName(f.path)) d = 1;
    if (d > best) continue;
    if (d < best) near.clear();
    best = d;
    near.push_back(f.path);
  }
  if (near.empty() || near.size() > 3) return {};
  std::string text = "; did you mean ";
  for (std::size_t k = 0; k < near.size(); ++k)
    text += (k == 0 ? "" : k + 1 == near.size() ? " or " : ", ") + near[k];
  return text + "?";
}

const CaseField* FieldOfPath(std::string_view path) {
  if (const CaseField* field = FindCaseField(path)) return field;
  const std::size_t dot = path.rfind('.');
  if (dot == std::string_view::npos) return nullptr;
  const CaseField* list = FindCaseField(path.substr(0, dot));
  return list && list->kind == FieldKind::kNumberList ? list : nullptr;
}

std::vector<const CaseField*> FieldsSetWith(const CaseField& field) {
  std::vector<const CaseField*> fields;
  for (const CaseField& f : CaseSchema()) {
    if (field.SameListTable(f)) fields.push_back(&f);
  }
  return fields;
}

namespace {
// 1/scale where it is an integer (a unit that is an integer fraction of SI); 0 otherwise.
double IntegerInverse(double scale) {
  if (!(scale > 0.0 && scale < 1.0)) return 0.0;
  const double inverse = std::round(1.0 / scale);
  return std::abs(inverse * scale - 1.0) <= 1e-12 ? inverse : 0.0;
}
}  // namespace

double ScaleToDisplay(double si, double scale) {
  const double inverse = IntegerInverse(scale);
  return inverse != 0.0 ? si * inverse : si / scale;
}

double ScaleFromDisplay(double display, double scale) {
  const double inverse = IntegerInverse(scale);
  return inverse != 0.0 ? display / inverse : display * scale;
}

double CaseField::ToDisplay(double si) const {
  return ScaleToDisplay(si - display_offset, display_scale);
}

double CaseField::FromDisplay(double display) const {
  return ScaleFromDisplay(display, display_scale) + display_offset;
}

const std::string& CaseField::ChoiceName(const EngineCase& c) const {
  return choices.at(static_cast<std::size_t>(choice(c)));
}

std::string CaseField::ChoiceTitle(std::size_t k) const {
  // One table for every choice field: the names mean the same wherever they appear.
  static const std::map<std::string, std::string, std::less<>> kTitles = {
      {"reynolds", "Reynolds (Swift–Stieber)"},
      {"jfo", "JFO (mass-conserving)"},
      {"starved", "starved (liner oil film)"},
      {"elastic_layer", "elastic layer"},
      {"half_space", "elastic half-spaces"},
      {"imported", "imported (finite elements)"},
      {"line_of_centres", "film start at the line of centres"},
      {"shell_holes", "holes in the shell"},
      {"pin_holes", "holes in the crank pin"},
      {"groove", "groove in the shell"},
      {"pin_holes_and_groove", "crank-pin holes and groove"},
      {"lubricant", "the case's lubricant"},
      {"own", "its own oil"},
      {"heat_balance", "heat balance"},
      {"vogel", "Vogel's law (temperature)"},
      {"grade", "catalogue oil (SAE grade)"},
      {"barus", "Barus"},
      {"roelands", "Roelands"},
      {"cross", "Cross (critical shear rate)"},
      {"hths", "Cross, from the HTHS viscosity"},
      {"linear", "linear (constant β)"},
      {"dowson_higginson", "Dowson–Higginson"},
  };
  const std::string& name = choices.at(k);
  if (const auto it = kTitles.find(name); it != kTitles.end()) return it->second;
  for (const lubrication::OilGrade& g : lubrication::OilCatalogue()) {
    if (g.key == name) {  // an SAE grade as it is written: "0W-20"
      std::string title = name;
      for (char& ch : title) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
      return title;
    }
  }
  return name;
}

int CaseField::ChoiceIndex(std::string_view text) const {
  for (std::size_t k = 0; k < choices.size(); ++k) {
    if (choices[k] == text || ChoiceTitle(k) == text) return static_cast<int>(k);
  }
  return -1;
}

std::string CaseField::ChoicesText(bool prose) const {
  std::string text;
  for (std::size_t k = 0; k < choices.size(); ++k) {
    if (k > 0) text += !prose ? " | " : (k + 1 == choices.size() ? " or " : ", ");
    text += "\"" + choices[k] + "\"";
  }
  return text;
}

void CaseField::SetChoice(EngineCase& c, const std::string& name) const {
  for (std::size_t k = 0; k < choices.size(); ++k) {
    if (choices[k] == name) {
      set_choice(c, static_cast<int>(k));
      return;
    }
  }
  throw InputError(path, name, "must be " + ChoicesText(true));
}

const char* JointModelName(JointModel model) {
  return model == JointModel::kIdeal ? "ideal" : "lubricated";
}

namespace {

// The big end's oil supply: a pressure needs somewhere to act, holes may not overlap or exceed
// the width, a groove spans at most a circle, a pressure curve is a proper periodic curve.
void CheckBigEndSupply(const BigEndCase& b) {
  using lubrication::OilFeedKind;
  const bool curve = !b.supply_pressure_angles.empty() || !b.supply_pressure_values.empty();
  if (b.supply == OilFeedKind::kLineOfCentres && (b.oil_feed_pressure > 0.0 || curve)) {
    throw InputError("big_end.supply", "\"line_of_centres\"",
                     "has no supply for the given pressure (big_end.oil_feed_pressure or the "
                     "supply-pressure curve): choose \"shell_holes\", \"pin_holes\", "
                     "\"groove\" or \"pin_holes_and_groove\"");
  }
  if (curve) {
    if (b.supply_pressure_angles.size() != b.supply_pressure_values.size()) {
      throw InputError("big_end.supply_pressure_values", Values(b.supply_pressure_values.size()),
                       "needs as many values as big_end.supply_pressure_angles (" +
                           std::to_string(b.supply_pressure_angles.size()) + ")");
    }
    // The cylinder-pressure curves' rules (increasing angles, no gap above 10 °CA, finite),
    // named as the two lists are given.
    CurveFields fields;
    fields.curve = "big_end.supply_pressure_angles";
    fields.point = [](std::size_t k, bool angle) {
      return std::string(angle ? "big_end.supply_pressure_angles."
                               : "big_end.supply_pressure_values.") +
             std::to_string(k);
    };
    fields.angles_in_radians = true;
    PressureCurve(b.supply_pressure_angles, b.supply_pressure_values, fields);
  }
  lubrication::OilFeed feed;
  feed.kind = b.supply;
  feed.hole_angles = b.supply_hole_angles;
  feed.hole_diameter = b.supply_hole_diameter;
  feed.groove_start = b.groove_start_angle;
  feed.groove_end = b.groove_end_angle;
  feed.groove_width = b.groove_width;
  lubrication::ValidateOilFeed(feed, b.bearing_radius, b.width,
                               {.hole_angles = "big_end.supply_hole_angles",
                                .hole_diameter = "big_end.supply_hole_diameter",
                                .groove_start = "big_end.groove_start_angle",
                                .groove_end = "big_end.groove_end_angle",
                                .groove_width = "big_end.groove_width",
                                .width = "big_end.width"});
}

// A starved skirt needs the film fraction of the mass-conserving model and a proper table: one
// that reaches the liner the skirt's leading edge runs over, from the skirt top at top dead
// centre (0) to its bottom at bottom dead centre (`liner` [m]); outside the table its end values
// hold, so a table wholly beside that (a unit slip) would set one constant film.
void CheckSkirtSupply(const SkirtCase& s, double liner) {
  if (s.supply == lubrication::SkirtSupply::kStarved &&
      s.cavitation != lubrication::CavitationModel::kJfo) {
    throw InputError("skirt.supply", "\"starved\"",
                     "needs skirt.cavitation = \"jfo\": the Reynolds condition tracks no "
                     "partial film");
  }
  const auto& x = s.oil_film_positions;
  if (x.size() != s.oil_film_values.size()) {
    throw InputError("skirt.oil_film_values", Values(s.oil_film_values.size()),
                     "needs as many values as skirt.oil_film_positions (" +
                         std::to_string(x.size()) + "; both empty = the constant oil_film)");
  }
  for (std::size_t k = 1; k < x.size(); ++k) {
    if (x[k] <= x[k - 1]) {
      throw InputError("skirt.oil_film_positions." + std::to_string(k), FormatValue(x[k]),
                       "must increase strictly [m]");
    }
  }
  if (!x.empty() && (x.back() < 0.0 || x.front() > liner)) {
    throw InputError("skirt.oil_film_positions",
                     fmt::format("{} … {} m", FormatValue(x.front()), FormatValue(x.back())),
                     fmt::format("must reach the liner the skirt runs over, 0 … {} m from the "
                                 "skirt top at top dead centre (the stroke 2 × "
                                 "geometry.crank_radius + skirt.length); outside the table its "
                                 "end values hold",
                                 FormatValue(liner)));
  }
}

}  // namespace

std::vector<JointProportion> JointProportions(const EngineCase& c) {
  std::vector<JointProportion> out;
  if (c.big_end.model == JointModel::kLubricated) {
    const double r = c.big_end.bearing_radius;
    out.push_back({"big_end.width", "the big end's width over its diameter, L/D", "L/D",
                   c.big_end.width / (2.0 * r), 0.1, 2.0});
    out.push_back({"big_end.journal_radius", "the big end's radial clearance over its radius, c/R",
                   "c/R", (r - c.big_end.journal_radius) / r, 1e-4, 1e-2});
  }
  if (c.skirt.model == JointModel::kLubricated) {
    const double r = c.geometry.liner_radius;
    out.push_back({"skirt.length", "the skirt's length over the bore", "length/bore",
                   c.skirt.length / (2.0 * r), 0.1, 2.0});
    out.push_back({"skirt.cold_clearance", "the skirt's cold clearance over the bore radius",
                   "clearance/radius", c.skirt.cold_clearance / r, 1e-5, 1e-2});
  }
  return out;
}

std::string DerivedNote(const EngineCase& c, const std::string& path) {
  // A proportion outside any engine's band first: the likely unit slip is what matters. A
  // length shows its proportion; a clearance its hot value (below).
  for (const JointProportion& p : JointProportions(c)) {
    if (p.field != path) continue;
    if (!p.Plausible()) {
      return fmt::format("{} = {:.3g}: engines lie within {:g}–{:g}; a length in the wrong unit?",
                         p.symbol, p.value, p.lo, p.hi);
    }
    if (path == "big_end.width" || path == "skirt.length")
      return fmt::format("{} = {:.3g}", p.symbol, p.value);
  }
  auto note = [](const JointFit& fit) -> std::string {
    if (fit.hot_clearance == fit.cold_clearance) return {};
    return fmt::format("hot: {:.2f} µm (cold {:.2f} µm)", fit.hot_clearance * 1e6,
                       fit.cold_clearance * 1e6);
  };
  if (path == "skirt.cold_clearance" || path == "skirt.piston_temperature" ||
      path == "skirt.liner_temperature")
    return note(SkirtFit(c));
  if (path == "big_end.journal_radius" || path == "big_end.journal_temperature" ||
      path == "big_end.bearing_temperature")
    return note(BigEndFit(c));
  // Values that stand for a choice rather than a quantity.
  const CaseField* field = FindCaseField(path);
  if (field != nullptr && field->get) {
    const double value = field->get(c);
    if (path.ends_with("bulk_modulus") && value == 0.0) return "0: an incompressible oil";
    if (path == "solver.error_estimate") return value != 0.0 ? "on" : "off";
  }
  return {};
}

std::string UnusedReason(const EngineCase& c, const std::string& path, ChoiceWording wording) {
  // A choice of the field at `field_path` as the reader knows it: its name in straight quotes
  // (as written in a file), or its title in typographic ones.
  auto choice = [wording](std::string_view field_path, std::string_view name) -> std::string {
    const CaseField* field = FindCaseField(field_path);
    const int k = field != nullptr ? field->ChoiceIndex(name) : -1;
    if (wording == ChoiceWording::kTitles && k >= 0)
      return "“" + field->ChoiceTitle(std::size_t(k)) + "”";
    return fmt::format("\"{}\"", name);
  };
  // The oil fields under a prefix: which of them the oil's own choices leave unused.
  auto oil_reason = [&choice](const lubrication::OilSpec& oil,
                              const std::string& name) -> std::string {
    using lubrication::PressureLaw;
    using lubrication::ViscosityModel;
    const bool vogel = oil.model == ViscosityModel::kVogel;
    const bool grade = oil.model == ViscosityModel::kGrade;
    if (name == "viscosity" && oil.model != ViscosityModel::kConstant)
      return grade ? "the viscosity follows the catalogue oil"
                   : "the viscosity follows Vogel's law";
    if ((name == "vogel_a" || name == "vogel_b" || name == "vogel_c") && !vogel)
      return grade ? "the catalogue oil sets Vogel's law" : "the viscosity model is constant";
    if (name == "grade" && !grade)
      return "the viscosity model is not " + choice("lubricant.viscosity_model", "grade");
    if (name == "barus_alpha" && oil.pressure_law != PressureLaw::kBarus)
      return "the pressure-viscosity law is not Barus'";
    if (name == "roelands_z" && oil.pressure_law != PressureLaw::kRoelands)
      return "the pressure-viscosity law is not Roelands'";
    using lubrication::ShearThinning;
    if ((name == "cross_ratio" || name == "cross_exponent") &&
        oil.shear_thinning == ShearThinning::kNone)
      return "no shear thinning";
    if (name == "cross_rate" && oil.shear_thinning != ShearThinning::kCross)
      return "the critical shear rate is not given (shear thinning is not " +
             choice("lubricant.shear_thinning", "cross") + ")";
    if (name == "hths" && oil.shear_thinning != ShearThinning::kHths)
      return "shear thinning is not set by the HTHS viscosity";
    return {};
  };
  if (path == "skirt.layer_thickness" &&
      c.skirt.compliance != lubrication::ComplianceModel::kElasticLayer)
    return "the skirt surfaces are not an elastic layer";
  if (path == "skirt.compliance_file" &&
      c.skirt.compliance != lubrication::ComplianceModel::kImported)
    return "the skirt compliance is not imported";
  if (path == "big_end.compliance_file" &&
      c.big_end.compliance != lubrication::ComplianceModel::kImported)
    return "the big-end compliance is not imported";
  if (path == "big_end.layer_thickness" &&
      c.big_end.compliance != lubrication::ComplianceModel::kElasticLayer)
    return "the big-end surfaces are not an elastic layer";
  // The oil supplies: what the supply choices leave unused. A supply pressure or a liner-film
  // table the choice cannot use is an error (CheckCaseConsistency), not an unused field: it
  // stays editable so that it can be removed.
  {
    using lubrication::OilFeedKind;
    const BigEndCase& b = c.big_end;
    auto supply = [&choice](std::string_view name) { return choice("big_end.supply", name); };
    const std::string feed = "the oil supply is " + supply(ToString(b.supply));
    if ((path == "big_end.supply_hole_angles" || path == "big_end.supply_hole_diameter") &&
        !lubrication::HasHoles(b.supply))
      return feed + "; holes feed the film only with " + supply("shell_holes") + ", " +
             supply("pin_holes") + " or " + supply("pin_holes_and_groove");
    if (path.rfind("big_end.groove_", 0) == 0 && !lubrication::HasGroove(b.supply))
      return feed + "; the groove feeds the film only with " + supply("groove") + " or " +
             supply("pin_holes_and_groove");
    const bool curve = !b.supply_pressure_angles.empty() || !b.supply_pressure_values.empty();
    if (b.supply != OilFeedKind::kLineOfCentres && curve && path == "big_end.oil_feed_pressure")
      return "the supply pressure follows the curve over the crank angle";
    if (b.supply == OilFeedKind::kLineOfCentres) {
      if (path == "big_end.oil_feed_pressure" && b.oil_feed_pressure == 0.0)
        return feed + "; a supply pressure needs holes or a groove";
      if ((path == "big_end.supply_pressure_angles" || path == "big_end.supply_pressure_values") &&
          !curve)
        return feed + "; a supply pressure needs holes or a groove";
    }
    const SkirtCase& sk = c.skirt;
    const bool film_path = path == "skirt.oil_film" || path == "skirt.oil_film_positions" ||
                           path == "skirt.oil_film_values";
    if (film_path && sk.supply != lubrication::SkirtSupply::kStarved)
      return "the skirt supply is " + choice("skirt.supply", ToString(sk.supply)) +
             "; the liner's oil film feeds the skirt only when its supply is " +
             choice("skirt.supply", "starved");
    if (path == "skirt.oil_film" && !sk.oil_film_positions.empty())
      return "the liner's oil film is the table over the liner position";
  }
  // The run-in: one of the two, by whether a lubricated film conserves mass.
  if (path == "solver.run_in_angle" && HasMassConservingFilm(c))
    return "a mass-conserving (JFO) film runs in for solver.jfo_run_in_angle";
  if (path == "solver.jfo_run_in_angle" && !HasMassConservingFilm(c))
    return "no lubricated film is mass-conserving (JFO)";
  // The bulk modulus: only a mass-conserving film uses it.
  {
    const bool skirt_jfo = IsMassConservingFilm(c.skirt);
    const bool big_end_jfo = IsMassConservingFilm(c.big_end);
    const bool skirt_lubricant = c.skirt.oil.source == OilSource::kLubricant;
    const bool big_end_lubricant = c.big_end.oil.source == OilSource::kLubricant;
    const char* reynolds = "only a mass-conserving (JFO) film uses the bulk modulus";
    if (path == "lubricant.bulk_modulus" && !(skirt_jfo && skirt_lubricant) &&
        !(big_end_jfo && big_end_lubricant))
      return reynolds;
    if (path == "skirt.oil.bulk_modulus" && !skirt_jfo && !skirt_lubricant) return reynolds;
    if (path == "big_end.oil.bulk_modulus" && !big_end_jfo && !big_end_lubricant) return reynolds;
    // The density law: as the bulk modulus, and only for a compressible oil.
    for (const auto& [oil_prefix, oil_spec] :
         {std::pair<std::string, const lubrication::OilSpec*>{"lubricant.", &c.lubricant},
          std::pair<std::string, const lubrication::OilSpec*>{"skirt.oil.", &c.skirt.oil.own},
          std::pair<std::string, const lubrication::OilSpec*>{"big_end.oil.",
                                                              &c.big_end.oil.own}}) {
      if (path != oil_prefix + "density_law") continue;
      const std::string modulus = oil_prefix + "bulk_modulus";
      if (std::string why = UnusedReason(c, modulus, wording); !why.empty()) return why;
      if (oil_spec->bulk_modulus == 0.0) return "the oil is incompressible (" + modulus + " = 0)";
    }
  }
  if (path.rfind("lubricant.", 0) == 0) return oil_reason(c.lubricant, path.substr(10));
  for (const auto& [joint, oil] : {std::pair{std::string("skirt"), &c.skirt.oil},
                                   std::pair{std::string("big_end"), &c.big_end.oil}}) {
    const std::string prefix = joint + ".oil.";
    if (path.rfind(prefix, 0) != 0) continue;
    const std::string name = path.substr(prefix.size());
    if (name == "source" || name == "temperature" || name == "temperature_mode") return {};
    if (name == "heat_share")
      return oil->temperature_mode == FilmTemperature::kHeatBalance
                 ? std::string()
                 : "the film temperature is given";
    if (oil->source == OilSource::kLubricant) return "the film carries the case's lubricant";
    return oil_reason(oil->own, name);
  }
  return {};
}

void CheckCaseConsistency(const EngineCase& c) {
  // The oils' bulk moduli: in range, and not beside a pressure law in a mass-conserving film.
  c.lubricant.CheckBulkModulus("lubricant.");
  JointBulkModulus(c, c.skirt.oil, "skirt", c.skirt.cavitation);
  JointBulkModulus(c, c.big_end.oil, "big_end", c.big_end.cavitation);
  CheckJointOils(c);
  // One cylinder-pressure curve per speed: a second one at the same speed would be ignored
  // (the first is taken), silently.
  for (std::size_t k = 0; k < c.pressure_curves.size(); ++k) {
    for (std::size_t i = 0; i < k; ++i) {
      if (c.pressure_curves[i].rpm == c.pressure_curves[k].rpm) {
        throw InputError("pressure_curves." + std::to_string(k) + ".rpm",
                         FormatValue(c.pressure_curves[k].rpm),
                         "pressure_curves." + std::to_string(i) +
                             " is at this speed already: one curve per speed [rpm]");
      }
    }
  }
  const auto& g = c.geometry;
  if (g.rod_length <= g.crank_radius + std::abs(g.pin_offset)) {
    throw InputError("geometry.rod_length", FormatValue(g.rod_length),
                     "must exceed geometry.crank_radius + |geometry.pin_offset| = " +
                         FormatValue(g.crank_radius + std::abs(g.pin_offset)) + " [m]");
  }
  if (g.rod_com_from_big_end > g.rod_length) {
    throw InputError("geometry.rod_com_from_big_end", FormatValue(g.rod_com_from_big_end),
                     "must lie on the rod: <= geometry.rod_length [m]");
  }
  if (!(c.skirt.cold_clearance < g.liner_radius)) {
    throw InputError(
        "skirt.cold_clearance", FormatValue(c.skirt.cold_clearance),
        "must be > 0 and smaller than geometry.liner_radius = " + FormatValue(g.liner_radius) +
            " [m] (the piston radius is their difference)");
  }
  if (c.big_end.journal_radius >= c.big_end.bearing_radius) {
    throw InputError("big_end.journal_radius", FormatValue(c.big_end.journal_radius),
                     "must be smaller than big_end.bearing_radius = " +
                         FormatValue(c.big_end.bearing_radius) + " [m]");
  }
  if (c.skirt.thrust_half_width + c.skirt.anti_thrust_half_width >= kPi) {
    throw InputError("skirt.anti_thrust_half_width", FormatValue(c.skirt.anti_thrust_half_width),
                     "thrust + anti-thrust half widths must be < π [rad]");
  }
  const auto& y = c.skirt.profile_y;
  if (y.size() != c.skirt.profile_h.size() || y.size() < 2) {
    throw InputError("skirt.profile_h", Values(c.skirt.profile_h.size()),
                     "needs as many values as skirt.profile_y (at least 2)");
  }
  for (std::size_t k = 1; k < y.size(); ++k) {
    if (y[k] <= y[k - 1]) {
      throw InputError("skirt.profile_y." + std::to_string(k), FormatValue(y[k]),
                       "must increase strictly [m]");
    }
  }
  const auto& alpha = c.skirt.ovality_alpha;
  if (alpha.size() != c.skirt.ovality_h.size()) {
    throw InputError("skirt.ovality_h", Values(c.skirt.ovality_h.size()),
                     "needs as many values as skirt.ovality_alpha (" +
                         std::to_string(alpha.size()) + "; both empty = no ovality)");
  }
  for (std::size_t k = 1; k < alpha.size(); ++k) {
    if (alpha[k] <= alpha[k - 1]) {
      throw InputError("skirt.ovality_alpha." + std::to_string(k), FormatValue(alpha[k]),
                       "must increase strictly [rad]");
    }
  }
  // A clearance that closes when hot: the temperatures and the result.
  if (const JointFit fit = SkirtFit(c); !(fit.hot_clearance > 0.0)) {
    throw InputError(
        "skirt.piston_temperature", FormatValue(c.skirt.piston_temperature),
        "with the liner at skirt.liner_temperature = " + FormatValue(c.skirt.liner_temperature) +
            " K the hot skirt clearance is " + FormatValue(fit.hot_clearance) + " m (cold " +
            FormatValue(fit.cold_clearance) + " m): it must stay > 0");
  }
  if (const JointFit fit = BigEndFit(c); !(fit.hot_clearance > 0.0)) {
    throw InputError("big_end.journal_temperature", FormatValue(c.big_end.journal_temperature),
                     "with the bearing at big_end.bearing_temperature = " +
                         FormatValue(c.big_end.bearing_temperature) +
                         " K the hot big-end clearance is " + FormatValue(fit.hot_clearance) +
                         " m (cold " + FormatValue(fit.cold_clearance) + " m): it must stay > 0");
  }
  CheckBigEndSupply(c.big_end);
  CheckSkirtSupply(c.skirt, 2.0 * c.geometry.crank_radius + c.skirt.length);
  CheckFilmMeshSizes(c);
}

}  // namespace filmdyn::engine
