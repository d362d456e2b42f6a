// `filmdyn reproduce` through the real executable: the paper's section 4 study on coarse
// meshes — six real runs, the comparisons, their plots and the figure index. Labelled `long`
// (like the error estimate's check): the sanitizer builds leave it out, since its runs are the
// run job the other suites drive under the sanitizers, six times over.
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "run_filmdyn.hpp"

namespace {

Result Run(const QStringList& arguments, int timeout_ms) {
  return RunFilmdyn(arguments, timeout_ms);
}

}  // namespace

class TestCliReproduce : public QObject {
  Q_OBJECT
 private slots:
  void reproduceRunsThePapersStudyAndIndexesItsFigures() {
    // The paper's section 4 study on the coarse test meshes: six real runs (three models at
    // 6000 rpm, Skirt-LBRBE at 1000/2000/4000 rpm), overlays and the figure index. On these
    // meshes the bearing film collapses at 1000 and 2000 rpm (the coarse mesh under-predicts the
    // MOFT ~2.6x): those runs must end as `failed` with partial results, and the study still
    // writes everything else (exit code 1 = some run incomplete).
    QTemporaryDir dir;
    const QString out = dir.filePath("paper");
    const Result result =
        Run({"reproduce", "--out", out, "--no-fields", "--quiet", "--jobs", "2", "--set",
             "skirt.mesh_thrust=10", "--set", "skirt.mesh_anti=10", "--set", "skirt.mesh_axial=12",
             "--set", "big_end.mesh_theta=24", "--set", "big_end.mesh_z=6"},
            280000);
    QVERIFY2(result.exit_code == 0 || result.exit_code == 1, qPrintable(result.err));
    for (const char* run : {"only-skirt-6000", "only-lbrbe-6000", "skirt-lbrbe-6000",
                            "skirt-lbrbe-1000", "skirt-lbrbe-2000", "skirt-lbrbe-4000"}) {
      const QString folder = out + "/runs/zhao-shen-gasoline-" + run;
      QVERIFY2(QFileInfo::exists(folder + "/summary.json"), qPrintable(folder));
      QVERIFY2(QFileInfo::exists(folder + "/results.csv"), qPrintable(folder));
    }
    QVERIFY(result.err.contains("reproduce: skirt-lbrbe 6000 rpm: completed"));
    QVERIFY(result.err.contains("reproduce: only-skirt 6000 rpm: completed"));
    QVERIFY(result.err.contains("reproduce: only-lbrbe 6000 rpm: completed"));
    // Models: three rows; speeds: four (the 6000 rpm Skirt-LBRBE run is shared).
    auto rows = [&](const QString& csv_path) {
      QFile csv(csv_path);
      return csv.open(QIODevice::ReadOnly)
                 ? QString::fromUtf8(csv.readAll()).trimmed().split('\n').size() - 1
                 : -1;
    };
    QCOMPARE(rows(out + "/models-6000rpm/comparison.csv"), 3);
    QCOMPARE(rows(out + "/speeds-skirt-lbrbe/comparison.csv"), 4);
    for (const char* plot :
         {"models-6000rpm/plots/journal_orbit.png", "models-6000rpm/plots/moft.png",
          "speeds-skirt-lbrbe/plots/fpl.png", "speeds-skirt-lbrbe/plots/phase_eps.png",
          "figures/cylinder_pressure.png"}) {
      const QImage image(out + "/" + plot);
      QVERIFY2(!image.isNull() && image.width() > 500, plot);
    }
    QVERIFY(QFileInfo(out + "/figures/cylinder_pressure.svg").size() > 1000);
    QFile index(out + "/figures.md");
    QVERIFY(index.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(index.readAll());
    for (int figure = 5; figure <= 15; ++figure) {
      QVERIFY2(text.contains(QString("| Fig. %1 |").arg(figure)), qPrintable(text));
    }
    // What every run ran with besides the case: the --set changes, and whether errors were
    // estimated.
    QVERIFY2(text.contains("Changed in the case for every run: `skirt.mesh_thrust = 10`, "),
             qPrintable(text));
    QVERIFY2(text.contains("holds the estimated discretisation error"), qPrintable(text));
    QVERIFY(result.out.contains("## The three models at 6000 rpm"));
  }
};

QTEST_MAIN(TestCliReproduce)
#include "test_cli_reproduce.moc"
