// `filmdyn skirt`, the real executable: mode 1 (a state) and mode 2 (a load) as text and JSON,
// mode 2 returning the state of mode 1 that carries the same load, the map's CSV and plots, the
// film fields, and bad input (a state into the liner, a load beyond the capacity, NaN, a bad
// mesh, conflicting modes) as one-line errors naming the option, with exit code 2.
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include "run_filmdyn.hpp"

namespace {

Result Run(const QStringList& arguments) {
  return RunFilmdyn(QStringList{"skirt"} + arguments, 120000);
}

QJsonObject Json(const Result& r) { return QJsonDocument::fromJson(r.out.toUtf8()).object(); }

}  // namespace

class TestCliSkirt : public QObject {
  Q_OBJECT
 private slots:
  void stateModePrintsEveryQuantity() {
    const Result text = Run({"--e0", "10e-6", "--tilt", "2e-4", "--speed", "12"});
    QCOMPARE(text.exit_code, 0);
    for (const char* words :
         {"normal force on the piston", "moment about the pin", "of which friction",
          "minimum oil film thickness", "angle from the thrust side", "cavitated fraction"}) {
      QVERIFY2(text.out.contains(words), words);
    }
    const Result json = Run({"--e0", "10e-6", "--tilt", "2e-4", "--speed", "12", "--json"});
    QCOMPARE(json.exit_code, 0);
    const QJsonObject j = Json(json);
    for (const char* key : {"normal_force", "moment_about_pin", "normal_moment", "friction_moment",
                            "friction_force", "max_pressure", "moft", "moft_alpha", "moft_y",
                            "contact_force", "cavitated_fraction", "e0", "tilt"}) {
      QVERIFY2(j.contains(key), key);
    }
    QCOMPARE(j.value("mode").toString(), QString("state"));
    QCOMPARE(j.value("e0").toDouble(), 10e-6);
    // Toward thrust, the film pushes back; the moment's parts add up.
    QVERIFY(j.value("normal_force").toDouble() < 0.0);
    QVERIFY(std::abs(j.value("normal_moment").toDouble() + j.value("friction_moment").toDouble() -
                     j.value("moment_about_pin").toDouble()) <
            1e-12 * std::abs(j.value("moment_about_pin").toDouble()));
    QCOMPARE(j.value("units").toObject().value("moft").toString(), QString("m"));
    // A Reynolds film's wetted share is its uncavitated share.
    QVERIFY(std::abs(j.value("wetted_fraction").toDouble() +
                     j.value("cavitated_fraction").toDouble() - 1.0) < 1e-12);
  }

  // A starved skirt (a mass-conserving film fed by the liner's 3 µm of oil) under a load: its
  // wetted fraction, the mean film fraction, is less than its uncavitated share (the partial
  // film counts by its oil) and is the figure docs/validation/cavitation.md tabulates (0.37).
  void starvedSkirtReportsItsWettedFraction() {
    const Result r =
        Run({"--side-force", "1500", "--speed", "10", "--set", "skirt.cavitation=jfo", "--set",
             "skirt.supply=starved", "--set", "skirt.oil_film=3e-6", "--json"});
    QCOMPARE(r.exit_code, 0);
    const QJsonObject j = Json(r);
    QVERIFY(j.value("converged").toBool());
    const double wetted = j.value("wetted_fraction").toDouble();
    const double cavitated = j.value("cavitated_fraction").toDouble();
    QVERIFY2(wetted < 1.0 - cavitated - 0.01, qPrintable(r.out));
    QVERIFY2(std::abs(wetted - 0.37) < 0.01, qPrintable(r.out));
    QCOMPARE(j.value("units").toObject().value("wetted_fraction").toString(), QString("-"));
    const Result text =
        Run({"--side-force", "1500", "--speed", "10", "--set", "skirt.cavitation=jfo", "--set",
             "skirt.supply=starved", "--set", "skirt.oil_film=3e-6"});
    QVERIFY2(text.out.contains("oil-covered (wetted) fraction of the skirt panels"),
             qPrintable(text.out));
  }

  void loadModeFindsTheStateOfTheStateMode() {
    const QJsonObject given =
        Json(Run({"--e0", "12e-6", "--tilt", "-3e-4", "--speed", "-9", "--json"}));
    const double force = -given.value("normal_force").toDouble();
    const double moment = -given.value("moment_about_pin").toDouble();
    const Result r = Run({"--side-force", QString::number(force, 'g', 17), "--moment",
                          QString::number(moment, 'g', 17), "--speed", "-9", "--json"});
    QCOMPARE(r.exit_code, 0);
    const QJsonObject j = Json(r);
    QCOMPARE(j.value("mode").toString(), QString("load"));
    QVERIFY(j.value("converged").toBool());
    QVERIFY2(std::abs(j.value("e0").toDouble() - 12e-6) < 1e-11, qPrintable(r.out));
    QVERIFY2(std::abs(j.value("tilt").toDouble() + 3e-4) < 1e-9, qPrintable(r.out));
    const Result text = Run({"--side-force", "800", "--speed", "10"});
    QCOMPARE(text.exit_code, 0);
    QVERIFY(text.out.startsWith("equilibrium under a side force of 800 N"));
  }

  void mapWritesTheCurveAndItsPlots() {
    QTemporaryDir dir;
    const Result r =
        Run({"--map", dir.path(), "--speed", "10", "--tilts", "0,5e-4", "--points", "11"});
    QCOMPARE(r.exit_code, 0);
    QFile csv(dir.filePath("skirt_map.csv"));
    QVERIFY(csv.open(QIODevice::ReadOnly));
    const QStringList lines = QString::fromUtf8(csv.readAll()).trimmed().split('\n');
    QCOMPARE(lines.size(), 1 + 2 * 11);
    QVERIFY(lines[0].startsWith("e0[m],tilt[rad],"));
    QVERIFY(lines[0].contains("normal_force[N]") && lines[0].contains("moft[m]"));
    for (const char* key : {"normal_force", "moment_about_pin", "moft"}) {
      const QImage png(dir.filePath(QString("plots/skirt_map_%1.png").arg(key)));
      QVERIFY2(!png.isNull() && png.width() >= 960, key);
      QVERIFY(QFileInfo(dir.filePath(QString("plots/skirt_map_%1.svg").arg(key))).size() > 1000);
    }
  }

  void fieldsOfTheStateAreWritten() {
    QTemporaryDir dir;
    const Result r =
        Run({"--e0", "5e-6", "--speed", "10", "--fields", dir.path(), "--mesh", "10+2+10x12"});
    QCOMPARE(r.exit_code, 0);
    QVERIFY(r.out.contains("skirt mesh 10+2+10x12 elements"));
    QVERIFY(QFileInfo(dir.filePath("skirt.h5")).size() > 1000);
    QFile xdmf(dir.filePath("skirt.xdmf"));
    QVERIFY(xdmf.open(QIODevice::ReadOnly));
    QVERIFY(xdmf.readAll().contains("pressure"));
  }

  void badInputNamesTheOption_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("starts");
    QTest::addColumn<QString>("contains");
    QTest::newRow("into the liner")
        << QStringList{"--e0", "40e-6", "--speed", "10"} << "--e0 = 4e-05"
        << "film is positive for";
    QTest::newRow("tilt too large")
        << QStringList{"--tilt", "0.01", "--speed", "10"} << "--tilt = 0.01"
        << "must lie within";
    QTest::newRow("beyond capacity")
        << QStringList{"--side-force", "5e6", "--speed", "10"} << "--side-force = 5000000"
        << "at most about";
    QTest::newRow("nan speed") << QStringList{"--e0", "0", "--speed", "nan"} << "--speed = 'nan'"
                               << "finite number";
    QTest::newRow("no speed") << QStringList{"--e0", "0"} << "--speed"
                              << "give the piston speed";
    QTest::newRow("bad mesh") << QStringList{"--speed", "1", "--mesh", "30x40"} << "--mesh = 30x40"
                              << "T+R+AxN";
    QTest::newRow("state and load") << QStringList{"--e0", "0", "--side-force", "1", "--speed", "1"}
                                    << "--e0 = (given with --side-force)"
                                    << "either a state, a load or --map";
    QTest::newRow("a rate and a load")
        << QStringList{"--e0-rate", "1", "--side-force", "1", "--speed", "1"}
        << "--e0-rate = (given with --side-force)"
        << "either a state, a load or --map";
    QTest::newRow("a map point into the liner")
        << QStringList{"--map",      QDir::tempPath() + "/filmdyn-skirt-map-bad",
                       "--speed",    "10",
                       "--e0-range", "-1e-3:1e-3",
                       "--points",   "3"}
        << "--e0-range = -0.001"
        << "at --tilts = 0 rad the film is positive for";
    // An output folder that cannot be made: said before the film is solved, as bad input (it
    // was a "filesystem error", exit 1, after the whole map was computed).
    const QString file = QDir::tempPath() + "/filmdyn-skirt-a-file";
    QFile(file).open(QIODevice::WriteOnly);
    QTest::newRow("map into a file") << QStringList{"--map", file, "--speed", "10"}
                                     << "--map = " + file << "cannot create the folder";
    QTest::newRow("fields under a file")
        << QStringList{"--e0", "5e-6", "--speed", "10", "--fields", file + "/x"}
        << "--fields = " + file + "/x"
        << "cannot create the folder";
  }
  void badInputNamesTheOption() {
    QFETCH(QStringList, arguments);
    QFETCH(QString, starts);
    QFETCH(QString, contains);
    const Result r = Run(arguments);
    QCOMPARE(r.exit_code, 2);
    QCOMPARE(r.err.count('\n'), 1);
    QVERIFY2(r.err.contains(starts) && r.err.contains(contains), qPrintable(r.err));
  }
};

QTEST_GUILESS_MAIN(TestCliSkirt)
#include "test_cli_skirt.moc"
