// One output path: a run made in the GUI (core's run job through the GUI's backend and run
// record) exports exactly the files `filmdyn run` writes for the same case: results.csv and the
// fields/ files byte for byte, summary.json equal but for the wall time.
#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <nlohmann/json.hpp>

#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"
#include "ui/run/run_backend.hpp"
#include "ui/run/run_record.hpp"

namespace {

// A short coupled run with both films on coarse meshes (both joints write fields).
const std::vector<std::string> kOverrides = {
    "skirt.mesh_thrust=8",   "skirt.mesh_anti=8",
    "skirt.mesh_axial=8",    "big_end.mesh_theta=24",
    "big_end.mesh_z=4",      "solver.max_cycles=1",
    "solver.run_in_angle=0", "solver.output_interval=0.0872664625997165"};

QByteArray Contents(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return file.readAll();
}

// Relative path → content hash of every file under `root`.
QMap<QString, QByteArray> Tree(const QString& root) {
  QMap<QString, QByteArray> files;
  QDirIterator it(root, QDir::Files, QDirIterator::Subdirectories);
  while (it.hasNext()) {
    const QString path = it.next();
    files[QDir(root).relativeFilePath(path)] =
        QCryptographicHash::hash(Contents(path), QCryptographicHash::Sha256);
  }
  return files;
}

nlohmann::json SummaryWithoutWallTime(const QString& path) {
  nlohmann::json j = nlohmann::json::parse(Contents(path).toStdString());
  j.erase("wall_time_s");
  j["discretisation_error"]["coarse_run"].erase("wall_time_s");
  return j;
}

}  // namespace

class TestOutputPath : public QObject {
  Q_OBJECT
 private slots:
  void guiExportsAreTheFilesOfFilmdynRun() {
    QTemporaryDir dir;
    const QString cli_out = dir.filePath("cli"), gui_out = dir.filePath("gui");

    QStringList args = {"run",   "--model", "skirt-lbrbe", "--rpm",     "6000",
                        "--out", cli_out,   "--quiet",     "--threads", "1"};
    for (const auto& o : kOverrides) args << "--set" << QString::fromStdString(o);
    QProcess cli;
    cli.start(FILMDYN_EXECUTABLE, args);
    QVERIFY(cli.waitForFinished(300000));
    // One cycle is not a periodic steady state: the run ends incomplete (its own exit code),
    // with every output written; bad input or a crash would not.
    QVERIFY2(cli.exitStatus() == QProcess::NormalExit && cli.exitCode() != 2,
             cli.readAllStandardError().constData());
    QVERIFY(QFile::exists(cli_out + "/summary.json"));

    filmdyn::io::LoadedCase loaded = filmdyn::io::LoadCase({}, kOverrides);
    filmdyn::ui::RunRequest request{loaded.value, "skirt-lbrbe", 6000.0, {}};
    filmdyn::ui::RunRecord record(1, request);
    std::atomic<bool> cancel{false};
    filmdyn::ui::CoreRunBackend()(request, cancel, record);
    QString error;
    QVERIFY2(record.writeRunFolder(gui_out, &error), qPrintable(error));
    QVERIFY2(record.writeFields(dir.filePath("gui_fields"), &error), qPrintable(error));

    // results.csv byte for byte, also the CSV export's text.
    const QByteArray csv = Contents(cli_out + "/results.csv");
    QVERIFY(csv.count('\n') == 1 + 144);  // 5 °CA steps over 720 °CA
    QCOMPARE(Contents(gui_out + "/results.csv"), csv);
    QCOMPARE(record.resultsCsv(), csv);
    // summary.json: the same keys and values but for the wall time.
    QCOMPARE(SummaryWithoutWallTime(gui_out + "/summary.json").dump(),
             SummaryWithoutWallTime(cli_out + "/summary.json").dump());
    // fields/: the same files with the same bytes, in the run folder and from "Export fields".
    const auto cli_fields = Tree(cli_out + "/fields");
    QVERIFY(cli_fields.size() >= 2);
    QCOMPARE(Tree(gui_out + "/fields"), cli_fields);
    QCOMPARE(Tree(dir.filePath("gui_fields")), cli_fields);
  }

  // A file the case names by a relative path (a compliance file) is looked for in the case
  // file's folder, which the GUI's run request carries, as `filmdyn run` does.
  void relativeCaseFilesAreFoundBesideTheCase() {
    QTemporaryDir dir;
    filmdyn::io::LoadedCase loaded = filmdyn::io::LoadCase(
        {}, {"big_end.compliance=imported", "big_end.compliance_file=housing.mtx"});
    filmdyn::ui::RunRequest request{loaded.value, "skirt-lbrbe", 6000.0, dir.path().toStdString()};
    filmdyn::ui::RunRecord record(1, request);
    std::atomic<bool> cancel{false};
    try {
      filmdyn::ui::CoreRunBackend()(request, cancel, record);
      QFAIL("a missing compliance file was accepted");
    } catch (const filmdyn::InputError& e) {
      QCOMPARE(e.field(), std::string("big_end.compliance_file"));
      const std::string expected = (dir.path() + "/housing.mtx").toStdString();
      QVERIFY2(std::string(e.what()).find(expected) != std::string::npos, e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestOutputPath)
#include "test_output_path.moc"
