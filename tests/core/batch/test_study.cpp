// Design studies in core: the study file's checks (every bad key, path, level and combination
// named with the file and the key), the three designs (factorial order and size, the Latin
// hypercube's one-point-per-stratum property and its seed, one-at-a-time around the base case),
// the points' cases through the case reader, the canonical study.json, a point folder's state
// as summary.json and the folder lock tell it, and the main effects, the ranking and the figure
// keys of the tables and plots (on rows made by hand).
#include <QtTest>

#include <QTemporaryDir>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/base/input_error.hpp"
#include "core/batch/study.hpp"
#include "core/engine/case_schema.hpp"
#include "core/io/output_files.hpp"
#include "core/io/run_comparison.hpp"
#include "core/io/run_summary.hpp"

using namespace filmdyn;
using batch::ParseStudy;
using batch::Study;

namespace {

// The InputError's message of parsing `text`, or "" when it parses.
std::string ErrorOf(const std::string& text) {
  try {
    ParseStudy(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// One row per design point of `s`, done, without figures.
std::vector<batch::StudyRow> DoneRows(const Study& s) {
  std::vector<batch::StudyRow> rows;
  for (const batch::StudyPoint& p : batch::DesignPoints(s, engine::EngineCase{})) {
    batch::StudyRow r;
    r.point = p;
    r.state = batch::PointState::kDone;
    r.figures.assign(io::ComparisonFigures().size(), std::nullopt);
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

class TestStudy : public QObject {
  Q_OBJECT
 private slots:
  void badStudiesAreRefusedNamingTheKey() {
    const std::string ok =
        R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "levels": [2000, 4000]}]})";
    QCOMPARE(ErrorOf(ok), std::string());
    struct Case {
      const char* text;
      const char* names;
    };
    const std::string deep = R"({"design": "full-factorial", "factors": )" + std::string(20, '[') +
                             std::string(20, ']') + "}";
    const Case cases[] = {
        {"not json", "s.json = not a valid JSON file"},
        // A repeated key would silently keep the last value; nesting is bounded (300 000 levels
        // crashed the reader's recursion).
        {R"({"design": "full-factorial", "design": "one-at-a-time", "factors": []})",
         "s.json: design = given twice: a key appears once in its object"},
        {R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "path": "operating.rpm", "levels": [1]}]})",
         "s.json: factors[0].path = given twice"},
        {deep.c_str(), "s.json = nested deeper than 16 levels: a study file is a few levels deep"},
        {R"({"design": "full-factorial", "factor": []})", "s.json: factor"},
        {R"({"design": "random", "factors": []})", "s.json: design"},
        {R"({"factors": [{"path": "operating.rpm", "levels": [1]}]})",
         "s.json: design = (missing)"},
        {R"({"design": "full-factorial", "factors": []})", "s.json: factors"},
        {R"({"design": "full-factorial", "factors": [{"path": "skirt.nope", "levels": [1]}]})",
         "s.json: factors[0].path = \"skirt.nope\": is not a case field"},
        {R"({"design": "full-factorial", "factors": [{"path": "name", "levels": [1]}]})",
         "cannot be a factor"},
        {R"({"design": "full-factorial", "factors": [{"path": "lubricant.viscosity", "levels": [0.01, -1]}]})",
         "s.json: factors[0].levels[1] (lubricant.viscosity)"},
        {R"({"design": "full-factorial", "factors": [{"path": "big_end.mesh_z", "levels": [8.5]}]})",
         "factors[0].levels[0] = 8.5: must be a whole number"},
        // A level that is no number names the field and its range too.
        {R"({"design": "full-factorial", "factors": [{"path": "skirt.oil_film", "levels": [1e-5, null]}]})",
         "s.json: factors[0].levels[1] (skirt.oil_film) = null: must be a finite number in "
         "[1e-09, "},
        {R"({"design": "full-factorial", "factors": [{"path": "big_end.mesh_z", "levels": ["8"]}]})",
         "s.json: factors[0].levels[0] (big_end.mesh_z) = \"8\": must be an integer in ["},
        // A number beyond a double's range is bad JSON for us, named with the file.
        {R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "levels": [1e999]}]})",
         "s.json = not a valid JSON file"},
        {R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "range": [1000, 2000]}]})",
         "a range needs \"count\""},
        {R"({"design": "latin-hypercube", "points": 5, "factors": [{"path": "operating.rpm", "range": [1000, 2000], "count": 3}]})",
         "factors[0].count"},
        {R"({"design": "latin-hypercube", "factors": [{"path": "operating.rpm", "range": [1000, 2000]}]})",
         "s.json: points = (missing)"},
        {R"({"design": "full-factorial", "seed": 3, "factors": [{"path": "operating.rpm", "levels": [1000]}]})",
         "s.json: seed"},
        {R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "range": [3000, 2000], "count": 2}]})",
         "must have low < high"},
        {R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "levels": [1000, 1000]}]})",
         "factors[0].levels[1] = 1000: is given twice"},
        {R"({"design": "full-factorial", "factors": [{"path": "model", "levels": ["skirt-lbrbe", "fast"]}]})",
         "factors[0].levels[1] = \"fast\""},
        {R"({"design": "full-factorial", "factors": [{"path": "model", "levels": ["ideal"]}, {"path": "skirt.model", "levels": ["ideal"]}]})",
         "factors[1].path = \"skirt.model\": is already a factor"},
        {R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "levels": [1000, 2000]}, {"path": "operating.rpm", "levels": [3000]}]})",
         "is already a factor"},
        {R"({"design": "full-factorial", "factors": [
              {"path": "operating.rpm", "range": [1000, 6000], "count": 100},
              {"path": "lubricant.viscosity", "range": [0.01, 0.03], "count": 100},
              {"path": "big_end.mesh_z", "range": [8, 100], "count": 20}]})",
         "too large"},
        {R"({"design": "full-factorial", "time_limit_s": -1, "factors": [{"path": "operating.rpm", "levels": [1000]}]})",
         "s.json: time_limit_s = -1"},
    };
    for (const Case& c : cases) {
      const std::string error = ErrorOf(c.text);
      QVERIFY2(Contains(error, c.names),
               qPrintable(QString::fromStdString("expected '" + std::string(c.names) + "' in '" +
                                                 error + "' for " + c.text)));
    }
  }

  void fullFactorialVariesTheLastFactorFastest() {
    const Study s = ParseStudy(R"({"design": "full-factorial", "factors": [
        {"path": "model", "levels": ["only-lbrbe", "ideal"]},
        {"path": "operating.rpm", "range": [2000, 6000], "count": 3}]})",
                               "s.json");
    const auto points = batch::DesignPoints(s, engine::EngineCase{});
    QCOMPARE(points.size(), std::size_t(6));
    const char* expected[6][2] = {{"only-lbrbe", "2000"}, {"only-lbrbe", "4000"},
                                  {"only-lbrbe", "6000"}, {"ideal", "2000"},
                                  {"ideal", "4000"},      {"ideal", "6000"}};
    for (std::size_t k = 0; k < 6; ++k) {
      QCOMPARE(points[k].number, int(k + 1));
      QCOMPARE(points[k].values[0], std::string(expected[k][0]));
      QCOMPARE(points[k].values[1], std::string(expected[k][1]));
    }
    QCOMPARE(points[2].folder, std::string("point-0003"));
    QCOMPARE(*points[4].numbers[1], 4000.0);
    QVERIFY(!points[4].numbers[0]);
  }

  void latinHypercubePutsOnePointInEachStratumAndFollowsTheSeed() {
    auto study = [](int seed) {
      return ParseStudy(R"({"design": "latin-hypercube", "points": 20, "seed": )" +
                            std::to_string(seed) + R"(, "factors": [
          {"path": "lubricant.viscosity", "range": [0.01, 0.03]},
          {"path": "big_end.mesh_z", "range": [8, 28]},
          {"path": "model", "levels": ["ideal", "only-lbrbe"]}]})",
                        "s.json");
    };
    const auto a = batch::DesignPoints(study(7), engine::EngineCase{});
    const auto b = batch::DesignPoints(study(7), engine::EngineCase{});
    const auto c = batch::DesignPoints(study(8), engine::EngineCase{});
    QCOMPARE(a.size(), std::size_t(20));
    std::set<int> strata;
    int only_lbrbe = 0;
    bool differs = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      QCOMPARE(a[k].values, b[k].values);  // the same seed: the same design, value for value
      differs = differs || a[k].values != c[k].values;
      const double mu = *a[k].numbers[0];
      QVERIFY(mu >= 0.01 && mu <= 0.03);
      strata.insert(int(std::floor((mu - 0.01) / 0.02 * 20)));
      const double mesh = *a[k].numbers[1];
      QCOMPARE(mesh, std::round(mesh));  // an integer field: whole values
      QVERIFY(mesh >= 8 && mesh <= 28);
      only_lbrbe += a[k].values[2] == "only-lbrbe";
    }
    QCOMPARE(strata.size(), std::size_t(20));  // one point in each of the 20 strata
    QCOMPARE(only_lbrbe, 10);                  // a two-level factor: half the strata each
    QVERIFY(differs);
  }

  void oneAtATimeStartsAtTheBaseCase() {
    const Study s = ParseStudy(R"({"design": "one-at-a-time", "factors": [
        {"path": "operating.rpm", "levels": [2000, 4000, 6000]},
        {"path": "lubricant.viscosity", "levels": [0.01, 0.03]}]})",
                               "s.json");
    engine::EngineCase base;
    base.operating.rpm = 4000;
    base.lubricant.viscosity = 0.02;
    const auto points = batch::DesignPoints(s, base);
    // The base, then rpm 2000 and 6000 (4000 is the base), then μ 0.01 and 0.03.
    QCOMPARE(points.size(), std::size_t(5));
    QCOMPARE(points[0].values, (std::vector<std::string>{"4000", "0.02"}));
    QCOMPARE(points[1].values, (std::vector<std::string>{"2000", "0.02"}));
    QCOMPARE(points[2].values, (std::vector<std::string>{"6000", "0.02"}));
    QCOMPARE(points[3].values, (std::vector<std::string>{"4000", "0.01"}));
    QCOMPARE(points[4].values, (std::vector<std::string>{"4000", "0.03"}));
  }

  void pointsAreCasesCheckedByTheCaseReader() {
    const Study s = ParseStudy(R"({"design": "full-factorial",
        "set": {"solver.max_cycles": 3},
        "factors": [{"path": "model", "levels": ["only-skirt", "ideal"]},
                    {"path": "geometry.rod_length", "levels": [0.14, 0.03]}]})",
                               "s.json");
    const auto points = batch::DesignPoints(s, batch::LoadStudyBase(s).value);
    const io::LoadedCase first = batch::LoadPointCase(s, points[0]);
    QCOMPARE(first.value.solver.max_cycles, 3);
    QCOMPARE(first.value.geometry.rod_length, 0.14);
    QCOMPARE(engine::ModelName(engine::ModelOfCase(first.value)), std::string("only-skirt"));
    QCOMPARE(engine::ModelName(engine::ModelOfCase(batch::LoadPointCase(s, points[2]).value)),
             std::string("ideal"));
    // A rod shorter than the crank radius: the rule between fields, named with the point.
    try {
      batch::LoadPointCase(s, points[1]);
      QFAIL("a rod shorter than the crank was accepted");
    } catch (const InputError& e) {
      const std::string text = e.what();
      QVERIFY2(Contains(text, "point 2 (model = only-skirt, geometry.rod_length = 0.03)"),
               e.what());
      QVERIFY2(Contains(text, "geometry.rod_length"), e.what());
    }
  }

  // The changes every point shares ("set"): the run model by its name (both joints' models, as
  // for a factor), a list field as a JSON list, and every error named with the file and the
  // set's key — a value out of range when the file is read, an unknown path when the base case
  // is built (not as the command line's --set).
  void setTakesTheModelAndListsAndNamesItsErrors() {
    const Study s = ParseStudy(R"({"design": "full-factorial",
        "set": {"model": "only-lbrbe", "big_end.supply": "pin_holes",
                "big_end.supply_hole_angles": [0, 3.1], "skirt.oil_film": 1e-5},
        "factors": [{"path": "operating.rpm", "levels": [2000, 4000]}]})",
                               "s.json");
    const engine::EngineCase base = batch::LoadStudyBase(s).value;
    QCOMPARE(engine::ModelName(engine::ModelOfCase(base)), std::string("only-lbrbe"));
    QCOMPARE(base.big_end.supply_hole_angles, (std::vector<double>{0.0, 3.1}));
    QCOMPARE(base.skirt.oil_film, 1e-5);
    const auto points = batch::DesignPoints(s, base);
    QCOMPARE(engine::ModelName(engine::ModelOfCase(batch::LoadPointCase(s, points[1]).value)),
             std::string("only-lbrbe"));
    // study.json writes the list back as a list, and reads it again the same.
    const std::string text = batch::StudyJson(s);
    const auto written = nlohmann::json::parse(text)["set"]["big_end.supply_hole_angles"];
    QVERIFY2(written == nlohmann::json::parse("[0, 3.1]"), text.c_str());
    QCOMPARE(batch::StudyJson(ParseStudy(text, "study.json")), text);
    // study.md says what every point ran with besides its factors.
    const std::string md = batch::StudyMarkdown(s, DoneRows(s), "");
    QVERIFY2(Contains(md,
                      "Changed in the base case for every point: `big_end.model = lubricated`, "
                      "`big_end.supply = pin_holes`, `big_end.supply_hole_angles = [0,3.1]`, "
                      "`skirt.model = ideal`, `skirt.oil_film = 1e-05`."),
             md.c_str());
    // The same from the study folder's copy of the file (its "set" a JSON object, in key order).
    QCOMPARE(batch::StudyMarkdown(ParseStudy(text, "s.json"), DoneRows(s), ""), md);
    QVERIFY(!Contains(batch::StudyMarkdown(ParseStudy(R"({"design": "full-factorial",
        "factors": [{"path": "operating.rpm", "levels": [2000]}]})",
                                                      "s.json"),
                                           {}, ""),
                      "Changed in the base case"));

    const struct {
      const char* set;
      const char* names;
    } refused[] = {
        {R"({"skirt.oil_film": -1})", "s.json: set.skirt.oil_film = -1: must be a finite number"},
        {R"({"big_end.mesh_z": 8.5})", "s.json: set.big_end.mesh_z = 8.5: must be a whole number"},
        {R"({"model": "fast"})", "s.json: set.model = \"fast\""},
        {R"({"model": 2})", "s.json: set.model = 2: must be a run model's name"},
        {R"({"big_end.supply_hole_angles": [0, "a"]})",
         "s.json: set.big_end.supply_hole_angles[1]"},
        {R"({"skirt.oil_film": [1e-5]})", "s.json: set.skirt.oil_film = [1e-05]: must be a number"},
        // A list's element out of its field's range, named in the file.
        {R"({"big_end.supply_hole_angles": [0, 10]})",
         "s.json: set.big_end.supply_hole_angles[1] = 10: must be a finite number in ["},
    };
    for (const auto& c : refused) {
      const std::string error =
          ErrorOf(std::string(R"({"design": "full-factorial", "set": )") + c.set +
                  R"(, "factors": [{"path": "operating.rpm", "levels": [2000]}]})");
      QVERIFY2(Contains(error, c.names), (error + " for " + c.set).c_str());
    }
    // A path the case has not: found when the base case is built, named as the file's.
    const Study unknown = ParseStudy(R"({"design": "full-factorial", "set": {"skirt.nope": 1},
        "factors": [{"path": "operating.rpm", "levels": [2000]}]})",
                                     "s.json");
    try {
      batch::LoadStudyBase(unknown);
      QFAIL("an unknown path in set was accepted");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("s.json: set.skirt.nope"));
      QVERIFY2(Contains(e.allowed(), "no such field"), e.what());
    }
    // A rule between fields broken by a set entry (a hole wider than the bearing): the set's.
    const Study wide = ParseStudy(R"({"design": "full-factorial", "set": {"model": "only-lbrbe",
        "big_end.supply": "pin_holes", "big_end.supply_hole_diameter": 0.03},
        "factors": [{"path": "operating.rpm", "levels": [2000]}]})",
                                  "s.json");
    try {
      batch::LoadStudyBase(wide);
      QFAIL("a supply hole wider than the bearing was accepted");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("s.json: set.big_end.supply_hole_diameter"));
      QVERIFY2(Contains(e.allowed(), "big_end.width"), e.what());
    }
  }

  void studyJsonIsCanonical() {
    const Study s = ParseStudy(R"({"name": "clearance", "design": "latin-hypercube",
        "points": 4, "seed": 11, "set": {"solver.max_cycles": 3, "skirt.model": "ideal"},
        "factors": [{"path": "skirt.cold_clearance", "range": [2e-5, 4e-5]},
                    {"path": "model", "levels": ["ideal", "only-lbrbe"]}]})",
                               "/tmp/s.json");
    const std::string text = batch::StudyJson(s);
    const Study again = ParseStudy(text, "/tmp/study.json");
    QCOMPARE(batch::StudyJson(again), text);
    QCOMPARE(again.points, 4);
    QCOMPARE(again.seed, std::uint64_t(11));
    QCOMPARE(again.base_overrides.size(), std::size_t(2));
    const auto a = batch::DesignPoints(s, engine::EngineCase{});
    const auto b = batch::DesignPoints(again, engine::EngineCase{});
    for (std::size_t k = 0; k < a.size(); ++k) QCOMPARE(a[k].values, b[k].values);
  }

  void aPointFolderSaysWhereItIs() {
    QTemporaryDir dir;
    const std::filesystem::path folder = dir.path().toStdString() + "/point-0001";
    QCOMPARE(batch::ReadPointState(folder), batch::PointState::kPending);
    std::filesystem::create_directories(folder);
    auto write = [&](const std::string& status) {
      io::RunSummary summary;
      summary.model = "ideal";
      summary.rpm = 2000;
      summary.status = status;
      summary.message = "why: " + status;
      io::WriteSummaryJson(folder / "summary.json", summary);
    };
    write("completed");
    QCOMPARE(batch::ReadPointState(folder), batch::PointState::kDone);
    write("not-converged");
    QCOMPARE(batch::ReadPointState(folder), batch::PointState::kDone);
    write("failed");
    std::string reason;
    QCOMPARE(batch::ReadPointState(folder, &reason), batch::PointState::kFailed);
    QCOMPARE(reason, std::string("why: failed"));
    write("time-limit");
    QCOMPARE(batch::ReadPointState(folder), batch::PointState::kIncomplete);
    write("running");
    // Nobody holds the lock: a run that was killed.
    QCOMPARE(batch::ReadPointState(folder, &reason), batch::PointState::kIncomplete);
    QVERIFY(Contains(reason, "stopped before it wrote its results"));
    {
      const io::OutputFolder held(folder, io::OutputFolder::Reuse::kReplace, "--out");
      write("running");
      QCOMPARE(batch::ReadPointState(folder), batch::PointState::kRunning);
    }
    std::ofstream(folder / "summary.json") << "{ broken";
    QCOMPARE(batch::ReadPointState(folder, &reason), batch::PointState::kFailed);
    QVERIFY(!reason.empty());
  }

  void mainEffectsAndRankingFromRowsByHand() {
    // Model × rpm, the rpm levels not in order: ideal points have no big-end figures, point 3
    // failed, point 6 stopped early with a figure that must not count.
    const Study s = ParseStudy(R"({"design": "full-factorial", "factors": [
        {"path": "model", "levels": ["ideal", "only-lbrbe"]},
        {"path": "operating.rpm", "levels": [4000, 2000, 6000]}]})",
                               "s.json");
    const std::size_t fpl = batch::StudyFigureIndex("mean_bearing_fpl[W]");
    const std::size_t moft = batch::StudyFigureIndex("min_bearing_moft[m]");
    QCOMPARE(io::ComparisonFigures()[fpl].key, std::string("mean_bearing_fpl[W]"));
    std::vector<batch::StudyRow> rows = DoneRows(s);
    QCOMPARE(rows.size(), std::size_t(6));
    QCOMPARE(rows[4].point.values, (std::vector<std::string>{"only-lbrbe", "2000"}));
    rows[2].state = batch::PointState::kFailed;                    // ideal, 6000
    rows[3].figures[fpl] = 200.0, rows[3].figures[moft] = 1.5e-6;  // only-lbrbe, 4000
    rows[4].figures[fpl] = 100.0, rows[4].figures[moft] = 2.0e-6;  // only-lbrbe, 2000
    rows[5].figures[fpl] = 999.0;                                  // only-lbrbe, 6000
    rows[5].state = batch::PointState::kIncomplete;

    const std::vector<batch::MainEffect> effects = batch::MainEffects(s, rows);
    QCOMPARE(effects.size(), std::size_t(2));
    const batch::MainEffect& model = effects[0];
    QCOMPARE(model.factor, std::size_t(0));
    QCOMPARE(model.levels.size(), std::size_t(2));
    QCOMPARE(model.levels[0].label, std::string("ideal"));
    QVERIFY(!model.levels[0].value);
    QCOMPARE(model.levels[0].points, 2);  // points 1 and 2 (3 failed)
    QVERIFY(!model.levels[0].means[fpl]);
    QCOMPARE(model.levels[1].label, std::string("only-lbrbe"));
    QCOMPARE(model.levels[1].points, 2);              // points 4 and 5 (6 incomplete)
    QCOMPARE(*model.levels[1].means[fpl], 150.0);     // (200 + 100) / 2
    QCOMPARE(*model.levels[1].means[moft], 1.75e-6);  // (1.5 + 2.0) / 2 µm
    const batch::MainEffect& rpm = effects[1];
    QCOMPARE(rpm.factor, std::size_t(1));
    QCOMPARE(rpm.levels.size(), std::size_t(3));  // in the study's order: 4000, 2000, 6000
    QCOMPARE(rpm.levels[0].label, std::string("4000"));
    QCOMPARE(*rpm.levels[0].value, 4000.0);
    QCOMPARE(rpm.levels[0].points, 2);           // points 1 and 4
    QCOMPARE(*rpm.levels[0].means[fpl], 200.0);  // point 4 alone has it
    QCOMPARE(*rpm.levels[1].means[fpl], 100.0);  // point 5
    QCOMPARE(rpm.levels[2].label, std::string("6000"));
    QCOMPARE(rpm.levels[2].points, 0);  // failed and incomplete only
    QVERIFY(!rpm.levels[2].means[fpl]);

    // Best first, done points with the figure only.
    QCOMPARE(batch::RankedPoints(rows, fpl, false), (std::vector<std::size_t>{4, 3}));
    QCOMPARE(batch::RankedPoints(rows, fpl, true), (std::vector<std::size_t>{3, 4}));
    QCOMPARE(batch::RankedPoints(rows, moft, true), (std::vector<std::size_t>{4, 3}));
    // Equal values keep the order of the rows.
    rows[4].figures[fpl] = 200.0;
    QCOMPARE(batch::RankedPoints(rows, fpl, false), (std::vector<std::size_t>{3, 4}));
    QCOMPARE(batch::RankedPoints(rows, fpl, true), (std::vector<std::size_t>{3, 4}));

    // The default ranking figure: big-end friction power, the skirt's when no point has one.
    QCOMPARE(batch::DefaultRankFigure(rows), fpl);
    rows[3].figures[fpl].reset();
    rows[4].figures[fpl].reset();
    QCOMPARE(batch::DefaultRankFigure(rows), batch::StudyFigureIndex("mean_skirt_fpl[W]"));

    // A range sampled continuously has no main effects.
    const Study lhs = ParseStudy(R"({"design": "latin-hypercube", "points": 4, "factors": [
        {"path": "operating.rpm", "range": [2000, 6000]},
        {"path": "model", "levels": ["ideal", "only-lbrbe"]}]})",
                                 "s.json");
    const std::vector<batch::MainEffect> sampled = batch::MainEffects(lhs, {});
    QCOMPARE(sampled.size(), std::size_t(1));
    QCOMPARE(sampled[0].factor, std::size_t(1));
    QCOMPARE(sampled[0].levels[1].points, 0);

    // One at a time (base: 6000 rpm, ideal): 1 the base, 2–3 rpm varied, 4 the model varied. The
    // rpm's 6000 level is the base point alone: point 4 holds 6000 rpm too, but varies the model,
    // whose effect must not enter the rpm's line (nor points 2–3 the model's).
    const Study oat = ParseStudy(R"({"design": "one-at-a-time", "factors": [
        {"path": "operating.rpm", "levels": [2000, 4000, 6000]},
        {"path": "model", "levels": ["ideal", "only-lbrbe"]}]})",
                                 "s.json");
    std::vector<batch::StudyRow> oat_rows = DoneRows(oat);
    QCOMPARE(oat_rows.size(), std::size_t(4));
    QCOMPARE(oat_rows[0].point.values, (std::vector<std::string>{"6000", "ideal"}));
    QCOMPARE(oat_rows[3].point.values, (std::vector<std::string>{"6000", "only-lbrbe"}));
    for (std::size_t k = 0; k < 4; ++k) oat_rows[k].figures[fpl] = 100.0 * double(k + 1);
    const std::vector<batch::MainEffect> oat_effects = batch::MainEffects(oat, oat_rows);
    QCOMPARE(oat_effects.size(), std::size_t(2));
    QCOMPARE(oat_effects[0].levels[2].label, std::string("6000"));
    QCOMPARE(oat_effects[0].levels[2].points, 1);
    QCOMPARE(*oat_effects[0].levels[2].means[fpl], 100.0);  // not (100 + 400) / 2
    QCOMPARE(*oat_effects[0].levels[0].means[fpl], 200.0);  // 2000 rpm: point 2
    QCOMPARE(oat_effects[1].levels[0].points, 1);           // ideal: the base alone
    QCOMPARE(*oat_effects[1].levels[0].means[fpl], 100.0);  // not (100 + 200 + 300) / 3
    QCOMPARE(*oat_effects[1].levels[1].means[fpl], 400.0);
  }

  // A figure a point's run has but the comparison leaves out (a peak film pressure that is a
  // spike between output samples: io::ComparisonRow::notes) is an empty cell, and the note says
  // why: study.csv's last column (quoted when it holds a comma), study.md below the table.
  void notesOfLeftOutFiguresReachStudyCsvAndMd() {
    const Study s = ParseStudy(R"({"design": "full-factorial", "factors": [
        {"path": "operating.rpm", "levels": [2000, 6000]}]})",
                               "s.json");
    std::vector<batch::StudyRow> rows = DoneRows(s);
    rows[1].notes = {"peak big-end film pressure left out: a spike, here"};
    std::ostringstream csv;
    batch::WriteStudyCsv(csv, s, rows);
    const std::string text = csv.str();
    QVERIFY2(Contains(text, ",reason,notes\n"), text.c_str());
    QVERIFY2(Contains(text, ",,\"peak big-end film pressure left out: a spike, here\"\n"),
             text.c_str());
    QVERIFY2(Contains(text.substr(0, text.find("\n2,") + 1), ",,\n"),
             text.c_str());  // point 1: none
    const std::string md = batch::StudyMarkdown(s, rows, "");
    QVERIFY2(
        Contains(md, "Notes:\n\n- point 2: peak big-end film pressure left out: a spike, here\n"),
        md.c_str());
    rows[1].notes.clear();
    QVERIFY(!Contains(batch::StudyMarkdown(s, rows, ""), "Notes:"));
  }

  void anUnknownFigureKeyListsTheKeys() {
    try {
      batch::StudyFigureIndex("mean_fpl[W]");
      QFAIL("an unknown figure key was accepted");
    } catch (const InputError& e) {
      QCOMPARE(e.field(), std::string("--rank-by"));
      QCOMPARE(e.value(), std::string("mean_fpl[W]"));
      QVERIFY2(Contains(e.allowed(), "must be one of: max_abs_piston_lateral[m], "), e.what());
      for (const io::ComparisonFigure& figure : io::ComparisonFigures())
        QVERIFY2(Contains(e.allowed(), figure.key), e.what());
    }
    // study.md refuses it too (it was silently left out before).
    const Study s = ParseStudy(
        R"({"design": "full-factorial", "factors": [{"path": "operating.rpm", "levels": [2000]}]})",
        "s.json");
    QVERIFY_THROWS_EXCEPTION(InputError, batch::StudyMarkdown(s, {}, "nope"));
    QVERIFY(Contains(batch::StudyMarkdown(s, {}, ""), "# Study: s"));
  }
};

QTEST_GUILESS_MAIN(TestStudy)
#include "test_study.moc"
