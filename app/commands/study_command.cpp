// `filmdyn study`: a design study over any case fields (core/batch/study.hpp): every point is
// checked before anything runs, the points run in parallel on this machine (batch::SweepRunner),
// a re-run skips the points whose results are complete, and `collect` / `status` read a study
// folder at any time. docs/study.md.
#include <fmt/format.h>

#include <sys/wait.h>

#include <QString>

#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "app/commands/commands.hpp"
#include "app/commands/run_common.hpp"
#include "core/base/input_error.hpp"
#include "core/batch/study.hpp"
#include "core/batch/sweep.hpp"
#include "core/io/output_files.hpp"
#include "ui/plots/study_charts.hpp"

namespace filmdyn::cli {

namespace {

namespace fs = std::filesystem;

// Bytes a point's folder takes: results.csv (~520 B a row), motion.csv (8 rows of ~140 B per
// output step), summary.json (~10 kB), case-as-run.json (~40 kB: the case and its pressure
// curve), and with fields the film arrays (3 single-precision values per node and output step,
// before compression: an upper bound, which the disk-space check wants). Measured on the default
// case (2026-11-30): 1.3 MB without fields; with them 11.6 MB, of which fields/ 10.4 MB against
// the 15.9 MB of film arrays counted here.
double PointBytes(const engine::EngineCase& c, bool fields) {
  const double steps = std::max(1.0, std::round(4 * M_PI / c.solver.output_interval));
  double bytes = steps * (520.0 + 8 * 140.0) + 50e3;
  if (fields) {
    const double skirt_nodes =
        double((c.skirt.mesh_thrust + c.skirt.mesh_anti + c.skirt.mesh_relief + 3) *
               (c.skirt.mesh_axial + 1));
    const double bearing_nodes = double(c.big_end.mesh_theta * (c.big_end.mesh_z + 1));
    bytes += steps * (skirt_nodes + bearing_nodes) * 3 * 4;
  }
  return bytes;
}

std::string Duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  if (seconds < 90) return fmt::format("{:.0f} s", seconds);
  if (seconds < 5400) return fmt::format("{:.0f} min", seconds / 60);
  return fmt::format("{:.1f} h", seconds / 3600);
}

// Writes study.csv, study.md and plots/ of `dir` from its folders; returns the rows. The plots
// are drawn when a point is done; a plot that cannot be drawn is a warning, never an error.
std::vector<batch::StudyRow> Collect(const fs::path& dir, const batch::Study& study,
                                     const Args& args, Streams& streams) {
  // One collect at a time, reading the folders under the lock: the last to write is the last to
  // read (a `collect` started during a study could otherwise write its older table after the
  // study's final one).
  const io::WaitedLock lock(dir / ".filmdyn-collect.lock", "study collect");
  const std::vector<batch::StudyRow> rows = batch::CollectStudy(dir, study);
  const std::string rank_by = args.Value("rank-by").value_or("");
  std::ostringstream csv;
  batch::WriteStudyCsv(csv, study, rows);
  io::WriteFileAtomically(dir / "study.csv", csv.str());
  io::WriteFileAtomically(dir / "study.md",
                          batch::StudyMarkdown(study, rows, rank_by, args.Has("largest-first")));
  QString error;
  try {
    ui::ExportStudyPlots(study, rows, QString::fromStdString(dir.string()), rank_by,
                         args.Has("largest-first"), &error);
  } catch (const std::exception& e) {
    error = QString::fromUtf8(e.what());
  }
  if (!error.isEmpty()) streams.err << "study: plots not written: " << error.toStdString() << "\n";
  return rows;
}

// --points-per-task: the points each array task runs.
long PointsPerTask(const Args& args) {
  const long per_task = args.Integer("points-per-task").value_or(1);
  if (per_task < 1 || per_task > 100000) {
    throw InputError("--points-per-task", std::to_string(per_task),
                     "must be an integer in [1, 100000]");
  }
  return per_task;
}

// The INDEX of `study task DIR INDEX`: a whole number ≥ 0 (parsed as Args::Integer parses an
// integer option, without a sign).
long TaskIndex(const std::string& text) {
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos ||
      end != text.c_str() + text.size() || errno == ERANGE) {
    throw InputError("task index", "'" + text + "'", "must be a whole number ≥ 0");
  }
  return value;
}

std::string Counts(const std::vector<batch::StudyRow>& rows) {
  int counts[5] = {0, 0, 0, 0, 0};
  for (const auto& r : rows) ++counts[int(r.state)];
  std::string text = fmt::format("{} points", rows.size());
  for (batch::PointState s :
       {batch::PointState::kDone, batch::PointState::kFailed, batch::PointState::kIncomplete,
        batch::PointState::kRunning, batch::PointState::kPending}) {
    if (counts[int(s)] > 0)
      text += fmt::format(", {} {}", counts[int(s)], batch::PointStateName(s));
  }
  return text;
}

// The run of one point into `out / point.folder`, checked (the case through the case reader,
// the pressure curve for its speed).
batch::SweepJob JobForPoint(const batch::Study& study, const batch::StudyPoint& point,
                            const fs::path& out) {
  const io::LoadedCase loaded = batch::LoadPointCase(study, point);
  const engine::EngineCase& c = loaded.value;
  batch::SweepJob job;
  try {
    job.config = BuildRunConfig(loaded, engine::ModelOfCase(c), c.operating.rpm, std::nullopt,
                                study.time_limit_s);
  } catch (const InputError& e) {
    throw InputError("point " + std::to_string(point.number) + ": " + e.field(), e.value(),
                     e.allowed());
  }
  job.case_name = c.name;
  job.output_folder = out / point.folder;
  job.write_fields = study.write_fields;
  job.overwrite = true;  // a point's folder is the study's own: an incomplete run is replaced
  job.keep_results = false;
  return job;
}

// Runs the jobs `make(0)` … `make(names.size() − 1)` on this machine, `parallel` at a time, with
// a progress line; returns the number that failed or stopped early. `names` labels each job in
// messages. The jobs are made in chunks of a few per slot (a run's configuration holds its case
// and pressure curve, ~60 kB: a study of 10 000 points would hold 600 MB at once otherwise).
int RunPoints(const std::function<batch::SweepJob(std::size_t)>& make,
              const std::vector<std::string>& names, int parallel, bool quiet, Streams& streams) {
  const std::size_t total = names.size();
  if (total == 0) return 0;
  parallel = std::min<int>(parallel, int(total));
  const long cores = std::max(1u, std::thread::hardware_concurrency());
  const InterruptGuard interrupt;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t chunk = std::size_t(std::max(16, 8 * parallel));
  int done = 0, failed = 0, not_started = 0;
  for (std::size_t begin = 0; begin < total && !interrupt.flag()->load(); begin += chunk) {
    const std::size_t end = std::min(total, begin + chunk);
    std::vector<batch::SweepJob> jobs;
    for (std::size_t k = begin; k < end; ++k) {
      jobs.push_back(make(k));
      jobs.back().config.threads = cores >= 2 * parallel ? 2 : 1;
    }
    batch::SweepRunner runner(std::move(jobs), parallel, interrupt.flag());
    for (int index; (index = runner.WaitNext(std::chrono::milliseconds(500))) != -1;) {
      if (index >= 0) {
        const batch::SweepOutcome& outcome = runner.outcome(index);
        if (outcome.not_started) {  // stopped before its turn: its folder as it was
          ++not_started;
          continue;
        }
        ++done;
        const bool ok =
            outcome.error.empty() && (outcome.result.status == engine::RunStatus::kCompleted ||
                                      outcome.result.status == engine::RunStatus::kNotConverged);
        if (!ok) {
          ++failed;
          if (!quiet) streams.err << "\n";
          streams.err << "study: " << names[begin + size_t(index)] << ": "
                      << (outcome.error.empty() ? engine::StatusName(outcome.result.status) +
                                                      " — " + outcome.result.message
                                                : "failed: " + outcome.error)
                      << "\n";
        }
      }
      if (!quiet) {
        double progress = double(begin);
        for (double f : runner.Fractions()) progress += f;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double remaining =
            progress > 0.05 ? elapsed * (double(total) - progress) / progress : NAN;
        streams.err << fmt::format("\rstudy: {}/{} points done, {} failed, ETA {}   ", done, total,
                                   failed, Duration(remaining))
                    << std::flush;
      }
    }
  }
  if (!quiet) streams.err << "\n";
  if (const std::size_t left = total - std::size_t(done); left > 0) {
    streams.err << fmt::format(
        "study: stopped; {} point(s) not started, their folders as they were\n", left);
  }
  return failed + not_started;
}

// The path of this executable (the job script calls it on the compute nodes).
fs::path ThisExecutable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path("filmdyn") : self;
}

// Runs a command and returns its exit code and output (stdout and stderr together).
std::pair<int, std::string> Capture(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return {-1, "cannot start: " + command};
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = ::pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

bool OnPath(const std::string& program) {
  return Capture("command -v " + program + " >/dev/null").first == 0;
}

std::string ShellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The job array of a study on Slurm: DIR/slurm/points-N.txt (the points to run, one folder a
// line; N counts this folder's submissions, so that tasks of an earlier array still queued keep
// reading their own list), DIR/slurm/study.sbatch (one array task per chunk of points),
// submitted with sbatch.
int SubmitToSlurm(const Args& args, Streams& streams, const fs::path& out,
                  const std::vector<std::string>& folders) {
  if (folders.empty()) {
    streams.err << "study: nothing to submit; every point is done or running\n";
    return 0;
  }
  const long per_task = PointsPerTask(args);
  const long tasks = (long(folders.size()) + per_task - 1) / per_task;
  const fs::path slurm = out / "slurm";
  fs::create_directories(slurm);
  std::string list;
  for (const std::string& f : folders) list += f + "\n";
  // Under the study folder's lock: no other submission picks the same number.
  int submission = 1;
  while (fs::exists(slurm / fmt::format("points-{}.txt", submission))) ++submission;
  const std::string list_name = fmt::format("points-{}.txt", submission);
  io::WriteFileAtomically(slurm / list_name, list);
  std::string script = "#!/bin/bash\n";
  script += "#SBATCH --job-name=filmdyn-study\n";
  script += fmt::format("#SBATCH --array=0-{}", tasks - 1);
  if (const auto max = args.Integer("max-parallel")) script += fmt::format("%{}", *max);  // ≥ 1
  script += "\n#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n";
  script += "#SBATCH --output=" + (fs::absolute(slurm) / "task-%A_%a.out").string() + "\n";
  if (const auto partition = args.Value("partition"))
    script += "#SBATCH --partition=" + *partition + "\n";
  if (const auto time = args.Value("time")) script += "#SBATCH --time=" + *time + "\n";
  script +=
      "# One array task runs its chunk of DIR/slurm/" + list_name + " (filmdyn study task).\n";
  script += "exec " + ShellQuote(ThisExecutable().string()) + " study task " +
            ShellQuote(fs::absolute(out).string()) +
            " \"$SLURM_ARRAY_TASK_ID\" --points-per-task " + std::to_string(per_task) +
            " --points-list " + list_name + "\n";
  io::WriteFileAtomically(slurm / "study.sbatch", script);
  const auto [code, output] =
      Capture("sbatch --parsable " + ShellQuote((slurm / "study.sbatch").string()));
  if (code != 0) {
    fs::remove(slurm / list_name);  // submitted nothing: the number is free again
    throw InputError("--scheduler", "slurm",
                     "sbatch failed (exit " + std::to_string(code) + "): " + output);
  }
  // --parsable prints "jobid[;cluster]" as its last line (warnings may come before it).
  std::string job;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0])))
      job = line.substr(0, line.find(';'));
  }
  if (job.empty()) {
    throw InputError("--scheduler", "slurm", "sbatch printed no job number: " + output);
  }
  std::ofstream(slurm / "jobs.txt", std::ios::app) << job << "\n";
  streams.err << fmt::format(
      "study: submitted job array {} ({} tasks, {} points); "
      "`filmdyn study status {}` follows it, `filmdyn study collect {}` "
      "tabulates what has finished\n",
      job, tasks, folders.size(), out.string(), out.string());
  streams.out << job << "\n";
  return 0;
}

// `filmdyn study task DIR INDEX`: what one array task runs — its chunk of the points listed in
// DIR/slurm/<--points-list> (points.txt by default, as arrays submitted by earlier versions
// name it), one after the other, by the same code as a local study. A point already done (a
// requeued task, or one run meanwhile by another submission) or being run by another process is
// skipped, its folder untouched.
int RunTask(const Args& args, Streams& streams) {
  if (args.positional().size() != 3) {
    throw InputError("study task", "(arguments)", "needs DIR and the task index");
  }
  const fs::path dir = args.positional()[1];
  const long index = TaskIndex(args.positional()[2]);
  const long per_task = PointsPerTask(args);
  const batch::Study study = batch::ReadStudyFolder(dir);
  const std::vector<batch::StudyPoint> points =
      batch::DesignPoints(study, batch::LoadStudyBase(study).value);
  const std::string list_name = args.Value("points-list").value_or("points.txt");
  if (list_name.empty() || list_name.find('/') != std::string::npos || list_name[0] == '.') {
    throw InputError("--points-list", list_name, "must be a file name in DIR/slurm");
  }
  std::ifstream list(dir / "slurm" / list_name);
  if (!list)
    throw InputError("--points-list", (dir / "slurm" / list_name).string(), "cannot be read");
  std::vector<std::string> folders;
  for (std::string line; std::getline(list, line);) {
    if (!line.empty()) folders.push_back(line);
  }
  // The array has one task per chunk of the list: a larger index names no task.
  const long tasks = (long(folders.size()) + per_task - 1) / per_task;
  if (index >= tasks) {
    throw InputError("task index", std::to_string(index),
                     fmt::format("must be below {}, the number of tasks of slurm/{} ({} points, "
                                 "{} per task)",
                                 tasks, list_name, folders.size(), per_task));
  }
  std::vector<const batch::StudyPoint*> mine;
  std::vector<std::string> names;
  for (long k = index * per_task; k < std::min<long>((index + 1) * per_task, long(folders.size()));
       ++k) {
    const auto point = std::find_if(points.begin(), points.end(), [&](const batch::StudyPoint& p) {
      return p.folder == folders[size_t(k)];
    });
    if (point == points.end()) {
      throw InputError("slurm/" + list_name, folders[size_t(k)], "is not a point of this study");
    }
    if (const batch::PointState state = batch::ReadPointState(dir / point->folder);
        state == batch::PointState::kDone || state == batch::PointState::kRunning) {
      streams.err << "study task: " << point->folder << " is " << batch::PointStateName(state)
                  << " already: skipped\n";
      continue;
    }
    mine.push_back(&*point);
    names.push_back(point->folder);
  }
  const int failed = RunPoints([&](std::size_t k) { return JobForPoint(study, *mine[k], dir); },
                               names, 1, true, streams);
  return failed == 0 ? 0 : 1;
}

int RunStudy(const Args& args, Streams& streams) {
  const fs::path file = args.positional()[0];
  const batch::Study study = batch::ReadStudyFile(file);
  const io::LoadedCase base = batch::LoadStudyBase(study);
  for (const std::string& note : base.notes) streams.err << "filmdyn: note: " << note << "\n";
  const std::vector<batch::StudyPoint> points = batch::DesignPoints(study, base.value);
  const fs::path out = args.Value("out")
                           ? fs::path(*args.Value("out"))
                           : fs::path("results") / ("study-" + io::SafeFolderName(study.name));
  const std::string scheduler = args.Value("scheduler").value_or("local");
  if (scheduler != "local" && scheduler != "slurm") {
    throw InputError("--scheduler", scheduler, "must be local or slurm");
  }
  // Every option is checked before the points are (a large study takes a while to check).
  if (scheduler == "local") {
    JobsOption(args);
    for (const char* option : {"partition", "time", "max-parallel", "points-per-task"}) {
      if (args.Value(option)) {
        throw InputError(std::string("--") + option, *args.Value(option),
                         "is an option of --scheduler slurm; this study runs here (local)");
      }
    }
  } else {
    PointsPerTask(args);
    if (const auto max = args.Integer("max-parallel"); max && *max < 1)
      throw InputError("--max-parallel", std::to_string(*max), "must be ≥ 1");
  }
  if (scheduler == "slurm" && !OnPath("sbatch")) {
    throw InputError("--scheduler", "slurm",
                     "needs Slurm's sbatch on the PATH of this machine (the cluster's login "
                     "node); it was not found");
  }

  // Every point's case and run configuration is checked before anything runs (and its folder's
  // size estimated); the runs are made again when they start.
  std::vector<double> point_bytes;
  for (const batch::StudyPoint& point : points) {
    point_bytes.push_back(
        PointBytes(JobForPoint(study, point, out).config.engine_case, study.write_fields));
  }

  if (args.Has("dry-run")) {
    batch::WriteDesignCsv(streams.out, study, points);
    double bytes = 0;
    for (double b : point_bytes) bytes += b;
    streams.err << fmt::format(
        "study: {} points ({} design), {} {:.0f} MB on disk{}; nothing run\n", points.size(),
        batch::StudyDesignName(study.design), study.write_fields ? "at most about" : "about",
        bytes / 1e6,
        study.write_fields ? " (the film fields counted before compression: on the default "
                             "case they take about two thirds of it)"
                           : "");
    return 0;
  }

  // The study folder: locked while this command works in it; a different study there refused.
  io::CreateFolder(out, "--out");
  const std::string definition = batch::StudyJson(study);
  // Throws when `out` holds another study.
  auto refuse_other_study = [&out, &definition] {
    std::ifstream in(out / "study.json", std::ios::binary);
    std::ostringstream existing;
    existing << in.rdbuf();
    if (existing.str() != definition) {
      throw InputError("--out", out.string(),
                       "holds a different study (its study.json differs from this one's); "
                       "choose another folder, or remove it to start again");
    }
  };
  // The plots/ of this same study (an earlier run's or collect's) are no earlier run to refuse:
  // the lock removes them, and they are drawn again from the folders at the end (or by
  // `collect`). Another study is refused first, untouched; so is any other folder holding a
  // run's files.
  const bool study_folder = fs::exists(out / "study.json");
  if (study_folder) refuse_other_study();
  const io::OutputFolder lock(
      out, study_folder ? io::OutputFolder::Reuse::kReplace : io::OutputFolder::Reuse::kRefuse,
      "--out");
  if (fs::exists(out / "study.json")) {
    refuse_other_study();  // again, under the lock
  } else if (std::any_of(fs::directory_iterator(out), fs::directory_iterator(),
                         [](const fs::directory_entry& e) {
                           return e.path().filename() != io::OutputFolder::kLockFile;
                         })) {
    throw InputError("--out", out.string(),
                     "is not empty and holds no study; choose an empty or new folder");
  }

  // Every point of the folder is made from its copy of the base case (written now for a new
  // study); a case file changed since the study began is refused, before anything is written.
  const batch::Study pinned = batch::PinStudyBase(out, study, base);

  // What is left to do: points whose results are complete are kept.
  std::vector<int> job_point;
  int kept = 0, elsewhere = 0;
  double bytes = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const batch::PointState state = batch::ReadPointState(out / points[k].folder);
    if (state == batch::PointState::kDone) {
      ++kept;
      continue;
    }
    if (state == batch::PointState::kRunning) {  // another process is computing it
      ++elsewhere;
      continue;
    }
    bytes += point_bytes[k];
    job_point.push_back(int(k));
  }
  std::error_code ec;
  const fs::space_info space = fs::space(out, ec);
  if (!ec && bytes > double(space.available)) {
    throw InputError("--out", out.string(),
                     fmt::format("has {:.0f} MB free; the {} points to run need about {:.0f} MB",
                                 double(space.available) / 1e6, job_point.size(), bytes / 1e6));
  }
  io::WriteFileAtomically(out / "study.json", definition);
  std::ostringstream design;
  batch::WriteDesignCsv(design, study, points);
  io::WriteFileAtomically(out / "design.csv", design.str());
  const bool quiet = args.Has("quiet");
  streams.err << fmt::format("study: {} points ({}), {} already done{}, {} to run in {}\n",
                             points.size(), batch::StudyDesignName(study.design), kept,
                             elsewhere ? fmt::format(", {} running elsewhere", elsewhere) : "",
                             job_point.size(), out.string());
  std::vector<std::string> names;
  for (int k : job_point) names.push_back(points[size_t(k)].folder);
  if (scheduler == "slurm") return SubmitToSlurm(args, streams, out, names);

  RunPoints([&](std::size_t k) { return JobForPoint(pinned, points[size_t(job_point[k])], out); },
            names, JobsOption(args), quiet, streams);
  const std::vector<batch::StudyRow> rows = Collect(out, pinned, args, streams);
  streams.err << "study: " << Counts(rows) << "; " << (out / "study.csv").string() << ", "
              << (out / "study.md").string() << ", " << (out / "plots").string() << "\n";
  const bool all_done = std::all_of(rows.begin(), rows.end(), [](const batch::StudyRow& r) {
    return r.state == batch::PointState::kDone;
  });
  return all_done ? 0 : 1;
}

int CollectOrStatus(const Args& args, Streams& streams, bool collect) {
  if (args.positional().size() != 2) {
    throw InputError(args.positional()[0], "(missing)",
                     "needs the study folder: filmdyn study " + args.positional()[0] + " DIR");
  }
  const fs::path dir = args.positional()[1];
  const batch::Study study = batch::ReadStudyFolder(dir);
  if (collect) {
    const std::vector<batch::StudyRow> rows = Collect(dir, study, args, streams);
    streams.err << "study collect: " << Counts(rows) << "; " << (dir / "study.csv").string() << ", "
                << (dir / "study.md").string() << ", " << (dir / "plots").string() << "\n";
    return 0;
  }
  const std::vector<batch::StudyRow> rows = batch::CollectStudy(dir, study);
  streams.out << Counts(rows) << "\n";
  // The scheduler's view of the job arrays submitted for this folder.
  if (std::ifstream jobs(dir / "slurm" / "jobs.txt"); jobs) {
    for (std::string job; std::getline(jobs, job);) {
      if (job.empty()) continue;
      // sacct knows finished tasks too, but only where the cluster keeps accounting; squeue
      // knows the queued and running ones.
      if (OnPath("sacct")) {
        const auto [code, text] =
            Capture("sacct -X -n -P -o JobID,State,ExitCode,Elapsed -j " + ShellQuote(job));
        if (code == 0) {
          streams.out << "slurm job " << job << " (sacct: task|state|exit code|elapsed):\n" << text;
          continue;
        }
      }
      if (OnPath("squeue")) {
        const auto [code, text] = Capture("squeue -h -o '%i %T %M' -j " + ShellQuote(job));
        streams.out << "slurm job " << job
                    << (code == 0 ? (text.empty() ? ": no task queued or running\n"
                                                  : " (squeue: task state time):\n" + text)
                                  : ": squeue: " + text);
      }
    }
  }
  for (const batch::StudyRow& r : rows) {
    if (r.state == batch::PointState::kDone) continue;
    streams.out << r.point.folder << ": " << batch::PointStateName(r.state)
                << (r.reason.empty() ? "" : " — " + r.reason) << "\n";
  }
  return 0;
}

}  // namespace

Command MakeStudyCommand() {
  Command command;
  command.name = "study";
  command.summary = "design study over any case fields: factorial, Latin hypercube, one at a time";
  command.positional_usage = "STUDY.json | collect DIR | status DIR";
  command.max_positional = 3;  // also `task DIR INDEX` (what a Slurm array task runs)
  command.needs_gui_application = true;  // plots/ are rendered with Qt Charts (offscreen)
  command.options = {
      {"out", "DIR", "the study folder (default: ./results/study-<name>)"},
      {"jobs", "N", "points computed at the same time (default: number of cores)"},
      {"dry-run", "", "check every point and print the design (design.csv); run nothing"},
      {"rank-by", "KEY", "best points (study.md, plots/) by this study.csv column"},
      {"largest-first", "", "rank the best points largest first (default: smallest first)"},
      {"quiet", "", "no progress line on stderr"},
      {"scheduler", "local|slurm", "where the points run (default local; slurm: a job array)"},
      {"partition", "P", "slurm: the partition (sbatch --partition)"},
      {"time", "T", "slurm: the time limit of each array task (sbatch --time, e.g. 0:30:00)"},
      {"max-parallel", "N", "slurm: at most N array tasks at once (--array=…%N)"},
      {"points-per-task", "K", "slurm: points run one after the other by each array task (1)"},
      {"points-list", "FILE", "study task: the submission's list in DIR/slurm (points.txt)"}};
  command.details =
      "STUDY.json names the base case, the factors (case fields by dotted path, with levels or a\n"
      "range; operating.rpm and \"model\" among them) and the design (docs/study.md; an example\n"
      "is examples/study-skirt-clearance.json). Every point is checked before anything runs.\n"
      "Each point is a run folder DIR/point-NNNN/ like `filmdyn run` writes (without fields/\n"
      "unless the study asks for them); DIR/study.csv and DIR/study.md tabulate the points'\n"
      "figures, DIR/plots/ draws them (main effects, scatter matrix, best points). Running the\n"
      "same study into DIR again skips the points whose results are complete and re-runs the\n"
      "failed or incomplete ones; Ctrl-C stops cleanly.\n"
      "  filmdyn study collect DIR   rewrite study.csv, study.md and plots/ from the folders\n"
      "  filmdyn study status DIR    points done, running, failed, incomplete, pending\n"
      "With --scheduler slurm the points are submitted as a job array (DIR/slurm/study.sbatch,\n"
      "one task per --points-per-task points) and nothing runs here; `status` shows the\n"
      "scheduler's view, `collect` tabulates what has finished. `filmdyn study task DIR I` is\n"
      "what array task I runs.\n"
      "--rank-by KEY must be a figure's study.csv column; without it plots/best-points ranks\n"
      "by mean_bearing_fpl[W] (mean_skirt_fpl[W] when no point has a lubricated big end).\n"
      "Example:\n  filmdyn study examples/study-skirt-clearance.json --out results/clearance";
  command.run = [](const Args& args, Streams& streams) {
    if (args.positional().empty()) {
      throw InputError("study", "(missing)", "needs STUDY.json, or collect DIR, or status DIR");
    }
    // An unknown figure is refused before anything is read or run.
    if (const auto rank_by = args.Value("rank-by")) batch::StudyFigureIndex(*rank_by);
    const std::string& first = args.positional()[0];
    if (first == "collect" || first == "status")
      return CollectOrStatus(args, streams, first == "collect");
    if (first == "task") return RunTask(args, streams);
    if (args.positional().size() > 1) {
      throw InputError(args.positional()[1], "(argument)",
                       "is one argument too many: filmdyn study STUDY.json [options]");
    }
    return RunStudy(args, streams);
  };
  return command;
}

}  // namespace filmdyn::cli
