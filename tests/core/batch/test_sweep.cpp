// Several ideal-model runs on a thread pool: every job finishes exactly once, writes its folder,
// agrees with the same run made alone; a raised cancel flag ends every job cleanly.
#include <QTemporaryDir>
#include <QtTest>
#include <set>

#include "core/batch/sweep.hpp"
#include "core/io/case_file.hpp"

using namespace filmdyn;

namespace {

std::vector<batch::SweepJob> MakeJobs(const std::filesystem::path& root) {
  const io::LoadedCase loaded = io::LoadCase("");
  std::vector<batch::SweepJob> jobs;
  for (double rpm : {1000.0, 2000.0, 4000.0, 6000.0}) {
    batch::SweepJob job;
    job.config = engine::MakeRunConfig(loaded.value, engine::Model::kIdeal, rpm,
                                       io::PressureCurveForSpeed(loaded, rpm));
    job.case_name = std::string(1, 't');  // (GCC 12 warns falsely on assigning the literal)
    job.output_folder = root / ("ideal-" + std::to_string(int(rpm)));
    jobs.push_back(std::move(job));
  }
  return jobs;
}

}  // namespace

class TestSweep : public QObject {
  Q_OBJECT
 private slots:
  void everyJobOnceWithFoldersAndSameResultsAsAlone() {
    QTemporaryDir dir;
    const auto jobs = MakeJobs(dir.path().toStdString());
    batch::SweepRunner runner(jobs, 2, nullptr);
    std::set<int> seen;
    for (int index; (index = runner.WaitNext(std::chrono::milliseconds(100))) != -1;) {
      if (index == -2) continue;
      QVERIFY2(seen.insert(index).second, "a job was returned twice");
      const auto& outcome = runner.outcome(index);
      QVERIFY2(outcome.error.empty(), outcome.error.c_str());
      QCOMPARE(outcome.result.status, engine::RunStatus::kCompleted);
      QVERIFY(std::filesystem::exists(jobs[index].output_folder / "results.csv"));
      QVERIFY(std::filesystem::exists(jobs[index].output_folder / "summary.json"));
      QCOMPARE(outcome.rows.size(), outcome.result.samples.size());
    }
    QCOMPARE(int(seen.size()), int(jobs.size()));
    for (double f : runner.Fractions()) QCOMPARE(f, 1.0);

    // The 6000 rpm run alone gives the same numbers as inside the pool (no shared state).
    const auto alone = engine::RunJob(jobs[3].config, nullptr, nullptr);
    const auto& pooled = runner.outcome(3).result;
    QCOMPARE(alone.samples.size(), pooled.samples.size());
    for (std::size_t k = 0; k < alone.samples.size(); k += 37) {
      QCOMPARE(alone.samples[k].gas_force, pooled.samples[k].gas_force);
      QCOMPARE(alone.samples[k].big_end_force_on_rod.y(),
               pooled.samples[k].big_end_force_on_rod.y());
    }
  }

  void cancelEndsEveryJobWithItsFolder() {
    QTemporaryDir dir;
    const auto jobs = MakeJobs(dir.path().toStdString());
    std::atomic<bool> cancel{true};
    batch::SweepRunner runner(jobs, 2, &cancel);
    int count = 0;
    for (int index; (index = runner.WaitNext(std::chrono::milliseconds(100))) != -1;) {
      if (index == -2) continue;
      ++count;
      QCOMPARE(runner.outcome(index).result.status, engine::RunStatus::kCancelled);
      QVERIFY(std::filesystem::exists(jobs[index].output_folder / "summary.json"));
    }
    QCOMPARE(count, 4);
  }
};

QTEST_GUILESS_MAIN(TestSweep)
#include "test_sweep.moc"
