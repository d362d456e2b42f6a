// `filmdyn study` through the real executable: a bad study refused before anything runs, the
// dry run, a small factorial study run for real (Ideal and a coarse Only-LBRBE at two speeds),
// its folders, study.csv and study.md; a second run that skips every finished point and leaves
// the tables byte for byte; an incomplete point re-run alone; a different study refused in the
// same folder; `status` and `collect`; the plots in DIR/plots (written by the run and by
// `collect`, not by `status`); points that stop early recorded with their reason; an unknown
// --rank-by and a bad task index refused before anything runs.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QtTest>

#include "run_filmdyn.hpp"

namespace {

Result Run(const QStringList& arguments, int timeout_ms = 300000) {
  return RunFilmdyn(arguments, timeout_ms);
}

QByteArray Read(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void Write(const QString& path, const QByteArray& text) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
  f.write(text);
}

// The study's pictures in `plots`: each PNG decodes to its expected width (2x the logical size)
// and is not blank, each SVG parses and has the same logical size.
void CheckPlots(const QString& plots) {
  // Logical sizes: main effects 2 panels of 500 x (300 + 20 per factor with levels) under a
  // heading line; the scatter matrix a row per plotted figure and a column per factor (360 x
  // 300); best points 960 x (130 + 34 per bar).
  struct Picture {
    const char* name;
    int width;
  };
  for (const Picture& p :
       {Picture{"main-effects", 2 * 3 * 500}, Picture{"scatter-matrix", 2 * 2 * 360},
        Picture{"best-points", 2 * 960}}) {
    const QString png = plots + "/" + p.name + ".png";
    const QImage image(png);
    QVERIFY2(!image.isNull(), qPrintable(png));
    QVERIFY2(image.width() == p.width, qPrintable(png + QString(": %1 wide").arg(image.width())));
    QVERIFY2(image.height() > 300, qPrintable(png));
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4) {
      for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    }
    QVERIFY2(colours.size() > 20, qPrintable(png));
    const QString svg = plots + "/" + p.name + ".svg";
    QSvgRenderer renderer(svg);
    QVERIFY2(renderer.isValid(), qPrintable(svg));
    QCOMPARE(renderer.viewBoxF().size() * 2, QSizeF(image.size()));
    QVERIFY(QFileInfo(svg).size() > 5000);
  }
}

// Ideal and Only-LBRBE on a coarse bearing mesh, at 2000 and 6000 rpm: four quick points.
const char kStudy[] = R"({
  "name": "quick",
  "design": "full-factorial",
  "set": {"big_end.mesh_theta": 24, "big_end.mesh_z": 6, "solver.error_estimate": 0,
          "solver.max_cycles": 2},
  "factors": [
    {"path": "model", "levels": ["ideal", "only-lbrbe"]},
    {"path": "operating.rpm", "levels": [2000, 6000]}
  ]
})";

}  // namespace

class TestCliStudy : public QObject {
  Q_OBJECT
 private slots:
  void aBadStudyIsRefusedBeforeAnythingRuns() {
    QTemporaryDir dir;
    const QString file = dir.filePath("bad.json");
    Write(
        file,
        R"({"design": "full-factorial", "factors": [{"path": "skirt.clearance", "levels": [1e-5]}]})");
    const QString out = dir.filePath("out");
    const Result r = Run({"study", file, "--out", out});
    QCOMPARE(r.exit_code, 2);
    QVERIFY2(r.err.contains("bad.json: factors[0].path = \"skirt.clearance\": is not a case field"),
             qPrintable(r.err));
    QVERIFY(!QDir(out).exists());
    // A level outside the field's range, named with the field and what is allowed.
    Write(
        file,
        R"({"design": "one-at-a-time", "factors": [{"path": "lubricant.viscosity", "levels": [0.02, 0]}]})");
    const Result range = Run({"study", file, "--out", out});
    QCOMPARE(range.exit_code, 2);
    QVERIFY2(range.err.contains("factors[1]") || range.err.contains("factors[0].levels[1]"),
             qPrintable(range.err));
    QVERIFY2(range.err.contains("lubricant.viscosity"), qPrintable(range.err));
    QVERIFY(!QDir(out).exists());
  }

  void aStudyRunsResumesAndCollects() {
    QTemporaryDir dir;
    const QString file = dir.filePath("quick.json");
    Write(file, kStudy);
    const QString out = dir.filePath("quick");

    const Result dry = Run({"study", file, "--out", out, "--dry-run"});
    QCOMPARE(dry.exit_code, 0);
    QVERIFY2(dry.out.startsWith("point,folder,model,operating.rpm[rpm]\n1,point-0001,ideal,2000\n"),
             qPrintable(dry.out));
    QCOMPARE(dry.out.count('\n'), 5);
    QVERIFY(!QDir(out).exists());
    // Without fields an estimate; with them an upper bound, said so.
    QVERIFY2(dry.err.contains("4 points (full-factorial design), about ") &&
                 dry.err.contains(" MB on disk; nothing run"),
             qPrintable(dry.err));

    const Result first =
        Run({"study", file, "--out", out, "--jobs", "2", "--rank-by", "mean_bearing_fpl[W]"});
    QVERIFY2(first.exit_code == 0, qPrintable(first.err));
    QVERIFY2(first.err.contains("4 points (full-factorial), 0 already done, 4 to run"),
             qPrintable(first.err));
    QVERIFY2(first.err.contains("study: 4 points, 4 done"), qPrintable(first.err));
    for (const char* point : {"point-0001", "point-0002", "point-0003", "point-0004"}) {
      QVERIFY(QFile::exists(out + "/" + point + "/results.csv"));
      QVERIFY(QFile::exists(out + "/" + point + "/summary.json"));
      QVERIFY(!QDir(out + "/" + point + "/fields").exists());  // fields are off in studies
    }
    const QByteArray csv = Read(out + "/study.csv");
    const QList<QByteArray> lines = csv.trimmed().split('\n');
    QCOMPARE(lines.size(), 5);
    QVERIFY2(
        lines[0].startsWith("point,folder,model,operating.rpm[rpm],state,status,wall_time[s],"),
        lines[0].constData());
    QVERIFY(lines[0].contains("min_bearing_moft[m]"));
    QVERIFY2(lines[3].startsWith("3,point-0003,only-lbrbe,2000,done,completed,"),
             lines[3].constData());
    // The Only-LBRBE points have a big-end MOFT, the Ideal ones none (an empty cell).
    const QList<QByteArray> header = lines[0].split(',');
    const int moft = int(header.indexOf("min_bearing_moft[m]"));
    QVERIFY(moft > 0);
    QVERIFY(lines[1].split(',').at(moft).isEmpty());
    QVERIFY(lines[3].split(',').at(moft).toDouble() > 1e-7);
    const QByteArray md = Read(out + "/study.md");
    QVERIFY(md.contains("# Study: quick"));
    QVERIFY(md.contains("## Main effects"));
    QVERIFY(md.contains("### operating.rpm[rpm]"));
    QVERIFY(md.contains("## Best points by mean bearing FPL"));
    QVERIFY2(first.err.contains(out + "/plots"), qPrintable(first.err));
    QVERIFY2(!first.err.contains("plots not written"), qPrintable(first.err));
    CheckPlots(out + "/plots");
    // Four done points: two of them (Only-LBRBE) have a big-end friction power, ranked.
    {
      const QImage best(out + "/plots/best-points.png");
      QCOMPARE(best.size(), QSize(2 * 960, 2 * (130 + 34 * 2)));
    }

    // Again: nothing to run, the tables unchanged byte for byte.
    const Result again = Run({"study", file, "--out", out, "--rank-by", "mean_bearing_fpl[W]"});
    QCOMPARE(again.exit_code, 0);
    QVERIFY2(again.err.contains("4 already done, 0 to run"), qPrintable(again.err));
    QCOMPARE(Read(out + "/study.csv"), csv);
    QCOMPARE(Read(out + "/study.md"), md);

    // A point left incomplete (its run was cancelled) is run again, alone.
    const QString summary = out + "/point-0004/summary.json";
    QByteArray text = Read(summary);
    QVERIFY(text.contains("\"status\": \"completed\""));
    text.replace("\"status\": \"completed\"", "\"status\": \"cancelled\"");
    Write(summary, text);
    QVERIFY(QDir(out + "/plots").removeRecursively());
    const Result status = Run({"study", "status", out});
    QCOMPARE(status.exit_code, 0);
    QVERIFY2(status.out.startsWith("4 points, 3 done, 1 incomplete\npoint-0004: incomplete"),
             qPrintable(status.out));
    QVERIFY(!QDir(out + "/plots").exists());  // status reads, never writes
    // A point killed before it wrote its results (its summary still "running", no lock held)
    // has no wall time: the cell is empty, not 0.
    Write(summary,
          QByteArray(text).replace("\"status\": \"cancelled\"", "\"status\": \"running\""));
    QCOMPARE(Run({"study", "collect", out}).exit_code, 0);
    for (const QByteArray& line : Read(out + "/study.csv").split('\n'))
      if (line.contains("point-0004"))
        QVERIFY2(line.contains(",incomplete,running,,"), line.constData());
    Write(summary, text);
    const Result resumed = Run({"study", file, "--out", out});
    QCOMPARE(resumed.exit_code, 0);
    QVERIFY2(resumed.err.contains("3 already done, 1 to run"), qPrintable(resumed.err));
    QVERIFY(Read(summary).contains("\"status\": \"completed\""));

    // collect rebuilds the tables and the plots from the folders alone.
    QVERIFY(QFile::remove(out + "/study.csv"));
    QVERIFY(QDir(out + "/plots").removeRecursively());
    const Result collect = Run({"study", "collect", out});
    QCOMPARE(collect.exit_code, 0);
    QVERIFY2(collect.err.contains("4 points, 4 done"), qPrintable(collect.err));
    QCOMPARE(Read(out + "/study.csv").count('\n'), 5);
    CheckPlots(out + "/plots");

    // An unknown --rank-by is refused, naming the option and the keys, before anything is read
    // or run: by collect, and by a run into a new folder (which gets no point).
    const Result bad_collect = Run({"study", "collect", out, "--rank-by", "total_fpl[W]"});
    QCOMPARE(bad_collect.exit_code, 2);
    QVERIFY2(bad_collect.err.contains("--rank-by = total_fpl[W]: must be one of: "),
             qPrintable(bad_collect.err));
    QVERIFY2(bad_collect.err.contains("mean_bearing_fpl[W]"), qPrintable(bad_collect.err));
    const QString fresh = dir.filePath("fresh");
    const Result bad_run = Run({"study", file, "--out", fresh, "--rank-by", "mean_fpl"});
    QCOMPARE(bad_run.exit_code, 2);
    QVERIFY2(
        bad_run.err.contains("--rank-by = mean_fpl: must be one of: max_abs_piston_lateral[m], "),
        qPrintable(bad_run.err));
    QVERIFY(!QDir(fresh + "/point-0001").exists());
    QVERIFY(!bad_run.err.contains("points done"));

    // The task index of `study task DIR INDEX` is a whole number ≥ 0.
    for (const char* index : {"1.5", "-1", "x", ""}) {
      const Result task = Run({"study", "task", out, index});
      QCOMPARE(task.exit_code, 2);
      QVERIFY2(
          task.err.contains(QString("task index = '%1': must be a whole number ≥ 0").arg(index)),
          qPrintable(task.err));
    }

    // Another study into the same folder is refused.
    Write(file, QByteArray(kStudy).replace("6000", "4000"));
    const Result other = Run({"study", file, "--out", out});
    QCOMPARE(other.exit_code, 2);
    QVERIFY2(other.err.contains("holds a different study"), qPrintable(other.err));
  }

  // The study folder keeps its own copy of the base case (base-case.json, its pressure curves
  // inline): a resume after the case file was edited is refused, naming what changed (its points
  // would mix two cases; the old code relabelled the done points with the new base values), and
  // status / collect / a Slurm task read the folder's copy, even once the case file is gone. A
  // task skips a point that is done already (a requeued task).
  void theStudyFolderKeepsItsBaseCase() {
    QTemporaryDir dir;
    const QString seed = dir.filePath("seed");
    const Result made =
        Run({"run", "--model", "ideal", "--rpm", "2000", "--out", seed, "--no-fields", "--quiet"});
    QVERIFY2(made.exit_code == 0, qPrintable(made.err));
    QByteArray base_case = Read(seed + "/case-as-run.json");
    base_case.replace("\"lubricated\"", "\"ideal\"");  // both joints ideal: quick points
    const QString case_file = dir.filePath("case.json");
    Write(case_file, base_case);
    const QString file = dir.filePath("pin.json");
    Write(file, R"({"name": "pin", "case": "case.json", "design": "one-at-a-time",
      "set": {"solver.error_estimate": 0, "solver.max_cycles": 2},
      "factors": [{"path": "lubricant.viscosity", "levels": [0.02, 0.03]}]})");
    const QString out = dir.filePath("pin");
    const Result first = Run({"study", file, "--out", out, "--quiet"});
    QVERIFY2(first.exit_code == 0, qPrintable(first.err));
    QVERIFY(QFile::exists(out + "/base-case.json"));
    QVERIFY(!Read(out + "/base-case.json").contains("\"file\""));  // curves inline
    const QByteArray table = Read(out + "/study.csv");

    // The piston's mass edited in the case file: the resume is refused, nothing changes.
    Write(case_file,
          QByteArray(base_case).replace("\"piston_mass\": 0.264", "\"piston_mass\": 0.3125"));
    QVERIFY(Read(case_file) != base_case);
    const Result resumed = Run({"study", file, "--out", out, "--quiet"});
    QCOMPARE(resumed.exit_code, 2);
    QVERIFY2(resumed.err.contains("differs from the base case the study in") &&
                 resumed.err.contains("0.3125"),
             qPrintable(resumed.err));
    QCOMPARE(Read(out + "/study.csv"), table);

    // A case whose curves are files (the shipped default case, its curves among the built-in
    // resources): the refusal names the changed field only, not the curves, which the folder's
    // copy holds inline.
    {
      QFile shipped(QString(FILMDYN_SOURCE_DIR) + "/resources/cases/default.json");
      QVERIFY(shipped.open(QIODevice::ReadOnly));
      const QByteArray text = shipped.readAll();
      const QString files_case = dir.filePath("files.json");
      Write(files_case, text);
      const QString files_study = dir.filePath("files-study.json");
      Write(files_study, R"({"name": "files", "case": "files.json", "design": "one-at-a-time",
        "set": {"solver.error_estimate": 0, "solver.max_cycles": 2, "model": "ideal"},
        "factors": [{"path": "lubricant.viscosity", "levels": [0.02, 0.03]}]})");
      const QString files_out = dir.filePath("files");
      const Result ran = Run({"study", files_study, "--out", files_out, "--quiet"});
      QVERIFY2(ran.exit_code == 0, qPrintable(ran.err));
      Write(files_case, QByteArray(text).replace("\"piston_mass\": 0.264", "\"piston_mass\": 0.3"));
      const Result refused = Run({"study", files_study, "--out", files_out, "--quiet"});
      QCOMPARE(refused.exit_code, 2);
      QVERIFY2(refused.err.contains("geometry.piston_mass 0.264 kg → now 0.3 kg") &&
                   !refused.err.contains("pressure"),
               qPrintable(refused.err));
    }

    // The case file gone: the folder still reads.
    QVERIFY(QFile::remove(case_file));
    const Result collect = Run({"study", "collect", out});
    QVERIFY2(collect.exit_code == 0, qPrintable(collect.err));
    QCOMPARE(Read(out + "/study.csv"), table);
    QVERIFY2(Run({"study", "status", out}).out.startsWith("2 points, 2 done"),
             qPrintable(Run({"study", "status", out}).out));

    // A task of a submission listing a done point skips it, its folder untouched.
    QVERIFY(QDir(out).mkpath("slurm"));
    Write(out + "/slurm/points-1.txt", "point-0002\n");
    const QByteArray summary = Read(out + "/point-0002/summary.json");
    const Result task = Run({"study", "task", out, "0", "--points-list", "points-1.txt"});
    QVERIFY2(task.exit_code == 0, qPrintable(task.err));
    QVERIFY2(task.err.contains("point-0002 is done already: skipped"), qPrintable(task.err));
    QCOMPARE(Read(out + "/point-0002/summary.json"), summary);
    // An index past the list's tasks names no task (the largest one used to overflow).
    for (const char* index : {"1", "9223372036854775807"}) {
      const Result past = Run({"study", "task", out, index, "--points-list", "points-1.txt"});
      QCOMPARE(past.exit_code, 2);
      QVERIFY2(past.err.contains("must be below 1, the number of tasks of slurm/points-1.txt"),
               qPrintable(past.err));
    }

    // Options are checked before the points: a bad --jobs, or a Slurm option on a local study,
    // is refused with nothing written.
    Write(case_file, base_case);
    const QString fresh = dir.filePath("fresh");
    const Result jobs = Run({"study", file, "--out", fresh, "--jobs", "0"});
    QCOMPARE(jobs.exit_code, 2);
    QVERIFY2(jobs.err.contains("--jobs = 0"), qPrintable(jobs.err));
    const Result slurm_only = Run({"study", file, "--out", fresh, "--points-per-task", "2"});
    QCOMPARE(slurm_only.exit_code, 2);
    QVERIFY2(slurm_only.err.contains("is an option of --scheduler slurm"),
             qPrintable(slurm_only.err));
    QVERIFY(!QDir(fresh).exists());
  }

  void pointsThatStopEarlyAreRecordedWithTheirReason() {
    // A wall-time limit no film run can meet: every Only-LBRBE point stops early; each is
    // recorded as incomplete with its reason, and none stops the others.
    QTemporaryDir dir;
    const QString file = dir.filePath("short.json");
    QByteArray study(kStudy);
    study.replace("\"name\": \"quick\",", "\"name\": \"short\", \"time_limit_s\": 0.05,");
    Write(file, study);
    const QString out = dir.filePath("short");
    const Result r = Run({"study", file, "--out", out, "--quiet"});
    QCOMPARE(r.exit_code, 1);
    QVERIFY2(r.err.contains("point-0003: time-limit"), qPrintable(r.err));
    QVERIFY2(r.err.contains("point-0004: time-limit"), qPrintable(r.err));
    const QList<QByteArray> lines = Read(out + "/study.csv").trimmed().split('\n');
    QCOMPARE(lines.size(), 5);
    QVERIFY2(lines[3].contains(",incomplete,time-limit,"), lines[3].constData());
    QVERIFY2(lines[3].contains("wall-time limit reached"), lines[3].constData());
  }
};

QTEST_GUILESS_MAIN(TestCliStudy)
#include "test_cli_study.moc"
