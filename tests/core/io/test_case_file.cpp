// The case file: the shipped default loads and equals the built-in defaults (Table I in SI), every
// field round-trips, bad input is rejected naming the field, --set overrides, the pressure curve
// resolves from the case (on disk and embedded) at and between the shipped speeds.
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <numbers>

#include "core/base/input_error.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/film_joints.hpp"
#include "core/io/case_file.hpp"
#include "core/io/resources.hpp"

using namespace filmdyn;
using nlohmann::json;

namespace {
json DefaultJson() {
  std::ifstream file(std::string(FILMDYN_SOURCE_DIR) + "/resources/cases/default.json");
  return json::parse(file);
}
// The InputError's field for a case JSON, or "" if it loads.
std::string ErrorField(const json& j) {
  try {
    io::CaseFromJson(j);
  } catch (const InputError& e) {
    return e.field();
  }
  return "";
}
}  // namespace

class TestCaseFile : public QObject {
  Q_OBJECT
 private slots:
  void meshSizesAreCaseFields() {
    // The default case's meshes (graded big end; the paper's Table II meshes by --set or
    // engine::UsePaperMeshes); reachable by --set and rejected when not a sensible integer.
    const engine::EngineCase d = io::CaseFromJson(DefaultJson());
    QCOMPARE(d.skirt.mesh_thrust, 15);
    QCOMPARE(d.skirt.mesh_axial, 20);
    QCOMPARE(d.big_end.mesh_theta, 100);
    QCOMPARE(d.big_end.mesh_theta_grading, 8.0);
    QCOMPARE(d.big_end.mesh_z_grading, 4.0);
    engine::EngineCase paper = d;
    engine::UsePaperMeshes(&paper);
    QCOMPARE(paper.skirt.mesh_thrust, 30);
    QCOMPARE(paper.skirt.mesh_axial, 40);
    QCOMPARE(paper.big_end.mesh_theta, 50);
    QCOMPARE(paper.big_end.mesh_theta_grading, 1.0);
    QCOMPARE(engine::DescribeMeshes(paper),
             std::string("skirt 30 + 2 + 30 x 40 elements; big end 50 x 10 elements, uniform"));
    const io::LoadedCase c = io::LoadCase("", {"skirt.mesh_axial=12", "big_end.mesh_theta=24"});
    QCOMPARE(c.value.skirt.mesh_axial, 12);
    QCOMPARE(c.value.big_end.mesh_theta, 24);
    for (const char* bad : {"skirt.mesh_axial=1.5", "big_end.mesh_z=0", "skirt.mesh_thrust=-3"}) {
      try {
        io::LoadCase("", {bad});
        QFAIL(bad);
      } catch (const InputError& error) {
        QVERIFY2(QString(error.what()).contains("must be an integer"), error.what());
        QVERIFY(QString(error.what()).contains(QString(bad).section('=', 0, 0)));
      }
    }
  }

  void defaultCaseIsTableOne() {
    const engine::EngineCase c = io::CaseFromJson(DefaultJson());
    QCOMPARE(c.geometry.crank_radius, 39.93e-3);
    QCOMPARE(c.geometry.rod_length, 129.5e-3);
    QCOMPARE(c.geometry.rod_mass, 0.345);
    QCOMPARE(c.geometry.piston_inertia, 1.29e-4);
    QCOMPARE(c.big_end.bearing_radius - c.big_end.journal_radius, 15.00e-3 - 14.95e-3);
    QCOMPARE(c.lubricant.viscosity, 0.02);
    QCOMPARE(c.pressure_curves.size(), std::size_t(4));
    // The file and the struct defaults agree (one source of truth for the GUI's "reset").
    // The embedded case runs the paper's coupled model; a case built in code keeps ideal joints
    // unless asked (no film models without the coupling factories).
    QCOMPARE(c.skirt.model, engine::JointModel::kLubricated);
    QCOMPARE(c.big_end.model, engine::JointModel::kLubricated);
    engine::EngineCase defaults;
    defaults.skirt.model = defaults.big_end.model = engine::JointModel::kLubricated;
    defaults.description = c.description;
    defaults.pressure_curves = c.pressure_curves;
    defaults.assumed = c.assumed;
    QCOMPARE(io::CaseToJson(c), io::CaseToJson(defaults));
    // Values the paper lacks are marked with a reason.
    for (const char* field :
         {"geometry.crank_mass", "skirt.peklenik", "skirt.modulus_skirt", "skirt.poisson_liner",
          "big_end.modulus_journal", "big_end.poisson_bearing", "skirt.profile_h",
          "skirt.ovality_alpha", "big_end.oil_feed_pressure"}) {
      QVERIFY2(c.assumed.count(field) && !c.assumed.at(field).empty(), field);
    }
  }
  // The oil supplies' fields the choices leave unused are named with the choice; a value the
  // choice makes an error (a supply pressure with the film starting at the line of centres) is
  // not called unused.
  void unusedSupplyFieldsNameTheChoice() {
    using engine::UnusedReason;
    engine::EngineCase c = io::LoadCase({}).value;
    using lubrication::OilFeedKind;
    QCOMPARE(c.big_end.supply, OilFeedKind::kLineOfCentres);
    for (const char* path :
         {"big_end.supply_hole_diameter", "big_end.supply_hole_angles", "big_end.groove_width",
          "big_end.oil_feed_pressure", "big_end.supply_pressure_values", "skirt.oil_film",
          "skirt.oil_film_positions"}) {
      QVERIFY2(!UnusedReason(c, path).empty(), path);
    }
    QVERIFY(QString::fromStdString(UnusedReason(c, "big_end.groove_width"))
                .contains("\"line_of_centres\""));
    QVERIFY(QString::fromStdString(UnusedReason(c, "skirt.oil_film")).contains("\"flooded\""));
    // Where the reader sees the choices' titles (the case editor), the reason uses them too,
    // and only them.
    const auto titles = engine::ChoiceWording::kTitles;
    const QString holes = QString::fromStdString(UnusedReason(c, "big_end.supply_hole_angles"));
    const QString holes_titled =
        QString::fromStdString(UnusedReason(c, "big_end.supply_hole_angles", titles));
    QVERIFY2(holes.contains("\"shell_holes\", \"pin_holes\" or \"pin_holes_and_groove\""),
             qPrintable(holes));
    QCOMPARE(holes_titled,
             QString("the oil supply is “film start at the line of centres”; holes feed the film "
                     "only with “holes in the shell”, “holes in the crank pin” or “crank-pin "
                     "holes and groove”"));
    QVERIFY(!QString::fromStdString(UnusedReason(c, "skirt.oil_film", titles)).contains('"'));
    QCOMPARE(QString::fromStdString(UnusedReason(c, "lubricant.grade", titles)),
             QString("the viscosity model is not “catalogue oil (SAE grade)”"));
    QCOMPARE(QString::fromStdString(UnusedReason(c, "lubricant.grade")),
             QString("the viscosity model is not \"grade\""));
    c.big_end.oil_feed_pressure = 3e5;  // an error with this supply, not unused
    QVERIFY(UnusedReason(c, "big_end.oil_feed_pressure").empty());
    c.big_end.supply = OilFeedKind::kGroove;
    QVERIFY(UnusedReason(c, "big_end.groove_width").empty());
    QVERIFY(UnusedReason(c, "big_end.oil_feed_pressure").empty());
    QVERIFY(!UnusedReason(c, "big_end.supply_hole_diameter").empty());
    c.big_end.supply_pressure_angles = {0.0, 2.0};
    c.big_end.supply_pressure_values = {3e5, 4e5};
    QVERIFY(QString::fromStdString(UnusedReason(c, "big_end.oil_feed_pressure")).contains("curve"));
    c.big_end.supply = OilFeedKind::kShellHoles;
    QVERIFY(UnusedReason(c, "big_end.supply_hole_diameter").empty());
    c.skirt.supply = lubrication::SkirtSupply::kStarved;
    QVERIFY(UnusedReason(c, "skirt.oil_film").empty());
    QVERIFY(UnusedReason(c, "skirt.oil_film_values").empty());
    c.skirt.oil_film_positions = {0.0, 0.05};
    c.skirt.oil_film_values = {5e-6, 6e-6};
    QVERIFY(QString::fromStdString(UnusedReason(c, "skirt.oil_film")).contains("table"));
  }

  void roundTrip() {
    engine::EngineCase c = io::CaseFromJson(DefaultJson());
    c.geometry.pin_offset = -1.25e-3;
    c.skirt.model = engine::JointModel::kLubricated;
    c.solver.max_cycles = 7;
    engine::PressureCurveSource inline_curve;
    inline_curve.rpm = 3000;
    inline_curve.crank_angle_deg = {0, 360};
    inline_curve.pressure = {1, 2};
    c.pressure_curves.push_back(inline_curve);
    const json once = io::CaseToJson(c);
    const json twice = io::CaseToJson(io::CaseFromJson(once));
    QCOMPARE(once, twice);
    QCOMPARE(io::CaseFromJson(once).skirt.model, engine::JointModel::kLubricated);
  }
  // An editor's autosave of a case with refused values: each refused field (or the list or the
  // section holding it) takes the base case's value, every other value is read as saved, and
  // each restored field is named; a base that is itself refused, or no JSON, throws.
  void caseFileKeepingValidRestoresOnlyTheRefusedFields() {
    const engine::EngineCase base = io::LoadCase({}).value;
    nlohmann::json edited = io::CaseToJson(base);
    edited["operating"]["rpm"] = 2468.5;                // good
    edited["geometry"]["rod_length"] = nullptr;         // a cleared cell (NaN is written null)
    edited["big_end"]["width"] = -0.01;                 // out of range
    edited["skirt"]["profile_y"] = {0.0, 0.01, 0.005};  // not increasing
    edited["pressure_curves"][0]["rpm"] = -5.0;         // inside a list of objects
    QTemporaryDir dir;
    const std::string path = dir.filePath("autosave.json").toStdString();
    const auto write = [&path](const std::string& text) { std::ofstream(path) << text; };
    write(edited.dump());
    std::vector<std::string> dropped;
    const engine::EngineCase c = io::CaseFileKeepingValid(path, base, &dropped);
    QCOMPARE(c.operating.rpm, 2468.5);
    QCOMPARE(c.geometry.rod_length, base.geometry.rod_length);
    QCOMPARE(c.big_end.width, base.big_end.width);
    QVERIFY(c.skirt.profile_y == base.skirt.profile_y);
    QCOMPARE(c.pressure_curves.size(), base.pressure_curves.size());
    QCOMPARE(c.pressure_curves[0].rpm, base.pressure_curves[0].rpm);
    QCOMPARE(int(dropped.size()), 4);
    std::string all;
    for (const std::string& d : dropped) all += d + "\n";
    for (const char* field :
         {"geometry.rod_length", "big_end.width", "skirt.profile_y", "pressure_curves"})
      QVERIFY2(all.find(field) != std::string::npos, all.c_str());
    // The refusal is the base's own: nothing to fall back on.
    engine::EngineCase bad_base = base;
    bad_base.big_end.width = -0.01;
    nlohmann::json only_width = io::CaseToJson(base);
    only_width["big_end"]["width"] = -0.01;
    write(only_width.dump());
    QVERIFY_THROWS_EXCEPTION(InputError, io::CaseFileKeepingValid(path, bad_base, &dropped));
    write("{ \"geometry\": ");
    QVERIFY_THROWS_EXCEPTION(InputError, io::CaseFileKeepingValid(path, base, &dropped));
  }

  void perSurfaceElasticityAndOvality() {
    // Defaults: E and ν per surface, no ovality.
    const engine::EngineCase d = io::CaseFromJson(DefaultJson());
    QCOMPARE(d.skirt.modulus_skirt, 75e9);
    QCOMPARE(d.skirt.poisson_liner, 0.26);
    QCOMPARE(d.big_end.modulus_bearing, 70e9);
    QVERIFY(d.skirt.ovality_alpha.empty() && d.skirt.ovality_h.empty());
    // Round trip of edited values.
    engine::EngineCase c = d;
    c.skirt.modulus_liner = 1.3e11;
    c.skirt.poisson_skirt = -0.2;
    c.big_end.modulus_journal = 2.05e11;
    c.big_end.poisson_bearing = 0.49;
    c.skirt.ovality_alpha = {0.0, 0.8, std::numbers::pi};
    c.skirt.ovality_h = {0.0, 10e-6, 25e-6};
    const engine::EngineCase back = io::CaseFromJson(io::CaseToJson(c));
    QCOMPARE(back.skirt.modulus_liner, 1.3e11);
    QCOMPARE(back.skirt.poisson_skirt, -0.2);
    QCOMPARE(back.big_end.modulus_journal, 2.05e11);
    QCOMPARE(back.big_end.poisson_bearing, 0.49);
    QCOMPARE(back.skirt.ovality_alpha, c.skirt.ovality_alpha);
    QCOMPARE(back.skirt.ovality_h, c.skirt.ovality_h);
    QCOMPARE(io::CaseToJson(back), io::CaseToJson(c));
    // Reachable by --set (scalars present in the embedded default).
    const io::LoadedCase set =
        io::LoadCase("", {"skirt.modulus_liner=1.2e11", "big_end.poisson_journal=0.29"});
    QCOMPARE(set.value.skirt.modulus_liner, 1.2e11);
    QCOMPARE(set.value.big_end.poisson_journal, 0.29);

    // Bad values name the field: E in (0, 1e13] Pa, ν in (−1, 0.5).
    auto with = [](const std::string& section, const std::string& key, json value) {
      json j = DefaultJson();
      j[section][key] = value;
      return j;
    };
    QCOMPARE(ErrorField(with("skirt", "modulus_liner", 0.0)), std::string("skirt.modulus_liner"));
    QCOMPARE(ErrorField(with("skirt", "modulus_skirt", 2e13)), std::string("skirt.modulus_skirt"));
    QCOMPARE(ErrorField(with("skirt", "modulus_skirt", 1e13)), std::string());  // closed bound
    QCOMPARE(ErrorField(with("big_end", "modulus_bearing", "nan")),
             std::string("big_end.modulus_bearing"));
    QCOMPARE(ErrorField(with("big_end", "poisson_bearing", 0.5)),
             std::string("big_end.poisson_bearing"));
    QCOMPARE(ErrorField(with("big_end", "poisson_journal", -1.0)),
             std::string("big_end.poisson_journal"));
    QCOMPARE(ErrorField(with("skirt", "poisson_liner", "stiff")),
             std::string("skirt.poisson_liner"));
    try {
      io::CaseFromJson(with("skirt", "poisson_liner", 0.6));
      QFAIL("no error");
    } catch (const InputError& e) {
      QVERIFY2(std::string(e.what()).find("0.6") != std::string::npos, e.what());
      QVERIFY2(std::string(e.what()).find("0.5") != std::string::npos, e.what());
    }
    // An old file with one composite E' is told what replaced it.
    json legacy = DefaultJson();
    legacy["big_end"]["composite_modulus"] = 1.172e11;
    try {
      io::CaseFromJson(legacy);
      QFAIL("no error");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("big_end.composite_modulus"));
      QVERIFY2(std::string(e.what()).find("modulus_journal") != std::string::npos, e.what());
    }

    // Ovality: empty allowed; else angles strictly increasing in [0, π], gaps finite and ≥ 0.
    auto oval = [](json alpha, json h) {
      json j = DefaultJson();
      j["skirt"]["ovality_alpha"] = alpha;
      j["skirt"]["ovality_h"] = h;
      return j;
    };
    QCOMPARE(ErrorField(oval(json::array(), json::array())), std::string());
    QCOMPARE(ErrorField(oval({0.0, 1.5}, {0.0, 2e-5})), std::string());
    QCOMPARE(ErrorField(oval({0.0, 1.0}, json::array({0.0}))), std::string("skirt.ovality_h"));
    QCOMPARE(ErrorField(oval(json::array({0.0}), json::array())), std::string("skirt.ovality_h"));
    QCOMPARE(ErrorField(oval({0.0, 3.5}, {0.0, 1e-5})), std::string("skirt.ovality_alpha.1"));
    QCOMPARE(ErrorField(oval({-0.1, 1.0}, {0.0, 1e-5})), std::string("skirt.ovality_alpha.0"));
    QCOMPARE(ErrorField(oval({0.0, 1.0, 1.0}, {0.0, 1e-5, 2e-5})),
             std::string("skirt.ovality_alpha.2"));
    QCOMPARE(ErrorField(oval({1.0, 0.5}, {0.0, 1e-5})), std::string("skirt.ovality_alpha.1"));
    QCOMPARE(ErrorField(oval({0.0, 1.0}, {0.0, -1e-6})), std::string("skirt.ovality_h.1"));
    QCOMPARE(ErrorField(oval({0.0, 1.0}, {0.0, "inf"})), std::string("skirt.ovality_h.1"));
    QCOMPARE(ErrorField(oval({0.0, "nan"}, {0.0, 1e-5})), std::string("skirt.ovality_alpha.1"));
    QCOMPARE(ErrorField(oval(1.0, json::array({0.0}))), std::string("skirt.ovality_alpha"));
  }

  void badInputNamesTheField() {
    auto with = [](const std::string& section, const std::string& key, json value) {
      json j = DefaultJson();
      j[section][key] = value;
      return j;
    };
    QCOMPARE(ErrorField(with("geometry", "rod_mass", -0.3)), std::string("geometry.rod_mass"));
    QCOMPARE(ErrorField(with("geometry", "crank_radius", -0.04)),
             std::string("geometry.crank_radius"));
    QCOMPARE(ErrorField(with("geometry", "rod_length", 0.03)), std::string("geometry.rod_length"));
    QCOMPARE(ErrorField(with("big_end", "width", "nan")), std::string("big_end.width"));
    QCOMPARE(ErrorField(with("lubricant", "viscosity", "wet")), std::string("lubricant.viscosity"));
    QCOMPARE(ErrorField(with("skirt", "model", "greasy")), std::string("skirt.model"));
    QCOMPARE(ErrorField(with("big_end", "journal_radius", 0.016)),
             std::string("big_end.journal_radius"));
    QCOMPARE(ErrorField(with("solver", "max_cycles", 2.5)), std::string("solver.max_cycles"));
    QCOMPARE(ErrorField(with("geometry", "rod_lenght", 0.13)), std::string("geometry.rod_lenght"));
    // A liner oil film below a molecular layer (1 nm) is no film to run a starved skirt on.
    QCOMPARE(ErrorField(with("skirt", "oil_film", 1e-15)), std::string("skirt.oil_film"));
    QCOMPARE(ErrorField(with("skirt", "oil_film", 1e-9)), std::string());
    // An inline curve's point is named with its curve's path; a second curve at one speed is
    // refused (the first was taken, silently).
    json inline_curve = DefaultJson();
    inline_curve["pressure_curves"] = json::array(
        {{{"rpm", 6000}, {"crank_angle_deg", {0, 90, 180}}, {"pressure", {1e5, 2e5, -1}}}});
    QCOMPARE(ErrorField(inline_curve), std::string("pressure_curves.0.pressure.2"));
    inline_curve["pressure_curves"][0]["crank_angle_deg"] = {0, 90, 900};
    QCOMPARE(ErrorField(inline_curve), std::string("pressure_curves.0.crank_angle_deg.2"));
    json twice = DefaultJson();
    twice["pressure_curves"].push_back(twice["pressure_curves"][0]);
    QCOMPARE(ErrorField(twice),
             "pressure_curves." + std::to_string(twice["pressure_curves"].size() - 1) + ".rpm");
    json not_a_section = DefaultJson();
    not_a_section["geometry"] = json::array({1, 2});
    try {
      io::CaseFromJson(not_a_section);
      QFAIL("a section given as a list was accepted");
    } catch (const InputError& e) {
      QCOMPARE(std::string(e.what()),
               std::string("geometry = [1,2]: must be an object of the section's fields (see "
                           "docs/case-file.md)"));
    }
    json bad_note = DefaultJson();
    bad_note["assumed"]["geometry.nothing"] = "x";
    QCOMPARE(ErrorField(bad_note), std::string("assumed.geometry.nothing"));
    // The message names value and range.
    try {
      io::CaseFromJson(with("geometry", "rod_mass", -0.3));
      QFAIL("no error");
    } catch (const InputError& e) {
      QVERIFY(std::string(e.what()).find("-0.3") != std::string::npos);
      QVERIFY(std::string(e.what()).find("(0, 100000]") != std::string::npos);
    }
  }
  // A key given twice in one object is refused, named by its path: the JSON parser would keep
  // the last value and silently drop the other (a case once ran with "rod_mass": 99 after a
  // "rod_mass": 0.345 above it).
  // A name that is no field suggests the fields a slip of the keyboard away, or the same name in
  // another section; a name near none suggests nothing.
  void unknownFieldsSuggestTheNearOnes() {
    auto message = [](const json& j) -> std::string {
      try {
        io::CaseFromJson(j);
      } catch (const InputError& e) {
        return e.what();
      }
      return "";
    };
    json typo = DefaultJson();
    typo["skirt"]["lenght"] = 0.09;
    QVERIFY2(message(typo).find("unknown field (see docs/case-file.md); did you mean "
                                "skirt.length?") != std::string::npos,
             message(typo).c_str());
    json section = DefaultJson();
    section["geometry"]["cold_clearance"] = 2e-5;
    QVERIFY2(message(section).find("did you mean skirt.cold_clearance?") != std::string::npos,
             message(section).c_str());
    json far = DefaultJson();
    far["skirt"]["zqxwv"] = 1.0;
    QVERIFY2(message(far).find("did you mean") == std::string::npos, message(far).c_str());
    try {
      io::LoadCaseText(DefaultJson().dump(), "case", {"big_end.widht=0.02"});
      QFAIL("no error");
    } catch (const InputError& e) {
      QVERIFY2(std::string(e.what()).find("did you mean big_end.width?") != std::string::npos,
               e.what());
    }
    QCOMPARE(engine::SimilarFieldsText("skirt.length"), std::string());  // a field itself
  }

  void aRepeatedKeyIsRefused() {
    auto error_of = [](const std::string& text) -> std::string {
      try {
        io::LoadCaseText(text, "c.json");
      } catch (const InputError& e) {
        return e.what();
      }
      return "";
    };
    QCOMPARE(error_of(R"({"geometry": {"rod_mass": 0.345, "rod_mass": 99.0}})"),
             std::string("c.json: geometry.rod_mass = given twice: a key appears once in its "
                         "object (the second value would silently replace the first): keep one"));
    QVERIFY(error_of(R"({"name": "a", "name": "b"})").starts_with("c.json: name = given twice"));
    QVERIFY(error_of(R"({"pressure_curves": [{"rpm": 2000}, {"rpm": 3000, "rpm": 4000}]})")
                .starts_with("c.json: pressure_curves.1.rpm = given twice"));
    // The same key in two objects is no repetition.
    QVERIFY(error_of(R"({"skirt": {"model": "ideal"}, "big_end": {"model": "ideal"}})").empty());
  }

  void coldSkirtClearanceIsTheInput() {
    // The default case gives the clearance; the piston radius derived from it is Table I's
    // 36.475 mm to the last bit, and the film's clearance is R_l − R as before.
    const engine::EngineCase c = io::CaseFromJson(DefaultJson());
    QVERIFY(!DefaultJson()["skirt"].contains("piston_radius"));
    QCOMPARE(c.skirt.cold_clearance, 25e-6);
    QVERIFY(engine::PistonRadius(c) == 0.036475);
    QVERIFY(engine::SkirtClearance(c) == 0.0365 - 0.036475);
    QCOMPARE(engine::SkirtConfigFromCase(c).geometry.radius, 0.036475);
    QCOMPARE(io::CaseToJson(c)["skirt"]["cold_clearance"].get<double>(), 25e-6);
    QVERIFY(!io::CaseToJson(c)["skirt"].contains("piston_radius"));
    // --set changes it, the piston radius follows.
    const io::LoadedCase set = io::LoadCase("", {"skirt.cold_clearance=4e-05"});
    QCOMPARE(set.value.skirt.cold_clearance, 40e-6);
    QCOMPARE(engine::PistonRadius(set.value), 0.0365 - 40e-6);
    QVERIFY(set.notes.empty());

    // An older file with the piston radius: read as the clearance it implies, with a note; the
    // radius and the film's clearance are bit for bit those of the older reader.
    json old = DefaultJson();
    old["skirt"].erase("cold_clearance");
    old["skirt"]["piston_radius"] = 0.0364;
    old["assumed"]["skirt.piston_radius"] = "a note on the radius";
    std::vector<std::string> notes;
    const engine::EngineCase migrated = io::CaseFromJson(old, &notes);
    QVERIFY(engine::PistonRadius(migrated) == 0.0364);
    QVERIFY(engine::SkirtClearance(migrated) == 0.0365 - 0.0364);
    QCOMPARE(notes.size(), std::size_t(1));
    QVERIFY2(notes[0].find("skirt.piston_radius = 0.0364") != std::string::npos &&
                 notes[0].find("skirt.cold_clearance = 0.0001") != std::string::npos,
             notes[0].c_str());
    QCOMPARE(migrated.assumed.count("skirt.cold_clearance"), std::size_t(1));
    // Saved, it has the new key only, and reads back to the same case.
    const json saved = io::CaseToJson(migrated);
    QVERIFY(!saved["skirt"].contains("piston_radius"));
    QCOMPARE(io::CaseToJson(io::CaseFromJson(saved)), saved);
    // The old key through LoadCaseText: the note reaches LoadedCase's caller.
    std::vector<std::string> text_notes;
    io::LoadCaseText(old.dump(), "old.json", {}, &text_notes);
    QCOMPARE(text_notes.size(), std::size_t(1));

    auto message = [](const json& j) -> std::string {
      try {
        io::CaseFromJson(j);
      } catch (const InputError& e) {
        return e.what();
      }
      return "loads";
    };
    // Both keys: the old one is named with its replacement.
    json both = DefaultJson();
    both["skirt"]["piston_radius"] = 0.036475;
    QCOMPARE(ErrorField(both), std::string("skirt.piston_radius"));
    QVERIFY2(message(both).find("skirt.cold_clearance") != std::string::npos,
             message(both).c_str());
    // An old radius at or beyond the liner radius: named, with the liner radius.
    json too_big = old;
    too_big["skirt"]["piston_radius"] = 0.0366;
    QCOMPARE(ErrorField(too_big), std::string("skirt.piston_radius"));
    QVERIFY2(message(too_big).find("0.0366") != std::string::npos &&
                 message(too_big).find("geometry.liner_radius = 0.0365") != std::string::npos,
             message(too_big).c_str());
    // A clearance of zero or less, or not smaller than the liner radius.
    for (const double bad : {0.0, -1e-6}) {
      json j = DefaultJson();
      j["skirt"]["cold_clearance"] = bad;
      QCOMPARE(ErrorField(j), std::string("skirt.cold_clearance"));
      QVERIFY2(message(j).find("(0, 0.01]") != std::string::npos, message(j).c_str());
    }
    json small_bore = DefaultJson();
    small_bore["geometry"]["liner_radius"] = 0.004;
    small_bore["skirt"]["cold_clearance"] = 0.005;
    QCOMPARE(ErrorField(small_bore), std::string("skirt.cold_clearance"));
    QVERIFY2(message(small_bore).find("0.005") != std::string::npos &&
                 message(small_bore).find("geometry.liner_radius = 0.004") != std::string::npos,
             message(small_bore).c_str());
    // --set of the old key on a new file names the replacement.
    try {
      io::LoadCase("", {"skirt.piston_radius=0.0364"});
      QFAIL("no error");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("--set skirt.piston_radius"));
      QVERIFY2(std::string(e.what()).find("skirt.cold_clearance") != std::string::npos, e.what());
    }
  }
  void setOverrides() {
    json j = DefaultJson();
    io::ApplyOverride(&j, "geometry.rod_length=0.14");
    io::ApplyOverride(&j, "skirt.model=lubricated");
    io::ApplyOverride(&j, "pressure_curves.0.rpm=1500");
    const engine::EngineCase c = io::CaseFromJson(j);
    QCOMPARE(c.geometry.rod_length, 0.14);
    QCOMPARE(c.pressure_curves[0].rpm, 1500.0);
    auto field = [&](const std::string& assignment) {
      json k = DefaultJson();
      try {
        io::ApplyOverride(&k, assignment);
        io::CaseFromJson(k);
      } catch (const InputError& e) {
        return e.field();
      }
      return std::string();
    };
    QCOMPARE(field("geometry.rod_length=abc"), std::string("--set geometry.rod_length"));
    // A number with a unit: the error says the field takes SI and its range.
    try {
      json k = DefaultJson();
      io::ApplyOverride(&k, "geometry.rod_length=130mm");
      QFAIL("130mm accepted");
    } catch (const InputError& e) {
      QCOMPARE(std::string(e.what()),
               "--set geometry.rod_length = 130mm: must be a number without a unit (SI): " +
                   engine::FindCaseField("geometry.rod_length")->AllowedText());
      QVERIFY2(std::string(e.what()).find("[m]") != std::string::npos, e.what());
    }
    QCOMPARE(field("geometry.no_such=1"), std::string("--set geometry.no_such"));
    QCOMPARE(field("geometry=1"), std::string("--set geometry"));
    QCOMPARE(field("geometry.rod_mass=nan"), std::string("geometry.rod_mass"));
    QCOMPARE(field("novalue"), std::string("--set"));
    // An element beyond a list's end: the error names the value given and the elements there are.
    for (const auto& [assignment, there] :
         {std::pair<std::string, std::string>{"skirt.oil_film_positions.5=0.03", "it is empty"},
          {"pressure_curves.7.rpm=1500", "its elements are 0 … "}}) {
      try {
        json k = DefaultJson();
        io::ApplyOverride(&k, assignment);
        QFAIL(assignment.c_str());
      } catch (const InputError& e) {
        const std::string path = assignment.substr(0, assignment.find('='));
        QCOMPARE(e.field(), "--set " + path);
        QCOMPARE(e.value(), assignment.substr(assignment.find('=') + 1));
        QVERIFY2(std::string(e.allowed()).find(there) != std::string::npos, e.what());
      }
    }
    // A liner oil-film table wholly beside the liner the skirt runs over (here in mm where m are
    // due) would hold one end value everywhere: refused, naming the liner's span.
    for (const std::string positions : {"[5,6]", "[-1,-0.5]"}) {
      try {
        json k = DefaultJson();
        io::ApplyOverride(&k, "skirt.oil_film_positions=" + positions);
        io::ApplyOverride(&k, "skirt.oil_film_values=[5e-6,5e-6]");
        io::CaseFromJson(k);
        QFAIL(positions.c_str());
      } catch (const InputError& e) {
        QCOMPARE(e.field(), std::string("skirt.oil_film_positions"));
        QVERIFY2(std::string(e.allowed()).find("0 … 0.10786 m") != std::string::npos, e.what());
      }
    }
    json partly = DefaultJson();  // reaching into it is fine
    io::ApplyOverride(&partly, "skirt.oil_film_positions=[-0.5,0.01]");
    io::ApplyOverride(&partly, "skirt.oil_film_values=[5e-6,5e-6]");
    QCOMPARE(io::CaseFromJson(partly).skirt.oil_film_positions.back(), 0.01);
    // The run model is no case field: the error says where it is chosen.
    try {
      json k = DefaultJson();
      io::ApplyOverride(&k, "model=only-skirt");
      QFAIL("--set model was accepted");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("--set model"));
      QVERIFY2(std::string(e.allowed()).find("--model") != std::string::npos, e.what());
    }

    // A list field is set whole: comma-separated, in brackets or not, blanks ignored; "[]" empties
    // it; one element by its index. The pair rules apply after all overrides.
    json lists = DefaultJson();
    for (const char* set :
         {"big_end.supply=pin_holes", "big_end.supply_hole_angles=[0, 3.14]",
          "skirt.oil_film_positions=0,0.02,0.05", "skirt.oil_film_values=[2e-6,4e-6,1e-5]",
          "skirt.oil_film_positions.1=0.03"})
      io::ApplyOverride(&lists, set);
    engine::EngineCase listed = io::CaseFromJson(lists);
    QCOMPARE(listed.big_end.supply_hole_angles, (std::vector<double>{0.0, 3.14}));
    QCOMPARE(listed.skirt.oil_film_positions, (std::vector<double>{0.0, 0.03, 0.05}));
    QCOMPARE(listed.skirt.oil_film_values, (std::vector<double>{2e-6, 4e-6, 1e-5}));
    io::ApplyOverride(&lists, "skirt.oil_film_positions=[]");
    io::ApplyOverride(&lists, "skirt.oil_film_values=");
    listed = io::CaseFromJson(lists);
    QVERIFY(listed.skirt.oil_film_positions.empty() && listed.skirt.oil_film_values.empty());
    // A list absent from the file is added like a scalar.
    json older = DefaultJson();
    older["big_end"].erase("supply_hole_angles");
    io::ApplyOverride(&older, "big_end.supply_hole_angles=[1]");
    QCOMPARE(io::CaseFromJson(older).big_end.supply_hole_angles, std::vector<double>{1.0});
    // Bad lists name the field (or the element); a pair of unequal lengths names the pair.
    QCOMPARE(field("big_end.supply_hole_angles=[0,x]"),
             std::string("--set big_end.supply_hole_angles.1"));
    QCOMPARE(field("big_end.supply_hole_angles=[0,,1]"),
             std::string("--set big_end.supply_hole_angles"));
    QCOMPARE(field("big_end.supply_hole_angles=[0,1"),
             std::string("--set big_end.supply_hole_angles"));
    QCOMPARE(field("big_end.supply_hole_angles=0,nan"),
             std::string("big_end.supply_hole_angles.1"));
    QCOMPARE(field("big_end.supply_hole_angles=0,99"), std::string("big_end.supply_hole_angles.1"));
    QCOMPARE(field("skirt.oil_film_values=[1e-6]"), std::string("skirt.oil_film_values"));
  }
  void pressureCurvesResolve() {
    const io::LoadedCase embedded = io::LoadCase({});  // the compiled-in default
    QVERIFY(embedded.directory.empty());
    const auto at_6000 = io::PressureCurveForSpeed(embedded, 6000);
    QVERIFY(at_6000.PeakPressure() > 4e6);
    const io::LoadedCase on_disk =
        io::LoadCase(std::string(FILMDYN_SOURCE_DIR) + "/resources/cases/default.json");
    QCOMPARE(io::PressureCurveForSpeed(on_disk, 6000).PeakPressure(), at_6000.PeakPressure());
    // Between speeds: a blend, within the neighbours' peaks.
    const double p2 = io::PressureCurveForSpeed(embedded, 2000).PeakPressure();
    const double p4 = io::PressureCurveForSpeed(embedded, 4000).PeakPressure();
    const double p3 = io::PressureCurveForSpeed(embedded, 3000).PeakPressure();
    QVERIFY(p3 >= std::min(p2, p4) - 1 && p3 <= std::max(p2, p4) + 1);
    try {
      io::PressureCurveForSpeed(embedded, 9000);
      QFAIL("no error");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("operating.rpm"));
    }
    // A curve file that does not exist names the field.
    json j = DefaultJson();
    j["pressure_curves"][0]["file"] = "missing.csv";
    io::LoadedCase broken{io::CaseFromJson(j), "/nonexistent", "test", {}};
    try {
      io::PressureCurveForSpeed(broken, 1000);
      QFAIL("no error");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("pressure_curves.0.file"));
    }
  }
  // A case file named without a folder ("case.json", run from its folder) reads the files it
  // names from beside it, as "./case.json" does: its own curve file, not the built-in resource
  // of the same name (the folder used to be empty, which means the embedded case).
  void aCaseNamedWithoutAFolderReadsItsOwnFiles() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkpath("pressure"));
    {
      std::ofstream csv(dir.filePath("pressure/synthetic_1000rpm.csv").toStdString());
      csv << "crank_angle[deg],pressure[Pa]\n";
      for (int deg = 0; deg <= 720; deg += 10)
        csv << deg << "," << (deg == 360 ? 9.87e6 : 1e5) << "\n";
    }
    json j = DefaultJson();
    j["pressure_curves"] =
        json::array({{{"rpm", 1000.0}, {"file", "pressure/synthetic_1000rpm.csv"}}});
    {
      std::ofstream out(dir.filePath("case.json").toStdString());
      out << j.dump(2);
    }
    const QString previous = QDir::currentPath();
    QVERIFY(QDir::setCurrent(dir.path()));
    double bare = 0.0, dotted = 0.0;
    std::filesystem::path folder;
    try {
      const io::LoadedCase loaded = io::LoadCase("case.json");
      folder = loaded.directory;
      bare = io::PressureCurveForSpeed(loaded, 1000).PeakPressure();
      dotted = io::PressureCurveForSpeed(io::LoadCase("./case.json"), 1000).PeakPressure();
    } catch (const std::exception& e) {
      QDir::setCurrent(previous);
      QFAIL(e.what());
    }
    QDir::setCurrent(previous);
    QCOMPARE(bare, 9.87e6);
    QCOMPARE(dotted, 9.87e6);
    QVERIFY(folder.is_absolute());
  }
  // A key holding a dot is no field ("skirt.cold_clearance" at the top level, "oil.viscosity"
  // inside "skirt"): refused, naming it, where it used to be ignored silently (its path joined
  // into a field's, which the reader had seen).
  void dottedKeysAreRefused() {
    for (const auto& [text, field] :
         {std::pair{R"({"skirt.cold_clearance": 0.5})", "skirt.cold_clearance"},
          std::pair{R"({"skirt": {"oil.viscosity": 5}})", "skirt.oil.viscosity"}}) {
      json j = DefaultJson();
      j.merge_patch(json::parse(text));
      try {
        io::CaseFromJson(j);
        QFAIL(text);
      } catch (const InputError& e) {
        QCOMPARE(e.field(), std::string(field));
        QVERIFY2(std::string(e.allowed()).find("nest it as objects") != std::string::npos,
                 e.what());
      }
    }
  }
  // The format's version is read: a newer FilmDyn's file is refused saying so (before any field
  // it may add), a version that is no whole number ≥ 1 is refused; the current one reads.
  void caseFormatVersionIsChecked() {
    for (const auto& [version, needle] :
         {std::pair{json(2), "written by a newer FilmDyn"},
          std::pair{json(99), "written by a newer FilmDyn"}, std::pair{json("abc"), "whole number"},
          std::pair{json(0), "whole number"}, std::pair{json(1.5), "whole number"}}) {
      json j = DefaultJson();
      j["filmdyn_case_version"] = version;
      j["a_field_of_a_newer_version"] = 1;
      try {
        io::CaseFromJson(j);
        QFAIL(version.dump().c_str());
      } catch (const InputError& e) {
        QCOMPARE(e.field(), std::string("filmdyn_case_version"));
        QVERIFY2(std::string(e.what()).find(needle) != std::string::npos, e.what());
      }
    }
    json j = DefaultJson();
    j["filmdyn_case_version"] = 1;
    io::CaseFromJson(j);
  }
  void embeddedResourcesPresent() {
    QVERIFY(io::ReadResource("cases/default.json").has_value());
    QVERIFY(io::ReadResource("pressure/synthetic_1000rpm.csv").has_value());
    QVERIFY(!io::ReadResource("pressure/none.csv").has_value());
  }

  // The oil's bulk modulus reaches a mass-conserving film only (Reynolds films are
  // incompressible), is refused beside a pressure-viscosity law and outside its range, naming the
  // field, and is marked unused where no film uses it.
  void bulkModulusReachesMassConservingFilmsOnly() {
    json j = DefaultJson();
    io::ApplyOverride(&j, "lubricant.bulk_modulus=1.7e9");
    engine::EngineCase c = io::CaseFromJson(j);
    QCOMPARE(engine::BearingConfigFromCase(c).bulk_modulus, 0.0);  // Reynolds
    QCOMPARE(engine::SkirtConfigFromCase(c).bulk_modulus, 0.0);
    QVERIFY(!engine::UnusedReason(c, "lubricant.bulk_modulus").empty());
    io::ApplyOverride(&j, "big_end.cavitation=jfo");
    c = io::CaseFromJson(j);
    QCOMPARE(engine::BearingConfigFromCase(c).bulk_modulus, 1.7e9);
    QCOMPARE(engine::SkirtConfigFromCase(c).bulk_modulus, 0.0);
    QVERIFY(engine::UnusedReason(c, "lubricant.bulk_modulus").empty());
    // The skirt's own incompressible oil in a JFO skirt; its field is used there.
    io::ApplyOverride(&j, "skirt.cavitation=jfo");
    io::ApplyOverride(&j, "skirt.oil.source=own");
    c = io::CaseFromJson(j);
    QCOMPARE(engine::SkirtConfigFromCase(c).bulk_modulus, 0.0);
    QVERIFY(engine::UnusedReason(c, "skirt.oil.bulk_modulus").empty());
    QCOMPARE(io::CaseToJson(io::CaseFromJson(io::CaseToJson(c))), io::CaseToJson(c));
    auto refused = [](const engine::EngineCase& bad, const std::string& field,
                      const std::string& words) {
      try {
        engine::BearingConfigFromCase(bad);
      } catch (const filmdyn::InputError& e) {
        const std::string what = e.what();
        return what.find(field) != std::string::npos && what.find(words) != std::string::npos;
      }
      return false;
    };
    engine::EngineCase bad = c;
    bad.lubricant.pressure_law = lubrication::PressureLaw::kBarus;
    QVERIFY(refused(bad, "lubricant.bulk_modulus", "pressure-viscosity law"));
    bad = c;
    bad.lubricant.bulk_modulus = 5e6;
    QVERIFY(refused(bad, "lubricant.bulk_modulus", "1e7–1e11 Pa"));
    bad.lubricant.bulk_modulus = std::nan("");
    QVERIFY(refused(bad, "lubricant.bulk_modulus", "1e7–1e11 Pa"));
    // A case file (and the GUI's validation, which reads the case as a file) is refused alike.
    for (const char* set : {"lubricant.bulk_modulus=5e6", "lubricant.pressure_viscosity=barus"}) {
      json b = j;
      io::ApplyOverride(&b, set);
      try {
        io::CaseFromJson(b);
        QFAIL(set);
      } catch (const filmdyn::InputError& e) {
        QCOMPARE(e.field(), std::string("lubricant.bulk_modulus"));
      }
    }
  }

  // Each joint's oil at its own film temperature: the case's lubricant (constant, or Vogel with
  // a pressure law) or the joint's own, set with --set paths and read back from the file.
  void jointOilsResolveAtTheirTemperatures() {
    json j = DefaultJson();
    for (const char* set : {"lubricant.viscosity_model=vogel", "lubricant.vogel_a=6.9e-5",
                            "lubricant.vogel_b=1050", "lubricant.vogel_c=165",
                            "lubricant.pressure_viscosity=barus", "lubricant.barus_alpha=2e-8",
                            "big_end.oil.temperature=363.15", "skirt.oil.temperature=393.15"})
      io::ApplyOverride(&j, set);
    engine::EngineCase c = io::CaseFromJson(j);
    auto vogel = [](double t) { return 6.9e-5 * std::exp(1050.0 / (t - 165.0)); };
    const auto bearing = engine::BearingConfigFromCase(c);
    QVERIFY(std::abs(bearing.viscosity / vogel(363.15) - 1.0) < 1e-14);
    QCOMPARE(bearing.pressure_viscosity.law(), lubrication::PressureLaw::kBarus);
    QCOMPARE(bearing.pressure_viscosity.InitialCoefficient(), 2e-8);
    QVERIFY(std::abs(engine::SkirtConfigFromCase(c).viscosity / vogel(393.15) - 1.0) < 1e-14);
    // The skirt with its own oil: a constant 5 mPa s and no pressure law; the big end unchanged.
    io::ApplyOverride(&j, "skirt.oil.source=own");
    io::ApplyOverride(&j, "skirt.oil.viscosity=0.005");
    c = io::CaseFromJson(j);
    const auto skirt = engine::SkirtConfigFromCase(c);
    QCOMPARE(skirt.viscosity, 0.005);
    QVERIFY(!skirt.pressure_viscosity.active());
    QVERIFY(std::abs(engine::BearingConfigFromCase(c).viscosity / vogel(363.15) - 1.0) < 1e-14);
    // Written and read back with the nested paths.
    const json once = io::CaseToJson(c);
    QCOMPARE(io::CaseToJson(io::CaseFromJson(once)), once);
    QCOMPARE(once["skirt"]["oil"]["source"].get<std::string>(), std::string("own"));
    // A film temperature at or below the Vogel pole names the joint's temperature field.
    c.big_end.oil.temperature = 160.0;
    try {
      engine::BearingConfigFromCase(c);
      QFAIL("no error below the pole");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("big_end.oil.temperature"));
    }
    // Vogel constants left at zero name the lubricant's field.
    c.big_end.oil.temperature = 363.15;
    c.lubricant.vogel_a = 0.0;
    try {
      engine::BearingConfigFromCase(c);
      QFAIL("no error for a = 0");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("lubricant.vogel_a"));
    }
    // The same oils checked with the case (file, --set, case editor), not first by the run: a
    // lubricated joint's film temperature below the pole is refused naming it ...
    json cold = j;
    io::ApplyOverride(&cold, "big_end.oil.temperature=160");
    QCOMPARE(ErrorField(cold), std::string("big_end.oil.temperature"));
    QCOMPARE(ErrorField(j), std::string());
    // ... and with a heat balance, the temperature it starts from: the supply temperature when
    // that is higher (a pole between the two is refused).
    json balanced = j;
    for (const char* set : {"big_end.oil.temperature=300",
                            "big_end.oil.temperature_mode=heat_balance", "lubricant.vogel_c=320"})
      io::ApplyOverride(&balanced, set);
    const engine::EngineCase heated = io::CaseFromJson(balanced);
    QCOMPARE(engine::StartFilmTemperature(heated, heated.big_end.oil),
             heated.lubricant.supply_temperature);
    io::ApplyOverride(&balanced, "big_end.oil.temperature_mode=given");
    QCOMPARE(ErrorField(balanced), std::string("big_end.oil.temperature"));
    // A joint that is not lubricated does not use its oil: not checked.
    io::ApplyOverride(&cold, "big_end.model=ideal");
    QCOMPARE(ErrorField(cold), std::string());
  }

  // Thermal clearances by hand: hot radii R (1 + α (T − 293.15 K)); at 20 °C the cold ones bit
  // for bit; a clearance that closes is an input error naming the temperatures and the result.
  void thermalClearancesByHand() {
    engine::EngineCase c = io::CaseFromJson(DefaultJson());
    const auto cold = engine::SkirtConfigFromCase(c);
    QCOMPARE(cold.geometry.radial_clearance, engine::SkirtClearance(c));
    QCOMPARE(cold.geometry.radius, engine::PistonRadius(c));
    QCOMPARE(engine::BearingConfigFromCase(c).geometry.radial_clearance,
             c.big_end.bearing_radius - c.big_end.journal_radius);
    c.skirt.piston_temperature = 333.15;  // 60 °C, α 21e-6: +30.6 µm on the radius
    c.skirt.liner_temperature = 323.15;   // 50 °C, α 11e-6: +12.0 µm
    const double bore = 36.50e-3 * (1.0 + 11e-6 * 30.0);
    const double piston = (36.50e-3 - 25e-6) * (1.0 + 21e-6 * 40.0);
    const auto hot = engine::SkirtConfigFromCase(c);
    QVERIFY(std::abs(hot.geometry.radius - piston) < 1e-15);
    QVERIFY(std::abs(hot.geometry.radial_clearance - (bore - piston)) < 1e-15);
    QVERIFY(std::abs(hot.geometry.radial_clearance - 6.4e-6) < 0.05e-6);  // 25 − 30.6 + 12.0 µm
    QCOMPARE(engine::DerivedNote(c, "skirt.cold_clearance"),
             std::string("hot: 6.41 µm (cold 25.00 µm)"));
    // Values that stand for a choice say which (the editor showed a bare "0 GPa", "1 –").
    engine::EngineCase choices = c;
    choices.lubricant.bulk_modulus = 0.0;
    QCOMPARE(engine::DerivedNote(choices, "lubricant.bulk_modulus"),
             std::string("0: an incompressible oil"));
    choices.lubricant.bulk_modulus = 1.7e9;
    QCOMPARE(engine::DerivedNote(choices, "lubricant.bulk_modulus"), std::string());
    choices.solver.error_estimate = 1;
    QCOMPARE(engine::DerivedNote(choices, "solver.error_estimate"), std::string("on"));
    choices.solver.error_estimate = 0;
    QCOMPARE(engine::DerivedNote(choices, "solver.error_estimate"), std::string("off"));
    c.big_end.journal_temperature = 393.15;
    c.big_end.bearing_temperature = 373.15;
    const double hot_big_end = 15.00e-3 * (1.0 + 12e-6 * 80.0) - 14.95e-3 * (1.0 + 12e-6 * 100.0);
    QVERIFY(std::abs(engine::BearingConfigFromCase(c).geometry.radial_clearance - hot_big_end) <
            1e-15);
    // The piston 20 K hotter closes the skirt clearance (an Al piston in an iron bore needs a
    // larger cold clearance to run hot).
    c.skirt.piston_temperature = 353.15;
    try {
      engine::CheckCaseConsistency(c);
      QFAIL("no error for a closed clearance");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("skirt.piston_temperature"));
      QVERIFY2(std::string(e.what()).find("liner_temperature") != std::string::npos, e.what());
      QVERIFY2(std::string(e.what()).find("hot skirt clearance is -") != std::string::npos,
               e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestCaseFile)
#include "test_case_file.moc"
