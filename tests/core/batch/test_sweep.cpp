// Several ideal-model runs on a thread pool: every job finishes exactly once, writes its folder,
// agrees with the same run made alone; a cancel raised before a job's turn leaves it unstarted
// with its folder untouched.
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>
#include <iterator>
#include <set>

#include "core/batch/sweep.hpp"
#include "core/io/case_file.hpp"
#include "core/io/run_summary.hpp"

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

  // A cancel raised before a job's turn: the job never starts, and its folder — here an earlier
  // run's complete results, which the job was to replace — is left as it was (a Ctrl-C used to
  // start every queued job, each wiping its folder first, to end it at once as "cancelled").
  void cancelledJobsNotStartedKeepTheirFolders() {
    QTemporaryDir dir;
    auto jobs = MakeJobs(dir.path().toStdString());
    {
      batch::SweepRunner first(jobs, 2, nullptr);
      while (first.WaitNext(std::chrono::milliseconds(100)) != -1) {
      }
    }
    auto read = [](const std::filesystem::path& file) {
      std::ifstream in(file, std::ios::binary);
      return std::string(std::istreambuf_iterator<char>(in), {});
    };
    std::vector<std::string> before;
    for (auto& job : jobs) {
      before.push_back(read(job.output_folder / "summary.json"));
      job.overwrite = true;
    }
    std::atomic<bool> cancel{true};
    batch::SweepRunner runner(jobs, 2, &cancel);
    int count = 0;
    for (int index; (index = runner.WaitNext(std::chrono::milliseconds(100))) != -1;) {
      if (index == -2) continue;
      ++count;
      QVERIFY(runner.outcome(index).not_started);
      QVERIFY(runner.outcome(index).error.empty());
      QCOMPARE(read(jobs[index].output_folder / "summary.json"), before[std::size_t(index)]);
      QVERIFY(std::filesystem::exists(jobs[index].output_folder / "results.csv"));
    }
    QCOMPARE(count, 4);
  }

  // A job refused by the run's own set-up (here a lubricated skirt in a build without film
  // models: an input error the case check cannot see) ends with that error, and its folder's
  // summary says "failed" with it, not "running" (which reads as a run killed).
  void aJobRefusedAtItsSetUpLeavesAFailedSummary() {
    QTemporaryDir dir;
    auto jobs = MakeJobs(dir.path().toStdString());
    jobs.resize(1);
    const io::LoadedCase loaded = io::LoadCase("");
    jobs[0].config = engine::MakeRunConfig(loaded.value, engine::Model::kOnlySkirt, 1000.0,
                                           io::PressureCurveForSpeed(loaded, 1000.0));
    jobs[0].config.factories = {};
    batch::SweepRunner runner(jobs, 1, nullptr);
    while (runner.WaitNext(std::chrono::milliseconds(100)) != -1) {
    }
    const std::string error = runner.outcome(0).error;
    QVERIFY2(error.find("skirt.model") != std::string::npos, error.c_str());
    const io::RunSummary summary = io::ReadSummaryJson(jobs[0].output_folder / "summary.json");
    QCOMPARE(summary.status, std::string("failed"));
    QVERIFY(!summary.complete);
    QCOMPARE(summary.message, error);
  }
};

QTEST_GUILESS_MAIN(TestSweep)
#include "test_sweep.moc"
