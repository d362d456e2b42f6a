// The real `filmdyn` executable, run as a user would: help, version, dispatching, and clear
// one-line errors with exit code 2 for bad input.
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include <sys/types.h>
#include <csignal>

#include "app/cli/command.hpp"
#include "app/cli/dispatcher.hpp"
#include "core/base/input_error.hpp"
#include "core/io/field_series.hpp"

#include "run_filmdyn.hpp"
#include "tests/comma_locale.hpp"

namespace {

Result Run(const QStringList& arguments,
           const QProcessEnvironment& env = QProcessEnvironment::systemEnvironment(),
           int timeout_ms = 60000) {
  return RunFilmdyn(arguments, timeout_ms, env);
}

}  // namespace

class TestCli : public QObject {
  Q_OBJECT
 private slots:
  // A user whose locale writes decimals with a comma (LANG=de_DE.UTF-8, which Qt hands to the C
  // library): a run reads the shipped CalculiX compliance (it was refused: "must be a finite
  // number") and writes its numbers with a point, as under "C".
  void aRunUnderACommaLocaleReadsAndWritesAsInC() {
    QTemporaryDir dir;
    const auto locale =
        filmdyn::testing::FindCommaDecimalLocale(dir.filePath("locales").toStdString());
    QVERIFY2(locale, filmdyn::testing::kNoCommaLocale);
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    if (!locale->locpath.empty()) env.insert("LOCPATH", QString::fromStdString(locale->locpath));
    env.insert("LANG", QString::fromStdString(locale->name));
    env.insert("LC_ALL", QString::fromStdString(locale->name));
    const QString out = dir.filePath("run");
    const Result r =
        Run({"run", "--model", "only-lbrbe", "--set", "big_end.compliance=imported", "--set",
             "big_end.compliance_file=" FILMDYN_SOURCE_DIR
             "/examples/calculix-bearing-shell/shell_compliance.mtx",
             "--set", "solver.error_estimate=0", "--time-limit", "1.5", "--no-fields", "--out", out,
             "--quiet"},
            env);
    // Completed, or stopped by the time limit with what it computed (exit 1): not refused (2).
    QVERIFY2(r.exit_code == 0 || r.exit_code == 1, qPrintable(r.err));
    QVERIFY2(!r.err.contains("must be a finite number"), qPrintable(r.err));
    QFile results(out + "/results.csv");
    QVERIFY(results.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(results.readAll()).split('\n', Qt::SkipEmptyParts);
    QVERIFY(lines.size() >= 2);
    const qsizetype columns = lines[0].count(',');
    for (qsizetype k = 1; k < lines.size(); ++k) {
      QCOMPARE(lines[k].count(','), columns);  // a decimal comma would add cells
    }
    QVERIFY2(lines[1].contains('.'), qPrintable(lines[1]));
  }

  void helpListsRegisteredCommands() {
    const Result result = Run({"--help"});
    QCOMPARE(result.exit_code, 0);
    QVERIFY(result.out.contains("Usage:"));
    QVERIFY(result.out.contains("versions"));
    // Every exit status the commands use is named (the calculators' 3 was not).
    for (const char* status : {"0 on success", "2 for bad input", "1 when a run", "3 when the"})
      QVERIFY2(result.out.contains(status), status);
  }

  void versionPrintsProjectVersion() {
    const Result result = Run({"--version"});
    QCOMPARE(result.exit_code, 0);
    QCOMPARE(result.out.trimmed(), QString("filmdyn ") + FILMDYN_VERSION);
  }

  void commandHelp() {
    const Result result = Run({"versions", "--help"});
    QCOMPARE(result.exit_code, 0);
    QVERIFY(result.out.contains("Usage: filmdyn versions"));
    QVERIFY(result.out.contains("--json"));
  }

  void versionsAsJson() {
    const Result result = Run({"versions", "--json"});
    QCOMPARE(result.exit_code, 0);
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(result.out.toUtf8(), &error);
    QCOMPARE(error.error, QJsonParseError::NoError);
    QCOMPARE(doc.object().value("FilmDyn").toString(), QString(FILMDYN_VERSION));
    QVERIFY(doc.object().value("VTK").toString().startsWith("9.1"));
  }

  void unknownCommandIsAOneLineError() {
    const Result result = Run({"frobnicate"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY(result.err.contains("unknown command 'frobnicate'"));
    QCOMPARE(result.err.trimmed().count('\n'), 0);
  }

  void unknownOptionNamesTheOptionAndTheAllowedOnes() {
    const Result result = Run({"versions", "--jsn"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY(result.err.contains("--jsn"));
    QVERIFY(result.err.contains("allowed: --json"));
  }

  void guiWithoutDisplayExplainsInsteadOfCrashing() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY");
    env.remove("QT_QPA_PLATFORM");
    const Result result = Run({}, env);
    QCOMPARE(result.exit_code, 1);
    QVERIFY(result.err.contains("no display"));
    QVERIFY(result.err.contains("filmdyn run"));
  }

  void runWritesTheOutputFolder() {
    QTemporaryDir dir;
    const QString out = dir.filePath("r");
    const Result result =
        Run({"run", "--model", "ideal", "--rpm", "2000", "--out", out, "--quiet"});
    QCOMPARE(result.exit_code, 0);
    QFile csv(out + "/results.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = csv.readAll().split('\n');
    QVERIFY(lines.first().startsWith("crank_angle[deg],time[s],piston_lateral[m],"));
    QVERIFY(lines.size() >= 720);
    QFile summary_file(out + "/summary.json");
    QVERIFY(summary_file.open(QIODevice::ReadOnly));
    const QJsonObject summary = QJsonDocument::fromJson(summary_file.readAll()).object();
    QCOMPARE(summary.value("model").toString(), QString("ideal"));
    QCOMPARE(summary.value("rpm").toDouble(), 2000.0);
    QVERIFY(summary.value("complete").toBool());
    // Plots rendered offscreen (no display needed): PNG decodes, SVG present.
    for (const char* plot : {"piston_lateral", "liner_forces", "bigend_forces"}) {
      QImage png(out + "/plots/" + plot + ".png");
      QVERIFY2(!png.isNull(), plot);
      QVERIFY(QFileInfo(out + "/plots/" + plot + ".svg").size() > 1000);
    }
  }

  void runRejectsBadInputNamingTheField() {
    Result result = Run({"run", "--model", "wobbly"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY(result.err.contains("wobbly"));
    result = Run({"run", "--set", "geometry.rod_mass=-1", "--model", "ideal"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("rod_mass"), qPrintable(result.err));
    result = Run({"run", "/nonexistent/case.json"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY(result.err.contains("/nonexistent/case.json"));
    // A Vogel law with no finite viscosity at the film's temperature (its exponent overflows):
    // refused before any folder is written, naming the temperature and the law's fields (it
    // reached the film solver as "skirt.viscosity = inf", a name no case has).
    QTemporaryDir dir;
    result = Run({"run", "--no-fields", "--out", dir.filePath("vogel"), "--set",
                  "lubricant.viscosity_model=vogel", "--set", "lubricant.vogel_a=1e-4", "--set",
                  "lubricant.vogel_b=100000", "--set", "lubricant.vogel_c=373"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("skirt.oil.temperature") &&
                 result.err.contains("lubricant.vogel_b") && result.err.contains("finite"),
             qPrintable(result.err));
    QVERIFY(!QFileInfo::exists(dir.filePath("vogel")));
  }

  void sweepRunsInParallelAndCompares() {
    QTemporaryDir dir;
    const QString out = dir.filePath("s");
    const Result result = Run({"sweep", "--models", "ideal", "--rpm", "1000,6000", "--jobs", "2",
                               "--set", "solver.max_cycles=3", "--out", out, "--quiet"});
    QCOMPARE(result.exit_code, 0);
    QFile csv(out + "/comparison.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).trimmed().split('\n');
    QCOMPARE(lines.size(), 3);  // header + two runs
    QVERIFY(lines[1].contains(",ideal,1000,completed,"));
    QVERIFY(lines[2].contains(",ideal,6000,completed,"));
    QVERIFY(result.out.contains("| ideal | 6000 | completed |"));
    // comparison.md says what the runs share: the case and the --set changes.
    QFile md(out + "/comparison.md");
    QVERIFY(md.open(QIODevice::ReadOnly));
    const QString report = QString::fromUtf8(md.readAll());
    QVERIFY2(report.contains("Case: the embedded default case; changed for every run: "
                             "`solver.max_cycles = 3`."),
             qPrintable(report));
    QVERIFY(!QImage(out + "/plots/bigend_forces.png").isNull());
    for (const char* rpm : {"1000", "6000"}) {
      const QString folder = out + "/zhao-shen-gasoline-ideal-" + rpm;
      QVERIFY2(QFileInfo::exists(folder + "/results.csv"), qPrintable(folder));
      QVERIFY(QFileInfo::exists(folder + "/plots/moft.png"));
    }

    // A run whose results cannot be written (the file's temporary name taken by a folder): its
    // row stays in the comparison, marked failed with the reason (it used to be left out), and
    // its summary says so.
    const QString blocked = out + "/zhao-shen-gasoline-ideal-6000";
    QVERIFY(QDir().mkpath(blocked + "/results.csv.tmp/x"));
    const Result again =
        Run({"sweep", "--models", "ideal", "--rpm", "1000,6000", "--jobs", "2", "--set",
             "solver.max_cycles=3", "--out", out, "--overwrite", "--quiet"});
    QVERIFY2(again.exit_code != 0, qPrintable(again.err));
    QFile csv2(out + "/comparison.csv");
    QVERIFY(csv2.open(QIODevice::ReadOnly));
    const QStringList rows = QString::fromUtf8(csv2.readAll()).trimmed().split('\n');
    QCOMPARE(rows.size(), 3);
    QVERIFY2(rows[2].contains(",ideal,6000,failed,") && rows[2].contains("results.csv"),
             qPrintable(rows[2]));
    QFile summary(blocked + "/summary.json");
    QVERIFY(summary.open(QIODevice::ReadOnly));
    QVERIFY(summary.readAll().contains("its results could not be written"));
  }

  // A run folder keeps the case it ran (case-as-run.json): its models, its speed, the cylinder
  // pressure it used (here blended between the case's 2000 and 4000 rpm curves) inline, and the
  // files it names by absolute paths. Running that file gives the same results, bit for bit.
  void runFolderKeepsTheCaseItRan() {
    QTemporaryDir dir;
    const QString first = dir.filePath("first"), again = dir.filePath("again");
    Result r = Run({"run", "--model", "ideal", "--rpm", "3500", "--set", "solver.max_cycles=3",
                    "--no-fields", "--out", first, "--quiet"});
    QVERIFY2(r.exit_code == 0, qPrintable(r.err));
    QFile file(first + "/case-as-run.json");
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QJsonObject c = QJsonDocument::fromJson(file.readAll()).object();
    QCOMPARE(c["operating"].toObject()["rpm"].toDouble(), 3500.0);
    QCOMPARE(c["skirt"].toObject()["model"].toString(), QString("ideal"));
    QCOMPARE(c["big_end"].toObject()["model"].toString(), QString("ideal"));
    QCOMPARE(c["solver"].toObject()["max_cycles"].toInt(), 3);
    const QJsonArray curves = c["pressure_curves"].toArray();
    QCOMPARE(curves.size(), 1);
    QCOMPARE(curves[0].toObject()["rpm"].toDouble(), 3500.0);
    QVERIFY(curves[0].toObject()["crank_angle_deg"].toArray().size() >= 72);
    r = Run({"run", first + "/case-as-run.json", "--no-fields", "--out", again, "--quiet"});
    QVERIFY2(r.exit_code == 0, qPrintable(r.err));
    for (const char* name : {"results.csv", "case-as-run.json"}) {
      QFile a(first + "/" + name), b(again + "/" + name);
      QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
      QVERIFY2(a.readAll() == b.readAll(), name);
    }

    // A compliance named relative to its case file: absolute in case-as-run.json, which is
    // written when the run starts (a run stopped at once keeps it).
    const QString shell = QString(FILMDYN_SOURCE_DIR) + "/examples/calculix-bearing-shell/";
    QVERIFY(QDir().mkpath(dir.filePath("engine")));
    for (const char* name : {"shell_compliance.mtx", "shell_compliance.nodes.csv"})
      QVERIFY(QFile::copy(shell + name, dir.filePath(QString("engine/") + name)));
    QFile own(dir.filePath("engine/case.json"));
    QVERIFY(own.open(QIODevice::WriteOnly));
    own.write(R"({"big_end": {"compliance": "imported",
                              "compliance_file": "shell_compliance.mtx"},
                  "pressure_curves": [{"rpm": 6000,
                                       "file": "../pressure/synthetic_6000rpm.csv"}]})");
    own.close();
    const QString stopped = dir.filePath("stopped");
    r = Run({"run", dir.filePath("engine/case.json"), "--model", "only-lbrbe", "--time-limit",
             "0.2", "--no-fields", "--out", stopped, "--quiet"});
    QVERIFY2(r.exit_code == 1, qPrintable(r.err));  // incomplete: the time limit
    // The reason line repeats the status of the first line.
    QVERIFY2(r.err.contains("filmdyn run: incomplete (time-limit): wall-time limit reached"),
             qPrintable(r.err));
    QFile kept(stopped + "/case-as-run.json");
    QVERIFY(kept.open(QIODevice::ReadOnly));
    const QString named = QJsonDocument::fromJson(kept.readAll())
                              .object()["big_end"]
                              .toObject()["compliance_file"]
                              .toString();
    QCOMPARE(QFileInfo(named).canonicalFilePath(),
             QFileInfo(dir.filePath("engine/shell_compliance.mtx")).canonicalFilePath());
    QVERIFY2(QFileInfo(named).isAbsolute(), qPrintable(named));

    // An input only the film's set-up can check (here the compliance's surface, shorter than the
    // skirt's film): exit 2 naming it, and the folder says the run failed and why, not
    // "running" (which reads as a run killed).
    const QString refused = dir.filePath("refused");
    r = Run({"run", "--model", "only-skirt", "--no-fields", "--out", refused, "--quiet", "--set",
             "skirt.compliance=imported", "--set",
             "skirt.compliance_file=" + QString(FILMDYN_SOURCE_DIR) +
                 "/examples/calculix-skirt-shell/skirt_compliance.mtx",
             "--set", "skirt.length=0.03", "--set",
             "skirt.profile_y=[0,0.0075,0.015,0.0225,0.03]"});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("FE surface"), qPrintable(r.err));
    QFile summary(refused + "/summary.json");
    QVERIFY(summary.open(QIODevice::ReadOnly));
    const QJsonObject s = QJsonDocument::fromJson(summary.readAll()).object();
    QCOMPARE(s["status"].toString(), QString("failed"));
    QCOMPARE(s["complete"].toBool(), false);
    QVERIFY2(s["message"].toString().contains("FE surface"), qPrintable(s["message"].toString()));
  }

  // Without --rpm a sweep runs at the speeds of the case's pressure curves (it used to take fixed
  // speeds, and a case whose curves did not cover 1000 rpm failed on a speed nobody asked for).
  void sweepWithoutSpeedsRunsAtTheCurvesSpeeds() {
    QTemporaryDir dir;
    const QString out = dir.filePath("s");
    const Result result = Run({"sweep", "--models", "ideal", "--set", "pressure_curves.0.rpm=1500",
                               "--set", "solver.max_cycles=2", "--out", out, "--quiet"});
    QVERIFY2(result.exit_code == 0, qPrintable(result.err));
    QFile csv(out + "/comparison.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).trimmed().split('\n');
    QCOMPARE(lines.size(), 5);  // header + the four curves' speeds, in order
    const char* speeds[] = {"1500", "2000", "4000", "6000"};
    for (int k = 0; k < 4; ++k) {
      QVERIFY2(lines[k + 1].contains(QString(",ideal,%1,completed,").arg(speeds[k])),
               qPrintable(lines[k + 1]));
    }
  }

  void sweepRejectsBadJobs() {
    const Result result = Run({"sweep", "--jobs", "0"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY(result.err.contains("--jobs"));
    // A --set of what the command sets for each run (it was replaced without a word).
    for (const auto& [argv, needle] :
         {std::pair{QStringList{"sweep", "--set", "operating.rpm=3000"},
                    "--set operating.rpm = 3000: is each run's speed in a sweep"},
          std::pair{QStringList{"sweep", "--models", "ideal", "--set", "skirt.model=lubricated"},
                    "--set skirt.model = lubricated: is set by each run's model"},
          std::pair{QStringList{"reproduce", "--set", "big_end.model=ideal"},
                    "--set big_end.model = ideal: is set by the paper's plan"}}) {
      const Result refused = Run(argv);
      QCOMPARE(refused.exit_code, 2);
      QVERIFY2(refused.err.contains(needle), qPrintable(refused.err));
    }
  }

  // An --out folder holding an earlier run is refused (exit 2 naming --out) unless --overwrite,
  // which removes FilmDyn's stale files (a fields/ file the new run does not write) and keeps
  // the user's.
  void runRefusesAnEarlierRunUnlessOverwrite() {
    QTemporaryDir dir;
    const QString out = dir.filePath("r");
    QCOMPARE(Run({"run", "--model", "ideal", "--out", out, "--quiet"}).exit_code, 0);
    QDir().mkpath(out + "/fields");
    QFile(out + "/fields/bearing.h5").open(QIODevice::WriteOnly);  // stale, from a film run
    QFile notes(out + "/notes.txt");
    QVERIFY(notes.open(QIODevice::WriteOnly));
    notes.close();
    Result result = Run({"run", "--model", "ideal", "--out", out, "--quiet"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("--out = " + out) && result.err.contains("--overwrite"),
             qPrintable(result.err));
    result = Run({"run", "--model", "ideal", "--out", out, "--quiet", "--overwrite"});
    QCOMPARE(result.exit_code, 0);
    QVERIFY(!QFileInfo::exists(out + "/fields/bearing.h5"));
    QVERIFY(QFileInfo::exists(out + "/notes.txt"));
    QVERIFY(QFileInfo::exists(out + "/results.csv"));
  }

  // A run stopped in its third (or, on a loaded machine, a later) cycle reports the one before,
  // the last whole one, with that cycle's film fields: one frame per results.csv row, at the crank
  // angle the row gives.
  void aRunStoppedInALaterCycleWritesTheReportedCyclesFields() {
    QTemporaryDir dir;
    const QString out = dir.filePath("r");
    QProcess run;
    run.start(FILMDYN_EXECUTABLE,
              {"run", "--out", out, "--model", "only-lbrbe", "--set", "big_end.mesh_theta=24",
               "--set", "big_end.mesh_z=4", "--set", "solver.error_estimate=0", "--set",
               "solver.steady_state_tolerance=1e-9", "--set", "solver.max_cycles=60"});
    QVERIFY(run.waitForStarted());
    // Into cycle 3 or later: the progress line is printed every 200 ms, and on an idle machine a
    // cycle of this mesh takes ~0.1 s, so "cycle 3/" itself may never be printed.
    QByteArray progress;
    const QRegularExpression later_cycle("cycle ([3-9]|[1-9][0-9])/");
    for (int k = 0; k < 1200 && !later_cycle.match(QString::fromUtf8(progress)).hasMatch(); ++k) {
      run.waitForReadyRead(100);
      progress += run.readAllStandardError();
    }
    QVERIFY2(later_cycle.match(QString::fromUtf8(progress)).hasMatch(),
             progress.right(300).constData());
    ::kill(static_cast<pid_t>(run.processId()), SIGTERM);
    QVERIFY(run.waitForFinished(60000));
    const QByteArray err = progress + run.readAllStandardError();
    QCOMPARE(run.exitCode(), 1);
    // The cycle it stopped in: the signal is sent on reading "cycle 3/", which a loaded machine
    // may deliver late.
    const QRegularExpressionMatch stopped =
        QRegularExpression("cancelled \\(cycle (\\d+),").match(QString::fromUtf8(err));
    QVERIFY2(stopped.hasMatch(), err.right(600).data());
    const int reported = stopped.captured(1).toInt() - 1;
    QVERIFY2(reported >= 2, err.right(600).data());
    QVERIFY2(err.contains(
                 QString("the results are cycle %1, the last whole one").arg(reported).toUtf8()),
             err.right(600).data());
    QVERIFY2(!err.contains("fields/ not written"), err.right(600).data());
    QFile summary(out + "/summary.json");
    QVERIFY(summary.open(QIODevice::ReadOnly));
    const QJsonObject s = QJsonDocument::fromJson(summary.readAll()).object();
    QCOMPARE(s.value("status").toString(), QString("cancelled"));
    QCOMPARE(s.value("reported_cycle").toInt(), reported);
    QFile csv(out + "/results.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    std::vector<double> row_angles;
    csv.readLine();  // the header; crank_angle[deg] is the first column
    while (!csv.atEnd()) row_angles.push_back(csv.readLine().split(',').front().toDouble());
    QCOMPARE(row_angles.size(), std::size_t(720));
    const filmdyn::io::FieldSeries fields =
        filmdyn::io::ReadFieldSeries((out + "/fields/bearing.xdmf").toStdString());
    QCOMPARE(fields.frames.size(), row_angles.size());
    for (std::size_t k = 0; k < row_angles.size(); ++k)
      QVERIFY(std::abs(fields.frames[k].crank_angle_deg - row_angles[k]) < 1e-6);
  }

  // A run whose film fails in its run-in writes the film where it failed: fields/ holds that one
  // step, results.csv's last row, and stderr says so (it used to write no fields/ at all).
  void aRunFailingInItsRunInWritesTheFilmWhereItFailed() {
    QTemporaryDir dir;
    const QString out = dir.filePath("r");
    QProcess run;
    run.start(
        FILMDYN_EXECUTABLE,
        {"run", "--out", out, "--model", "only-lbrbe", "--rpm", "6000", "--set",
         "big_end.mesh_theta=24", "--set", "big_end.mesh_z=4", "--set", "big_end.cavitation=jfo",
         "--set", "lubricant.viscosity=0.6e-3", "--set", "solver.error_estimate=0", "--quiet"});
    QVERIFY(run.waitForFinished(120000));
    const QByteArray err = run.readAllStandardError();
    QCOMPARE(run.exitCode(), 1);
    QVERIFY2(err.contains("journal touches the bearing") && err.contains("(run-in, at"),
             err.right(600).data());
    QVERIFY2(err.contains("fields/ holds one step, the film where the run failed in its run-in"),
             err.right(600).data());
    QFile csv(out + "/results.csv");
    QVERIFY(csv.open(QIODevice::ReadOnly));
    double last_angle = NAN;
    csv.readLine();  // the header; crank_angle[deg] is the first column
    while (!csv.atEnd()) last_angle = csv.readLine().split(',').front().toDouble();
    const filmdyn::io::FieldSeries fields =
        filmdyn::io::ReadFieldSeries((out + "/fields/bearing.xdmf").toStdString());
    QCOMPARE(fields.frames.size(), std::size_t(1));
    QVERIFY(std::abs(fields.frames.front().crank_angle_deg - last_angle) < 1e-6);
  }

  // A stop signal that arrives after the computing, while the files are written (a scheduler's
  // time limit can land there), lets the writing finish: the run is complete, its fields and
  // plots are there, exit 0. It used to kill the process half-way (exit 143, summary "running",
  // no plots, fields cut short).
  void aStopSignalWhileWritingLetsTheFilesFinish() {
    QTemporaryDir dir;
    const QString out = dir.filePath("r");
    QProcess run;
    run.start(FILMDYN_EXECUTABLE, {"run", "--out", out, "--quiet", "--model", "only-lbrbe", "--set",
                                   "big_end.mesh_theta=24", "--set", "big_end.mesh_z=4", "--set",
                                   "solver.error_estimate=0"});
    QVERIFY(run.waitForStarted());
    // results.csv is the first file written once the run has computed.
    for (int k = 0; k < 12000 && !QFile::exists(out + "/results.csv"); ++k) QTest::qWait(5);
    QVERIFY(QFile::exists(out + "/results.csv"));
    ::kill(static_cast<pid_t>(run.processId()), SIGTERM);
    QVERIFY(run.waitForFinished(60000));
    const QByteArray err = run.readAllStandardError();
    QCOMPARE(run.exitStatus(), QProcess::NormalExit);
    QVERIFY2(run.exitCode() == 0, err.right(600).constData());
    QVERIFY2(err.contains("a stop signal arrived while the results were being written"),
             err.right(600).constData());
    QFile summary(out + "/summary.json");
    QVERIFY(summary.open(QIODevice::ReadOnly));
    const QJsonObject s = QJsonDocument::fromJson(summary.readAll()).object();
    QCOMPARE(s.value("status").toString(), QString("completed"));
    QVERIFY(s.value("complete").toBool());
    QVERIFY(QFile::exists(out + "/fields/bearing.xdmf"));
    QVERIFY(QDir(out + "/plots").entryList({"*.png"}).size() > 3);
  }

  // A running run marks its folder "running" and locks it: a second writer is refused. SIGTERM
  // and SIGHUP stop it like Ctrl-C: partial results written, status "cancelled", exit 1 — never
  // an earlier run's "completed" left behind. A time limit on a mesh whose every step takes
  // seconds is honoured inside the step (it used to run on for minutes).
  void stopSignalsAndTimeLimitsEndARunWithItsPartialResults() {
    for (const int signal : {SIGTERM, SIGHUP}) {
      QTemporaryDir dir;
      const QString out = dir.filePath("r");
      QProcess run;
      run.start(FILMDYN_EXECUTABLE,
                {"run", "--out", out, "--no-fields", "--set", "solver.max_cycles=20"});
      QVERIFY(run.waitForStarted());
      QString status;
      for (int k = 0; k < 600 && status != "running"; ++k) {  // up to 60 s to start
        QTest::qWait(100);
        QFile summary(out + "/summary.json");
        if (summary.open(QIODevice::ReadOnly)) {
          status = QJsonDocument::fromJson(summary.readAll()).object().value("status").toString();
        }
      }
      QCOMPARE(status, QString("running"));
      const Result second = Run({"run", "--model", "ideal", "--out", out, "--overwrite"});
      QCOMPARE(second.exit_code, 2);
      QVERIFY2(second.err.contains("another FilmDyn run"), qPrintable(second.err));
      // Into the first cycle (its progress line says so; a loaded machine may take a while).
      QByteArray progress;
      for (int k = 0; k < 1200 && !progress.contains("cycle 1/"); ++k) {
        run.waitForReadyRead(100);
        progress += run.readAllStandardError();
      }
      QVERIFY2(progress.contains("cycle 1/"), progress.right(300).constData());
      QTest::qWait(300);
      QElapsedTimer stopping;
      stopping.start();
      ::kill(static_cast<pid_t>(run.processId()), signal);
      QVERIFY(run.waitForFinished(60000));
      qInfo("signal %d: exited %lld ms after the signal (results written)", signal,
            static_cast<long long>(stopping.elapsed()));
      QCOMPARE(run.exitStatus(), QProcess::NormalExit);
      QCOMPARE(run.exitCode(), 1);
      QFile summary(out + "/summary.json");
      QVERIFY(summary.open(QIODevice::ReadOnly));
      const QJsonObject s = QJsonDocument::fromJson(summary.readAll()).object();
      QCOMPARE(s.value("status").toString(), QString("cancelled"));
      QVERIFY(!s.value("complete").toBool());
      QFile csv(out + "/results.csv");
      QVERIFY(csv.open(QIODevice::ReadOnly));
      QVERIFY(csv.readAll().count('\n') >= 2);  // the header and the cycle's rows so far
      // The plots say in their legend that what they draw is incomplete.
      QFile chart(out + "/plots/moft.svg");
      QVERIFY(chart.open(QIODevice::ReadOnly));
      QVERIFY(chart.readAll().contains("(cancelled: incomplete)"));
    }
    QTemporaryDir dir;
    QElapsedTimer timer;
    timer.start();
    const Result limited =
        Run({"run", "--out", dir.filePath("big"), "--quiet", "--no-fields", "--time-limit", "1",
             "--set", "big_end.mesh_theta=2000", "--set", "big_end.mesh_z=200"},
            QProcessEnvironment::systemEnvironment(), 120000);
    qInfo("--time-limit 1 on a 2000 x 200 big-end mesh: exited after %lld ms",
          static_cast<long long>(timer.elapsed()));
    QCOMPARE(limited.exit_code, 1);
    QVERIFY2(limited.err.contains("wall-time limit reached"), qPrintable(limited.err));
  }

  void sweepRejectsTheSamePointTwice() {
    QTemporaryDir dir;
    const Result result = Run({"sweep", "--models", "ideal", "--rpm", "6000,3000,6000", "--out",
                               dir.filePath("s"), "--quiet"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("ideal at 6000 rpm") && result.err.contains("twice"),
             qPrintable(result.err));
  }

  // Hostile input files and values end in a one-line error naming the field (exit 2), never a
  // crash, a hang or an unbounded read; a case name cannot send the outputs out of results/.
  void hostileInputsAreInputErrors() {
    QTemporaryDir dir;
    const QString deep = dir.filePath("deep.json");
    {
      QFile file(deep);
      QVERIFY(file.open(QIODevice::WriteOnly));
      const int depth = 100000;
      file.write(QByteArray("{\"x\":").repeated(depth) + "1" + QByteArray("}").repeated(depth));
    }
    Result result = Run({"run", deep, "--model", "ideal", "--out", dir.filePath("a")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("nested deeper than 64"), qPrintable(result.err));
    const QString overflow = dir.filePath("overflow.json");
    {
      QFile file(overflow);
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write(R"({"geometry": {"rod_length": 1e400}})");
    }
    result = Run({"run", overflow, "--model", "ideal", "--out", dir.filePath("b")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("1e400"), qPrintable(result.err));
    // Values near the double range: errors naming the field, not failures inside the solver.
    result = Run({"run", "--model", "ideal", "--set", "geometry.rod_length=1e300", "--out",
                  dir.filePath("b2")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("geometry.rod_length = 1e+300"), qPrintable(result.err));
    for (const char* set :
         {"geometry.piston_mass=1e300", "geometry.rod_inertia=1e300", "lubricant.viscosity=1e300",
          "big_end.roughness_journal=1e300", "big_end.oil_feed_pressure=1e300"}) {
      result = Run({"run", "--model", "ideal", "--set", set, "--out", dir.filePath("b4")});
      QCOMPARE(result.exit_code, 2);
      const QString field = QString(set).section('=', 0, 0);
      QVERIFY2(result.err.contains(field + " = 1e+300"), qPrintable(result.err));
    }
    // Meshes beyond the case's maximum, and a run larger than this machine's memory (one cycle
    // of fields at 125 664 output steps on a 2000 × 498 big end: terabytes): refused before
    // anything is written.
    result = Run({"run", "--model", "only-lbrbe", "--set", "big_end.mesh_theta=5000", "--set",
                  "big_end.mesh_z=2000", "--out", dir.filePath("m1")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("big_end.mesh_theta × big_end.mesh_z") &&
                 result.err.contains("at most 500000"),
             qPrintable(result.err));
    result = Run({"run", "--model", "only-lbrbe", "--set", "big_end.mesh_theta=2000", "--set",
                  "big_end.mesh_z=498", "--set", "solver.output_interval=0.0001", "--out",
                  dir.filePath("m2")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("big-end mesh") && result.err.contains("2000 × 498") &&
                 result.err.contains("available"),
             qPrintable(result.err));
    QVERIFY(!QFileInfo::exists(dir.filePath("m2")));
    const QString huge_pressure = dir.filePath("huge.csv");
    {
      QFile file(huge_pressure);
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write("crank_angle[deg],pressure[Pa]\n");
      for (int deg = 0; deg <= 720; deg += 60) {
        file.write(QByteArray::number(deg) + "," + (deg == 360 ? "1e300" : "1e5") + "\n");
      }
    }
    result = Run({"run", "--model", "ideal", "--pressure-curve", huge_pressure, "--out",
                  dir.filePath("b3")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("huge.csv:8 pressure[Pa] = 1e+300"), qPrintable(result.err));
    // A speed outside the case's curves, given as --rpm, names --rpm (it named operating.rpm).
    result = Run({"run", "--model", "ideal", "--rpm", "500", "--out", dir.filePath("r500")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("--rpm = 500: must lie within the speeds of pressure_curves"),
             qPrintable(result.err));
    // A time limit of 0 is refused (it meant no limit, silently).
    result = Run({"run", "--model", "ideal", "--time-limit", "0", "--out", dir.filePath("t0")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("--time-limit = 0: must be a finite number > 0"),
             qPrintable(result.err));
    result = Run(
        {"run", "--model", "ideal", "--pressure-curve", "/dev/zero", "--out", dir.filePath("c")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("--pressure-curve = /dev/zero: is not a regular file"),
             qPrintable(result.err));
    result = Run({"run", "--model", "ideal", "--set", "pressure_curves.3.file=/dev/zero", "--out",
                  dir.filePath("d")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("pressure_curves.3.file"), qPrintable(result.err));
    const QString cell = dir.filePath("cell.csv");
    {
      QFile file(cell);
      QVERIFY(file.open(QIODevice::WriteOnly));
      file.write("crank_angle[deg],pressure[Pa]\n0," + QByteArray(5 << 20, '9') + "x\n");
    }
    result = Run({"run", "--model", "ideal", "--pressure-curve", cell, "--out", dir.filePath("e")});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.size() < 1000, qPrintable(result.err.left(300)));
    // Not UTF-8: the argument goes through the native 8-bit encoding untouched.
    QProcess latin;
    latin.setProgram(FILMDYN_EXECUTABLE);
    latin.setArguments({"run", "--model", "ideal", "--out", dir.filePath("g"), "--set",
                        QString::fromLatin1("name=ab\xff")});
    latin.start();
    QVERIFY(latin.waitForFinished(60000));
    const QString latin_err = QString::fromUtf8(latin.readAllStandardError());
    if (latin_err.contains("UTF-8")) {  // the byte arrived as 0xff: refused
      QCOMPARE(latin.exitCode(), 2);
      QVERIFY(latin_err.contains("--set name"));
    } else {  // the platform re-encoded it as valid UTF-8: accepted, summary complete
      QCOMPARE(latin.exitCode(), 0);
    }
    // A case name with separators and "..": the default folder stays inside results/.
    QProcess escape;
    escape.setWorkingDirectory(dir.path());
    escape.start(FILMDYN_EXECUTABLE,
                 {"run", "--model", "ideal", "--quiet", "--set", "name=../../escaped"});
    QVERIFY(escape.waitForFinished(60000));
    QCOMPARE(escape.exitCode(), 0);
    const QStringList made =
        QDir(dir.filePath("results")).entryList(QDir::Dirs | QDir::NoDotAndDotDot);
    QCOMPARE(made.size(), 1);
    QVERIFY2(!made.first().contains('/'), qPrintable(made.first()));
    QVERIFY(!QFileInfo::exists(QDir(dir.path()).absoluteFilePath("../escaped-ideal-6000")));
  }

  void runRejectsBadThreads() {
    const Result result = Run({"run", "--model", "ideal", "--threads", "3"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY2(result.err.contains("--threads = 3: must be 1 or 2"), qPrintable(result.err));
  }

  void validateRunsEverySuiteAndPasses() {
    const Result result = Run({"validate", "--json"});
    QCOMPARE(result.exit_code, 0);
    const QJsonArray rows = QJsonDocument::fromJson(result.out.toUtf8()).array();
    QVERIFY(rows.size() >= 50);
    QSet<QString> suites;
    for (const QJsonValue& row : rows) {
      suites.insert(row["suite"].toString());
      QVERIFY2(row["pass"].toBool(), qPrintable(row["case"].toString()));
      QVERIFY(row["error"].toDouble() <= row["tolerance"].toDouble());
    }
    QVERIFY(suites.contains("multibody"));
    QVERIFY(suites.contains("bearing"));
    const Result table = Run({"validate", "--suite", "multibody"});
    QCOMPARE(table.exit_code, 0);
    QVERIFY(table.out.contains("cases pass"));
    QVERIFY(!table.out.contains("Raimondi"));
  }

  // The bearing calculator's inputs out of range name the option the user typed (and a malformed
  // mesh its whole value and form).
  void bearingErrorsNameTheOption() {
    for (const auto& [argv, needle] : std::vector<std::pair<QStringList, QString>>{
             {{"bearing", "--eps", "1"}, "--eps = 1: must be a finite number in [0, 1)"},
             {{"bearing", "--eps", "0.5", "--clearance", "-1e-6"}, "--clearance = -1e-06"},
             {{"bearing", "--eps", "0.5", "--rpm", "-3000"}, "--rpm = -3000"},
             {{"bearing", "--load", "0"}, "--load = 0"},
             {{"bearing", "--eps", "0.5", "--mesh", "240x"}, "--mesh = 240x: must be NthetaxNz"},
             {{"bearing", "--eps", "0.5", "--mesh", "240x40x3"},
              "--mesh = 240x40x3: must be NthetaxNz"},
             {{"bearing", "--eps", "0.5", "--load", "5"},
              "--eps / --load = both --eps and --load: give exactly one of --eps"},
             {{"bearing", "--eps", "0.5", "--roelands", "-1"}, "--roelands = -1"},
             {{"bearing", "--eps", "0.5", "--sigma1", "-1e-6"}, "--sigma1 = -1e-06"},
             {{"bearing", "--eps", "0.5", "--sigma1", "1e-6", "--E1", "0"}, "--E1 = 0"},
             {{"bearing", "--eps", "0.5", "--sigma1", "1e-6", "--peklenik", "20"},
              "--peklenik = 20"},
             {{"bearing", "--eps", "0.5", "--sigma1", "1e-6", "--nu2", "0.7"}, "--nu2 = 0.7"},
             // Options that would be ignored are refused: the width set twice, contact or
             // elasticity data without a roughness or an elastic model.
             {{"bearing", "--eps", "0.5", "--ld", "1", "--length", "0.03"},
              "--ld = 1: either --ld or --length, not both"},
             {{"bearing", "--eps", "0.5", "--peklenik", "3"},
              "--peklenik = 3: only with a roughness (--sigma1, --sigma2)"},
             {{"bearing", "--eps", "0.5", "--boundary-friction", "0.1"},
              "--boundary-friction = 0.1: only with a roughness"},
             {{"bearing", "--eps", "0.5", "--E1", "100e9"},
              "--E1 = 100e9: only with a roughness (--sigma1, --sigma2: the asperity contact) or "
              "--half-space"},
             // Checks of the film's own configuration name the options too (they named
             // bearing.radial_clearance and bearing.mesh), and the mesh's limits are given.
             {{"bearing", "--eps", "0.5", "--clearance", "0.03"},
              "--clearance = 0.03: must be smaller than the radius"},
             {{"bearing", "--eps", "0.5", "--half-space", "--mesh", "240x42"},
              "--half-space = \"half_space\" on a film of 10320 nodes"},
             {{"bearing", "--eps", "0.5", "--half-space", "--mesh", "240x42"},
              "coarsen the mesh (--mesh) or choose --elastic-layer"},
             {{"bearing", "--eps", "0.5", "--elastic-layer", "1e-3,5e9,0.3", "--half-space"},
              "--half-space = given with --elastic-layer: one of --elastic-layer, --half-space or "
              "--compliance at a time"},
             {{"bearing", "--eps", "0.5", "--mesh", "20001x2"},
              "--mesh = 20001x2: must be NthetaxNz with integers, e.g. 240x40 (8 <= Ntheta <= "
              "20000, 2 <= Nz <= 5000)"},
             // Within the case's ranges of the same quantities (1e300 Pa s gave NaN figures
             // reported as converged), and a film within an engine run's size.
             {{"bearing", "--eps", "0.5", "--viscosity", "1e300"},
              "--viscosity = 1e+300: must be a finite number in (0, 1000] [Pa*s]"},
             {{"bearing", "--eps", "0.5", "--rpm", "1e300"}, "--rpm = 1e+300"},
             {{"bearing", "--eps", "0.5", "--sigma1", "1"}, "--sigma1 = 1"},
             {{"bearing", "--eps", "0.5", "--mesh", "4000x1000"},
              "--mesh = 4000x1000: 4004000 unknowns: at most 500000 pressure unknowns"},
             {{"skirt", "--e0", "0", "--tilt", "0", "--speed", "10", "--mesh", "1+1+1x2"},
              "--mesh = 1+1+1x2 (skirt.mesh_thrust 1): must be an integer in [2, 2000]"},
             {{"skirt", "--e0", "0", "--tilt", "0", "--speed", "10", "--mesh",
               "2000+2000+2000x1000"},
              "4006002 unknowns): at most 500000 pressure unknowns"}}) {
      const Result result = Run(argv);
      QCOMPARE(result.exit_code, 2);
      QVERIFY2(result.err.contains(needle) && !result.err.contains("bearing."),
               qPrintable(result.err));
    }
  }

  // A centred journal carries no load: its attitude is undefined and S, (R/c) f unbounded — said
  // in words (text) and as null with the reason (JSON), not "180°" and a bare "inf"; its Petroff
  // friction is still reported: T = 2π μ ω R³ L / c (independent formula).
  void bearingAtZeroEccentricitySaysTheLoadFiguresAreUndefined() {
    const Result text = Run({"bearing", "--eps", "0"});
    QCOMPARE(text.exit_code, 0);
    QVERIFY2(text.out.contains("attitude angle [deg]     undefined (no load: the journal is "
                               "centred)"),
             qPrintable(text.out));
    QVERIFY(text.out.contains("Sommerfeld number S      infinite (no load"));
    QVERIFY(!text.out.contains("180"));
    const Result json = Run({"bearing", "--eps", "0", "--json"});
    QCOMPARE(json.exit_code, 0);
    const QJsonObject j = QJsonDocument::fromJson(json.out.toUtf8()).object();
    QVERIFY(j["attitude_deg"].isNull() && j["sommerfeld"].isNull() &&
            j["friction_variable"].isNull());
    QCOMPARE(j["undefined"].toArray().size(), 3);
    QCOMPARE(j["undefined_reason"].toString(), QString("no load: the journal is centred"));
    QCOMPARE(j["load"].toDouble(), 0.0);
    // Defaults: μ 0.01 Pa s, 3000 rpm, R 0.025 m, L = 0.025 m (L/D 0.5), c 25 µm.
    const double omega = 3000.0 * 2.0 * M_PI / 60.0;
    const double petroff = 2.0 * M_PI * 0.01 * omega * std::pow(0.025, 3) * 0.025 / 25e-6;
    QVERIFY2(std::abs(j["friction_torque"].toDouble() / petroff - 1.0) < 1e-6,
             qPrintable(QString::number(j["friction_torque"].toDouble())));
    // A loaded bearing keeps its figures.
    const QJsonObject loaded =
        QJsonDocument::fromJson(Run({"bearing", "--eps", "0.6", "--json"}).out.toUtf8()).object();
    QVERIFY(loaded["attitude_deg"].isDouble() && !loaded.contains("undefined"));
    QVERIFY(loaded["warnings"].toArray().isEmpty());
  }

  // Smooth surfaces carry any load on a thin enough film: a film below real surfaces' roughness
  // (0.1 µm) is answered with a warning that says so (stderr and JSON), not silently; rough
  // surfaces (asperity contact) have no such warning.
  void bearingWarnsOfAFilmThinnerThanRealRoughness() {
    const Result huge = Run({"bearing", "--load", "1e7", "--json"});
    QCOMPARE(huge.exit_code, 0);
    const QJsonObject j = QJsonDocument::fromJson(huge.out.toUtf8()).object();
    QVERIFY(j["moft"].toDouble() < 0.1e-6);
    QCOMPARE(j["warnings"].toArray().size(), 1);
    QVERIFY2(j["warnings"][0].toString().contains("thinner than the roughness of real bearing"),
             qPrintable(j["warnings"][0].toString()));
    QVERIFY2(huge.err.contains("filmdyn bearing: warning: the minimum film"), qPrintable(huge.err));
    const Result rough = Run({"bearing", "--load", "1e5", "--sigma1", "0.3e-6", "--json"});
    QVERIFY(QJsonDocument::fromJson(rough.out.toUtf8()).object()["warnings"].toArray().isEmpty());
    QVERIFY(!rough.err.contains("warning"));
  }

  void validateRejectsUnknownSuite() {
    const Result result = Run({"validate", "--suite", "nope"});
    QCOMPARE(result.exit_code, 2);
    QVERIFY(result.err.contains("--suite = nope"));
    QVERIFY(result.err.contains("lubrication, cavitation, multibody"));
  }

  // The parser itself, in process.
  void parserAcceptsBothValueForms() {
    const std::vector<filmdyn::cli::OptionSpec> specs = {
        {"rpm", "N", "speed", false}, {"set", "K=V", "override", true}, {"json", "", "", false}};
    const auto args = filmdyn::cli::Args::Parse(
        "run", {"case.json", "--rpm=6000", "--set", "a.b=1", "--set", "c=2", "--json"}, specs, 1);
    QCOMPARE(*args.Double("rpm"), 6000.0);
    QCOMPARE(args.Values("set").size(), std::size_t(2));
    QVERIFY(args.Has("json"));
    QCOMPARE(args.positional().front(), std::string("case.json"));
  }

  void parserRejectsBadInputWithField() {
    const std::vector<filmdyn::cli::OptionSpec> specs = {{"rpm", "N", "speed", false}};
    auto expect_error = [&](const std::vector<std::string>& argv, const QString& needle) {
      try {
        const auto args = filmdyn::cli::Args::Parse("run", argv, specs, 0);
        (void)args.Double("rpm");
      } catch (const filmdyn::InputError& error) {
        QVERIFY2(QString(error.what()).contains(needle), error.what());
        return;
      }
      QFAIL("no InputError thrown");
    };
    expect_error({"--rpm"}, "needs a value");
    // An option's value missing before the next option: that option is not taken as the value
    // ("--out --overwrite" wrote into a folder named "--overwrite").
    expect_error({"--rpm", "--rpm", "1"},
                 "--rpm = (missing): needs a value: --rpm N (the next argument, --rpm, is an "
                 "option)");
    expect_error({"--rpm", "0x1770"}, "--rpm = '0x1770': must be a finite number");
    expect_error({"--rpm", "+-5"}, "must be a finite number");
    expect_error({"--rpm", "fast"}, "--rpm = 'fast': must be a finite number");
    expect_error({"--rpm", "nan"}, "must be a finite number");
    expect_error({"--rpm", "1", "--rpm", "2"}, "--rpm = '2': may be given only once");
    expect_error({"extra"}, "takes no positional");
    // An unknown option with a value is named as unknown, not its value as a surplus argument;
    // a known option's value may look like an option.
    expect_error({"--pressure-curve", "p.csv", "--rpm", "1"},
                 "--pressure-curve = '--pressure-curve': unknown option for 'run'; allowed: --rpm");
    expect_error({"--rpm", "1", "--pressure-curve=p.csv"}, "unknown option for 'run'");
    try {
      (void)filmdyn::cli::Args::Parse("run", {"--rpm", "--5"}, specs, 0);
    } catch (const filmdyn::InputError& error) {
      QVERIFY2(!QString(error.what()).contains("unknown option"), error.what());
    }
    QCOMPARE(filmdyn::cli::ParseDoubleList("--rpm", "1000,2000").size(), std::size_t(2));
  }

  // The calculator's oil options: the viscosity a Vogel law gives at the temperature (reported
  // as viscosity_used), Barus raising the load, and clear errors for what does not fit.
  // Elastic surfaces in the calculator: an elastic lining, the half-space, an imported FE
  // compliance (the shipped CalculiX shell); --json says the model and max_deformation [m]; bad
  // values name the option, a bad file names the file.
  void bearingSolvesElasticSurfaces() {
    const Result rigid = Run({"bearing", "--eps", "0.8", "--mesh", "96x16", "--json"});
    QCOMPARE(rigid.exit_code, 0);
    const QJsonObject r = QJsonDocument::fromJson(rigid.out.toUtf8()).object();
    QCOMPARE(r["compliance"].toString(), QString("rigid"));
    // Every dimensional figure names its unit.
    const QJsonObject units = r["units"].toObject();
    for (const auto& [key, unit] :
         std::vector<std::pair<QString, QString>>{{"load", "N"},
                                                  {"moft", "m"},
                                                  {"friction_torque", "N*m"},
                                                  {"friction_power_loss", "W"},
                                                  {"max_pressure", "Pa"},
                                                  {"inlet_flow", "m^3/s"},
                                                  {"side_flow", "m^3/s"},
                                                  {"max_deformation", "m"}}) {
      QVERIFY2(r.contains(key) && units[key].toString() == unit, qPrintable(key));
    }
    QCOMPARE(r["max_deformation"].toDouble(), 0.0);
    const Result layer = Run({"bearing", "--eps", "0.8", "--mesh", "96x16", "--elastic-layer",
                              "2e-3,3e9,0.3", "--json"});
    QVERIFY2(layer.exit_code == 0, qPrintable(layer.err));
    const QJsonObject l = QJsonDocument::fromJson(layer.out.toUtf8()).object();
    QCOMPARE(l["compliance"].toString(), QString("elastic_layer"));
    QVERIFY(l["max_deformation"].toDouble() > 0.1e-6);
    QVERIFY(l["load"].toDouble() < 0.98 * r["load"].toDouble());  // the film opens
    QVERIFY(l["elastic_residual"].toDouble() <= l["elastic_tolerance"].toDouble());
    const Result half =
        Run({"bearing", "--eps", "0.8", "--mesh", "96x16", "--half-space", "--json"});
    QVERIFY2(half.exit_code == 0, qPrintable(half.err));
    QCOMPARE(QJsonDocument::fromJson(half.out.toUtf8()).object()["compliance"].toString(),
             QString("half_space"));
    const QString shell =
        QString(FILMDYN_SOURCE_DIR) + "/examples/calculix-bearing-shell/shell_compliance.mtx";
    const Result fe = Run({"bearing", "--eps", "0.8", "--radius", "0.015", "--length", "0.022",
                           "--mesh", "96x16", "--compliance", shell, "--json"});
    QVERIFY2(fe.exit_code == 0, qPrintable(fe.err));
    const QJsonObject f = QJsonDocument::fromJson(fe.out.toUtf8()).object();
    QCOMPARE(f["compliance"].toString(), QString("imported"));
    QVERIFY(f["max_deformation"].toDouble() > 0.0);
    const Result nu = Run({"bearing", "--eps", "0.8", "--elastic-layer", "1e-3,10e9,0.5"});
    QVERIFY(nu.exit_code != 0 && nu.err.contains("--elastic-layer NU"));
    const Result both =
        Run({"bearing", "--eps", "0.8", "--elastic-layer", "1e-3,10e9,0.3", "--half-space"});
    QVERIFY(both.exit_code != 0 && both.err.contains("one of --elastic-layer"));
    const Result missing = Run({"bearing", "--eps", "0.8", "--compliance", "/nonexistent/c.mtx"});
    QVERIFY2(missing.exit_code != 0 && missing.err.contains("/nonexistent/c"),
             qPrintable(missing.err));
  }

  void bearingTakesOilTemperatureAndPressureLaws() {
    const Result vogel = Run(
        {"bearing", "--eps", "0.6", "--vogel", "6.9e-5,1050,165", "--temperature", "90", "--json"});
    QCOMPARE(vogel.exit_code, 0);
    const QJsonObject v = QJsonDocument::fromJson(vogel.out.toUtf8()).object();
    const double expected = 6.9e-5 * std::exp(1050.0 / (363.15 - 165.0));
    QVERIFY(std::abs(v["viscosity_used"].toDouble() / expected - 1.0) < 1e-12);
    QCOMPARE(v["temperature"].toDouble(), 90.0);
    QCOMPARE(v["pressure_viscosity"].toString(), QString("none"));
    const Result barus = Run({"bearing", "--eps", "0.6", "--vogel", "6.9e-5,1050,165",
                              "--temperature", "90", "--barus", "2e-8", "--json"});
    QCOMPARE(barus.exit_code, 0);
    const QJsonObject b = QJsonDocument::fromJson(barus.out.toUtf8()).object();
    QCOMPARE(b["pressure_viscosity"].toString(), QString("barus"));
    QCOMPARE(b["viscosity_used"].toDouble(), v["viscosity_used"].toDouble());
    QVERIFY(b["load"].toDouble() > 1.01 * v["load"].toDouble());
    // Shear thinning calibrated by the HTHS viscosity: the critical rate at 90 °C is the one at
    // 150 °C shifted by mu1(150 °C) / mu1(90 °C); the load falls.
    const Result cross =
        Run({"bearing", "--eps", "0.6", "--vogel", "6.9e-5,1050,165", "--temperature", "90",
             "--cross", "0.7,1", "--hths", "3.2e-3", "--json"});
    QVERIFY2(cross.exit_code == 0, qPrintable(cross.err));
    const QJsonObject x = QJsonDocument::fromJson(cross.out.toUtf8()).object();
    QCOMPARE(x["shear_thinning"].toString(), QString("cross"));
    const double mu150 = 6.9e-5 * std::exp(1050.0 / (423.15 - 165.0));
    const double rate150 = 1e6 / ((mu150 - 3.2e-3) / (3.2e-3 - 0.7 * mu150));  // m = 1
    QVERIFY(std::abs(x["cross_critical_rate"].toDouble() / (rate150 * mu150 / expected) - 1.0) <
            1e-12);
    QVERIFY(x["load"].toDouble() < 0.99 * v["load"].toDouble());
    // A catalogue grade: the oil it names, its viscosity at the temperature, and a warning when
    // the temperature is outside the fit's 40–150 °C.
    const Result grade =
        Run({"bearing", "--eps", "0.6", "--grade", "5w-30", "--temperature", "100", "--json"});
    QVERIFY2(grade.exit_code == 0, qPrintable(grade.err));
    const QJsonObject g = QJsonDocument::fromJson(grade.out.toUtf8()).object();
    QCOMPARE(g["grade_product"].toString(), QString("Mobil 1 ESP Formula 5W-30"));
    QVERIFY(std::abs(g["viscosity_used"].toDouble() - 9.633e-3) < 1e-6);
    QVERIFY(!g["grade_extrapolated"].toBool());
    const Result cold = Run({"bearing", "--eps", "0.6", "--grade", "5w-30", "--temperature", "20"});
    QCOMPARE(cold.exit_code, 0);
    QVERIFY2(cold.err.contains("outside the 40–150 °C"), qPrintable(cold.err));
    struct Bad {
      QStringList args;
      QString field;
    };
    const QList<Bad> bad = {
        {{"--vogel", "6.9e-5,1050,165"}, "--temperature"},
        {{"--vogel", "6.9e-5,1050,165", "--temperature", "-120"}, "--temperature"},
        {{"--vogel", "6.9e-5,1050"}, "--vogel"},
        {{"--vogel", "-1,1050,165", "--temperature", "90"}, "--vogel.a"},
        {{"--viscosity", "0.01", "--temperature", "90"}, "--temperature"},
        {{"--barus", "-2e-8"}, "--barus = -2e-08"},
        {{"--barus", "2e-8", "--roelands", "0.6"}, "--barus"},
        {{"--cross", "0.7,1"}, "--cross"},
        {{"--cross", "1.5,1,1e6"}, "--cross"},
        {{"--hths", "3e-3"}, "--hths"},
        {{"--cross", "0.7,1", "--hths", "0.02"}, "--hths"},
        {{"--grade", "5w-31", "--temperature", "100"}, "--grade"},
        {{"--grade", "5w-30"}, "--temperature"},
        {{"--grade", "5w-30", "--vogel", "6.9e-5,1050,165", "--temperature", "90"}, "--grade"}};
    for (const Bad& c : bad) {
      const Result r = Run(QStringList{"bearing", "--eps", "0.6"} + c.args);
      QVERIFY2(r.exit_code == 2, qPrintable(c.args.join(' ') + ": " + r.err));
      QVERIFY2(r.err.contains(c.field), qPrintable(c.args.join(' ') + ": " + r.err));
    }
    // An engine run takes the pressure law (phased in over its run-in); summary.json says which.
    QTemporaryDir dir;
    const Result run =
        Run({"run", "--model", "only-lbrbe", "--out", dir.filePath("r"), "--quiet", "--no-fields",
             "--set", "solver.error_estimate=0", "--set", "lubricant.pressure_viscosity=roelands"});
    QVERIFY2(run.exit_code == 0, qPrintable(run.err));
    QFile summary_file(dir.filePath("r/summary.json"));
    QVERIFY(summary_file.open(QIODevice::ReadOnly));
    const QJsonObject oil = QJsonDocument::fromJson(summary_file.readAll())
                                .object()["oil"]
                                .toObject()["big_end"]
                                .toObject();
    QCOMPARE(oil["pressure_viscosity"].toString(), QString("roelands"));
    QVERIFY(oil["pressure_viscosity_coefficient[1/Pa]"].toDouble() > 1e-8);
  }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
