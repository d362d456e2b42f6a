#include "ui/runs/run_store.hpp"

#include <QDir>
#include <QFileInfo>
#include <QObject>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "core/base/input_error.hpp"
#include "core/io/case_file.hpp"
#include "core/io/field_series.hpp"
#include "core/io/output_files.hpp"
#include "core/io/run_summary.hpp"

namespace filmdyn::ui {

namespace fs = std::filesystem;

namespace {

constexpr char kFormat[] = "FilmDyn runs";
constexpr int kFormatVersion = 1;
constexpr char kIndex[] = "runs.json";
constexpr char kSamplesSuffix[] = ".samples.csv";
constexpr char kMotionSuffix[] = ".motion.csv";
constexpr char kKeyPrefix[] = "run-";
constexpr double kPi = std::numbers::pi;

fs::path PathOf(const QString& path) { return fs::path(path.toStdString()); }
QString QPath(const fs::path& path) { return QString::fromStdString(path.string()); }

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string() + ": missing or unreadable");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The samples as CSV: results.csv's leading column names, every double in its shortest exact
// form (std::to_chars), NaN as an empty cell.
std::string SamplesCsv(const std::vector<RunSample>& samples) {
  std::string out;
  for (int c = 0; c < kColumnCount; ++c) {
    if (c > 0) out += ',';
    out += kColumnHeaders[size_t(c)];
  }
  out += '\n';
  char buffer[64];
  for (const RunSample& s : samples) {
    for (int c = 0; c < kColumnCount; ++c) {
      if (c > 0) out += ',';
      const double v = s.values[size_t(c)];
      if (std::isnan(v)) continue;
      const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
      out.append(buffer, result.ptr);
    }
    out += '\n';
  }
  return out;
}

// Reads SamplesCsv's text. Columns are found by their header names: a file saved by an earlier
// version, which lacks columns added since, reads with those columns empty (NaN). With
// `skip_unknown` the columns this version does not show are skipped (results.csv and motion.csv
// of a run folder carry more columns than the plots draw); without, they are an error.
std::vector<RunSample> ParseSamplesCsv(const std::string& text, const fs::path& path,
                                       bool skip_unknown = false) {
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<int> columns;  // the Column of each of the file's columns
  for (std::size_t start = 0; start <= line.size();) {
    const std::size_t end = std::min(line.find(',', start), line.size());
    const std::string name = line.substr(start, end - start);
    const auto known = std::find(kColumnHeaders.begin(), kColumnHeaders.end(), name);
    if (known == kColumnHeaders.end() && skip_unknown) {
      columns.push_back(-1);
    } else if (known == kColumnHeaders.end() ||
               std::find(columns.begin(), columns.end(), int(known - kColumnHeaders.begin())) !=
                   columns.end()) {
      throw std::runtime_error(path.string() + ": the header's column \"" + name +
                               "\" is not one of the columns this version shows, or repeated");
    } else {
      columns.push_back(int(known - kColumnHeaders.begin()));
    }
    start = end + 1;
  }
  std::vector<RunSample> samples;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    RunSample sample;
    std::size_t start = 0;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const std::size_t end = std::min(line.find(',', start), line.size());
      if (columns[c] >= 0 && end > start) {  // (< 0: a column this version does not show)
        const char* name = kColumnHeaders[size_t(columns[c])];
        double v = 0;
        if (!ParseNumber(std::string_view(line).substr(start, end - start), v)) {
          throw std::runtime_error(path.string() + ": row " + std::to_string(row) + ", column " +
                                   name + " is not a number");
        }
        sample.values[size_t(columns[c])] = v;
      }
      if (c + 1 < columns.size() && end >= line.size()) {
        throw std::runtime_error(path.string() + ": row " + std::to_string(row) + " has " +
                                 std::to_string(c + 1) + " of " + std::to_string(columns.size()) +
                                 " columns");
      }
      start = end + 1;
    }
    samples.push_back(sample);
  }
  return samples;
}

// Copies a stored run folder's files (results.csv, summary.json, fields/) into `to`, each
// atomically.
void CopyFieldFiles(const fs::path& fields, const fs::path& to) {
  if (!fs::is_directory(fields)) throw std::runtime_error("this run has no film fields");
  bool any = false;
  for (const auto& entry : fs::directory_iterator(fields)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".h5" && ext != ".xdmf") continue;
    fs::create_directories(to);
    io::WriteFileAtomically(to / entry.path().filename(), ReadBytes(entry.path()));
    any = true;
  }
  if (!any) throw std::runtime_error("this run has no film fields");
}

RunWriters CopyingWriters(const fs::path& folder) {
  RunWriters writers;
  writers.folder = [folder](const std::string& dir) {
    const fs::path to(dir);
    try {
      io::CreateFolder(to, "export folder");
      io::WriteFileAtomically(to / "results.csv", ReadBytes(folder / "results.csv"));
      if (fs::is_directory(folder / "fields")) CopyFieldFiles(folder / "fields", to / "fields");
      for (const char* file : {"motion.csv", "case-as-run.json"}) {
        if (fs::exists(folder / file)) io::WriteFileAtomically(to / file, ReadBytes(folder / file));
      }
      // Last, as a run writes its folder: a summary is only ever beside complete files.
      io::WriteFileAtomically(to / "summary.json", ReadBytes(folder / "summary.json"));
    } catch (const std::exception& e) {
      // As a run whose files cannot be written: the copy's summary says it is not complete (when
      // that can be written; the caller has the message either way).
      try {
        io::RunSummary failed = io::ReadSummaryJson(folder / "summary.json");
        failed.status = engine::StatusName(engine::RunStatus::kFailed);
        failed.complete = false;
        failed.message =
            std::string("its files could not be copied from ") + folder.string() + ": " + e.what();
        io::WriteSummaryJson(to / "summary.json", failed);
      } catch (const std::exception&) {
      }
      throw;
    }
  };
  writers.csv = [folder] { return ReadBytes(folder / "results.csv"); };
  writers.fields = [folder](const std::string& dir) { CopyFieldFiles(folder / "fields", dir); };
  return writers;
}

const char* StatusKey(RunStatus status) {
  switch (status) {
    case RunStatus::kRunning:
      return "running";
    case RunStatus::kFinished:
      return "finished";
    case RunStatus::kFailed:
      return "failed";
    case RunStatus::kCancelled:
      return "cancelled";
  }
  return "failed";
}

RunStatus StatusFromKey(const std::string& key) {
  if (key == "finished") return RunStatus::kFinished;
  if (key == "cancelled") return RunStatus::kCancelled;
  if (key == "failed") return RunStatus::kFailed;
  throw std::runtime_error("status \"" + key + "\" is not finished, failed or cancelled");
}

// Whether `name` is a key of this layout (a run folder, its samples or their temporaries).
bool OwnEntry(const std::string& name) { return name.rfind(kKeyPrefix, 0) == 0; }

std::string KeyOfEntry(std::string name) {
  for (const std::string& suffix :
       {std::string(kSamplesSuffix), std::string(kMotionSuffix), std::string(".tmp")}) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
      name.resize(name.size() - suffix.size());
    }
  }
  return name;
}

void AddBigEndLoads(const fs::path& results_csv, FieldFrames* frames);

// The runs index at `path`, checked to be one this version reads; throws std::runtime_error
// saying why not (not JSON, not a runs index, saved by a newer FilmDyn, no list of runs).
nlohmann::json ReadRunsIndex(const fs::path& path) {
  nlohmann::json index = nlohmann::json::parse(ReadBytes(path));
  if (!index.is_object() || index.value("format", "") != kFormat) {
    throw std::runtime_error("not a FilmDyn runs index (\"format\" is not \"" +
                             std::string(kFormat) + "\")");
  }
  if (!index.contains("format_version") || !index["format_version"].is_number_integer() ||
      index["format_version"].get<int>() > kFormatVersion) {
    throw std::runtime_error("format_version must be an integer ≤ " +
                             std::to_string(kFormatVersion) + " (saved by a newer FilmDyn?)");
  }
  if (!index.contains("runs") || !index["runs"].is_array()) {
    throw std::runtime_error("\"runs\" must be a list");
  }
  return index;
}

// The run-folder key of an index entry ("" for an entry without a usable one).
std::string EntryKey(const nlohmann::json& entry) {
  if (!entry.is_object() || !entry.contains("key") || !entry["key"].is_string()) return {};
  const std::string key = entry["key"].get<std::string>();
  if (!OwnEntry(key) || key.find('/') != std::string::npos || key.find("..") != std::string::npos)
    return {};
  return key;
}

// Fills a run from the files of its run folder (as `filmdyn run` writes it): the counters and
// the error estimate of summary.json, the film fields, the writers that copy the files; throws
// std::runtime_error naming the file and the problem.
void RestoreFolder(RunRecord& run, const fs::path& folder, const io::RunSummary& summary) {
  ReportRunCounters(
      run, OilCounters({double(summary.cycles), double(summary.cycles_to_steady_state),
                        summary.cycle_to_cycle_change, double(summary.solver.steps),
                        double(summary.solver.rejected_steps), summary.max_constraint_violation,
                        double(summary.solver.reynolds_solves)},
                       summary.kpis));
  run.ReportErrorEstimate(summary.error_estimate);
  run.ReportCycleScatter(summary.cycle_scatter);
  run.ReportWarnings(summary.warnings);
  if (!fs::exists(folder / "results.csv")) {
    throw std::runtime_error("cannot read " + (folder / "results.csv").string() + ": missing");
  }
  if (fs::is_directory(folder / "fields")) {
    auto fields =
        ReadFieldFrames(QPath(folder / "fields"), run.request().engine_case, run.request().rpm);
    if (fields) {
      auto with_loads = std::make_shared<FieldFrames>(*fields);
      AddBigEndLoads(folder / "results.csv", with_loads.get());
      fields = with_loads;
    }
    run.ReportFields(fields);
  }
  run.SetWriters(CopyingWriters(folder));
  run.setStoredFolder(QPath(folder));
}

// Fills a run from its stored files; throws std::runtime_error naming the file and the problem.
void Restore(RunRecord& run, const fs::path& dir, const std::string& key, bool has_folder) {
  if (const fs::path motion = dir / (key + kMotionSuffix); fs::exists(motion)) {
    run.ReportMotion(ParseSamplesCsv(ReadBytes(motion), motion));
  }
  run.Report(
      ParseSamplesCsv(ReadBytes(dir / (key + kSamplesSuffix)), dir / (key + kSamplesSuffix)));
  const fs::path folder = dir / key;
  if (has_folder) RestoreFolder(run, folder, io::ReadSummaryJson(folder / "summary.json"));
  run.setStoredFolder(QPath(folder));
}

// The big end's load per field frame (crank pin on the rod, rod frame, as the live view records
// it) from results.csv: the global force turned by the rod angle of the row at the frame's crank
// angle. Left empty when a frame has no row.
void AddBigEndLoads(const fs::path& results_csv, FieldFrames* frames) {
  JointFieldFrames* big_end = nullptr;
  for (JointFieldFrames& joint : frames->joints) {
    if (joint.name == "big_end") big_end = &joint;
  }
  if (big_end == nullptr) return;
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    for (std::size_t start = 0; start <= line.size();) {
      const std::size_t end = std::min(line.find(',', start), line.size());
      cells.push_back(line.substr(start, end - start));
      start = end + 1;
    }
    return cells;
  };
  std::istringstream in(ReadBytes(results_csv));
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split(line);
  auto column = [&header](const std::string& name) {
    return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t rod = column("rod_angle[rad]"), fx = column("bigend_force_x[N]"),
                    fy = column("bigend_force_y[N]");
  if (rod >= header.size() || fx >= header.size() || fy >= header.size()) return;
  std::vector<std::array<double, 4>> rows;  // crank angle, rod angle, fx, fy
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    if (cells.size() != header.size()) continue;
    std::array<double, 4> row;
    const std::size_t from[] = {0, rod, fx, fy};
    for (int k = 0; k < 4; ++k) {
      const std::string& cell = cells[from[k]];
      row[size_t(k)] = std::numeric_limits<double>::quiet_NaN();
      ParseNumber(cell, row[size_t(k)]);  // a cell that is no number stays NaN
    }
    rows.push_back(row);
  }
  std::vector<std::array<double, 2>> loads;
  for (double frame_angle : frames->crank_angle_deg) {
    const auto row = std::find_if(rows.begin(), rows.end(), [frame_angle](const auto& r) {
      return std::abs(r[0] - frame_angle) < 1e-6;
    });
    if (row == rows.end() || !std::isfinite((*row)[2])) return;
    const double c = std::cos((*row)[1]), sn = std::sin((*row)[1]);
    loads.push_back({c * (*row)[2] + sn * (*row)[3], -sn * (*row)[2] + c * (*row)[3]});
  }
  big_end->load = std::move(loads);
}

// One joint of the view from core's field series.
JointFieldFrames JointFromSeries(const io::FieldSeries& series, bool big_end,
                                 const engine::EngineCase& engine_case,
                                 const std::vector<std::size_t>& kept) {
  JointFieldFrames joint;
  joint.name = big_end ? "big_end" : "skirt";
  joint.mesh.triangles = series.triangles;
  for (const auto& p : series.points) {
    // The big end's reference position has the film angle θ at π + θ (core's field files):
    // the view's points put θ at θ and turn each frame by its own angle instead.
    joint.mesh.points.push_back(big_end ? std::array<double, 3>{-p[0], -p[1], p[2]} : p);
  }
  const auto& points = joint.mesh.points;
  joint.radius = std::hypot(points.front()[0], points.front()[1]);
  joint.periodic = big_end;
  // The tensor grid: the first row's nodes share the axial position of node 0.
  std::size_t columns = 0;
  while (columns < points.size() && points[columns][2] == points.front()[2]) ++columns;
  if (columns > 0 && points.size() % columns == 0) {
    for (std::size_t i = 0; i < columns; ++i) {
      double angle = std::atan2(points[i][1], points[i][0]);
      if (big_end && angle < -1e-9) angle += 2 * kPi;
      joint.angle_lines.push_back(std::abs(angle) < 1e-12 ? 0.0 : angle);
    }
    for (std::size_t j = 0; j < points.size() / columns; ++j) {
      const double z = points[j * columns][2];
      joint.axial_lines.push_back(big_end ? z : -z);
    }
  }
  if (!big_end) {
    const double a1 = engine_case.skirt.thrust_half_width;
    const double a2 = engine_case.skirt.anti_thrust_half_width;
    if (kPi - a2 > a1) joint.no_film.push_back({a1, kPi - a2});
  }
  // The fluid fraction with mass-conserving cavitation only (with Reynolds cavitation core's θ,
  // when written, is 1 everywhere and says nothing).
  joint.mass_conserving =
      (big_end ? engine_case.big_end.cavitation : engine_case.skirt.cavitation) ==
      lubrication::CavitationModel::kJfo;
  static const char* const kArrays[] = {"pressure", "contact_pressure", "film_thickness",
                                        "fluid_fraction", "deformation"};
  std::vector<std::pair<const char*, std::size_t>> index;  // view name, series array
  for (const char* name : kArrays) {
    // The deformation is written for elastic surfaces only.
    const bool optional =
        std::string_view(name) == "fluid_fraction" || std::string_view(name) == "deformation";
    if (std::string_view(name) == "fluid_fraction" && !joint.mass_conserving) continue;
    int found = -1;
    for (std::size_t a = 0; a < series.array_names.size(); ++a) {
      if (series.array_names[a].substr(0, series.array_names[a].find('[')) == name) found = int(a);
    }
    if (found < 0 && optional) continue;  // fields written before core recorded it
    if (found < 0) {
      throw std::runtime_error(series.name + " field series: no array " + name);
    }
    index.push_back({name, std::size_t(found)});
  }
  for (std::size_t k : kept) {
    const io::SeriesFrame& frame = series.frames[k];
    std::vector<std::pair<std::string, std::vector<double>>> arrays;
    for (const auto& [name, a] : index) {
      const std::vector<float>& values = frame.arrays[a];
      arrays.push_back({name, std::vector<double>(values.begin(), values.end())});
    }
    joint.frames.push_back(std::move(arrays));
    if (big_end) joint.frame_rotation.push_back(std::remainder(frame.rotation_z + kPi, 2 * kPi));
  }
  return joint;
}

}  // namespace

QString RunsFolderFor(const QString& project_path) {
  const QFileInfo info(project_path);
  return info.absoluteDir().filePath(info.completeBaseName() + ".runs");
}

std::shared_ptr<const FieldFrames> ReadFieldFrames(const QString& fields_folder,
                                                   const engine::EngineCase& engine_case,
                                                   double rpm) {
  const fs::path folder = PathOf(fields_folder);
  auto frames = std::make_shared<FieldFrames>();
  // Every stride-th output step, as the live view keeps them (ui/fields/field_collector).
  const int steps_per_cycle =
      std::max(1, int(std::lround(4 * kPi / engine_case.solver.output_interval)));
  constexpr int kMaxFrames = 240;
  const std::size_t stride =
      std::size_t(std::max(1, (steps_per_cycle + kMaxFrames - 1) / kMaxFrames));
  for (const auto& [file, big_end] :
       {std::pair{"skirt.h5", false}, std::pair{"bearing.h5", true}}) {
    if (!fs::exists(folder / file)) continue;
    const io::FieldSeries series = io::ReadFieldSeries(folder / file);
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < series.frames.size(); k += stride) kept.push_back(k);
    if (frames->joints.empty()) {
      for (std::size_t k : kept) {
        const double angle = series.frames[k].crank_angle_deg;
        frames->crank_angle_deg.push_back(angle);
        frames->time.push_back(rpm > 0 ? angle / (6.0 * rpm) : 0.0);  // within the cycle
      }
    } else if (kept.size() != frames->crank_angle_deg.size()) {
      throw std::runtime_error((folder / file).string() + ": " +
                               std::to_string(series.frames.size()) +
                               " frames, the other joint has a different number");
    }
    frames->joints.push_back(JointFromSeries(series, big_end, engine_case, kept));
  }
  if (frames->joints.empty()) return nullptr;
  return frames;
}

bool SaveProjectRuns(const QString& project_path, const std::vector<ProjectRun>& runs, int base_id,
                     SaveRunsReport* report, QString* error) {
  SaveRunsReport done;
  const fs::path dir = PathOf(RunsFolderFor(project_path));
  std::string writing;  // the key whose files this save is writing, until they are complete
  try {
    // The index already there: a save removes only the runs it lists and this save does not
    // (runs the user removed). One this version cannot read (damaged, or a newer FilmDyn's) is
    // left as it is, with every run in the folder: nothing is written.
    std::set<std::string> listed_before;
    if (fs::exists(dir / kIndex)) {
      try {
        const nlohmann::json before = ReadRunsIndex(dir / kIndex);
        for (const nlohmann::json& e : before["runs"])
          if (const std::string key = EntryKey(e); !key.empty()) listed_before.insert(key);
      } catch (const std::exception& e) {
        throw std::runtime_error((dir / kIndex).string() + " cannot be read (" + e.what() +
                                 "): it and the runs in its folder are left as they are; save "
                                 "the project under another name to keep this session's runs");
      }
    }
    fs::create_directories(dir);
    std::set<std::string> keep;
    // The runs that could not be read back keep their keys and their entries as saved (for a
    // later version or a repair); no new run takes one of those keys.
    std::map<int, nlohmann::json> unrestored;  // by run id: the entry as saved
    for (const ProjectRun& entry : runs) {
      if (entry.run->restoreError().isEmpty()) continue;
      nlohmann::json saved = nlohmann::json::parse(entry.run->restoreEntry(), nullptr, false);
      if (saved.is_discarded()) continue;
      if (const std::string key = EntryKey(saved); !key.empty()) keep.insert(key);
      unrestored[entry.run->id()] = std::move(saved);
    }
    nlohmann::json list = nlohmann::json::array();
    std::string base_key;
    int next = 1;
    for (const ProjectRun& entry : runs) {
      const RunHandle& run = entry.run;
      const fs::path stored = PathOf(run->storedFolder());
      const bool stored_here = !run->storedFolder().isEmpty() && stored.parent_path() == dir;
      if (run->status() == RunStatus::kRunning) {
        ++done.skipped_running;
        continue;
      }
      if (!run->restoreError().isEmpty()) {
        if (const auto saved = unrestored.find(run->id()); saved != unrestored.end()) {
          list.push_back(saved->second);
          if (run->id() == base_id) base_key = EntryKey(saved->second);
        }
        ++done.skipped_unrestored;
        continue;
      }
      std::string key;
      if (stored_here && fs::exists(dir / (stored.filename().string() + kSamplesSuffix))) {
        key = stored.filename().string();  // written by an earlier save: files unchanged
      } else {
        do {
          key = kKeyPrefix + std::to_string(next++);
        } while (fs::exists(dir / key) || fs::exists(dir / (key + kSamplesSuffix)) ||
                 keep.count(key));
        writing = key;
        const fs::path tmp = dir / (key + ".tmp");
        fs::remove_all(tmp);
        if (!run->resultsCsv().isEmpty()) {  // a run with core's writers: its run folder
          QString message;
          if (!run->writeRunFolder(QPath(tmp), &message)) {
            fs::remove_all(tmp);
            throw std::runtime_error(message.toStdString());
          }
          fs::rename(tmp, dir / key);
        }
        // The motion first: a save interrupted between the two leaves no samples file, and the
        // key is then written anew by the next save.
        if (const std::vector<RunSample> motion = run->motion(); !motion.empty()) {
          io::WriteFileAtomically(dir / (key + kMotionSuffix), SamplesCsv(motion));
        }
        io::WriteFileAtomically(dir / (key + kSamplesSuffix), SamplesCsv(run->samples()));
        run->setStoredFolder(QPath(dir / key));
        writing.clear();
      }
      keep.insert(key);
      const RunRequest& request = run->request();
      list.push_back({{"key", key},
                      {"name", run->name().toStdString()},
                      {"notes", run->notes().toStdString()},
                      {"hidden", !entry.visible},
                      {"model", request.model},
                      {"rpm", request.rpm},
                      {"status", StatusKey(run->status())},
                      {"reason", run->reason().toStdString()},
                      {"wall_time_s", run->elapsedSeconds()},
                      {"has_folder", fs::exists(dir / key / "summary.json")},
                      {"case", io::CaseToJson(request.engine_case)}});
      if (run->id() == base_id) base_key = key;
      ++done.saved;
    }
    const nlohmann::json index = {{"format", kFormat},
                                  {"format_version", kFormatVersion},
                                  {"base", base_key},
                                  {"runs", list}};
    io::WriteFileAtomically(dir / kIndex, index.dump(2) + "\n");
    // What the index listed and lists no more (removed runs) goes, and what a save left half
    // written: a ".tmp", or a run's files without its samples file (written last for each run,
    // so a save stopped before it leaves such files, listed by no index). A run's complete files
    // listed by no index this version read (a lost index) stay, as does anything else.
    for (const auto& item : fs::directory_iterator(dir)) {
      const std::string name = item.path().filename().string();
      const std::string key = KeyOfEntry(name);
      if (!OwnEntry(name) || keep.count(key)) continue;
      const bool unfinished = !fs::exists(dir / (key + kSamplesSuffix));
      if (listed_before.count(key) || name.ends_with(".tmp") || unfinished)
        fs::remove_all(item.path());
    }
  } catch (const std::exception& e) {
    // A run whose files were being written when the save failed: none of them stays.
    if (!writing.empty()) {
      std::error_code ignored;
      for (const std::string& suffix : {std::string(), std::string(".tmp"),
                                        std::string(kSamplesSuffix), std::string(kMotionSuffix)})
        fs::remove_all(dir / (writing + suffix), ignored);
    }
    if (error) *error = QObject::tr("Runs not saved: %1").arg(QString::fromUtf8(e.what()));
    if (report) *report = done;
    return false;
  }
  if (report) *report = done;
  return true;
}

RunHandle ReadRunFolder(const QString& folder_path, RunRequest request, int id) {
  const fs::path folder = PathOf(folder_path);
  const io::RunSummary summary = io::ReadSummaryJson(folder / "summary.json");
  if (summary.status == io::kRunningStatus) {
    throw std::runtime_error(folder.string() +
                             " holds a run that has not ended (summary.json "
                             "says \"running\")");
  }
  auto run = std::make_shared<RunRecord>(id, std::move(request));
  if (const fs::path motion = folder / "motion.csv"; fs::exists(motion)) {
    run->ReportMotion(ParseSamplesCsv(ReadBytes(motion), motion, true));
  }
  run->Report(ParseSamplesCsv(ReadBytes(folder / "results.csv"), folder / "results.csv", true));
  RestoreFolder(*run, folder, summary);
  const QString message = QString::fromStdString(summary.message);
  RunStatus status = RunStatus::kFinished;
  if (summary.status == "failed") {
    status = RunStatus::kFailed;
  } else if (summary.status == "cancelled" || summary.status == "time-limit") {
    status = RunStatus::kCancelled;
  } else if (summary.status != "completed" && summary.status != "not-converged") {
    throw std::runtime_error((folder / "summary.json").string() + ": status \"" + summary.status +
                             "\" is not one a run ends with");
  }
  if (status == RunStatus::kFinished && !message.isEmpty()) run->Warn(summary.message);
  run->finish(status, message);
  run->setWallSeconds(summary.wall_time_s);
  return run;
}

LoadedRuns LoadProjectRuns(const QString& project_path, const std::function<int()>& take_id) {
  LoadedRuns loaded;
  const fs::path dir = PathOf(RunsFolderFor(project_path));
  if (!fs::exists(dir)) return loaded;
  nlohmann::json index;
  try {
    index = ReadRunsIndex(dir / kIndex);
  } catch (const std::exception& e) {
    // A save leaves such a folder as it is (SaveProjectRuns).
    loaded.problems << QObject::tr("No runs restored from %1: %2")
                           .arg(QPath(dir / kIndex), QString::fromUtf8(e.what()));
    return loaded;
  }
  const std::string base_key = index.value("base", "");
  int position = 0;
  for (const nlohmann::json& entry : index["runs"]) {
    ++position;
    const int id = take_id();
    RunRequest request;
    std::string key;
    QString problem;
    try {
      if (!entry.is_object()) throw std::runtime_error("the entry is not an object");
      key = entry.at("key").get<std::string>();
      if (EntryKey(entry).empty())
        throw std::runtime_error("key \"" + key + "\" is not a run folder name");
      request.model = entry.at("model").get<std::string>();
      request.rpm = entry.at("rpm").get<double>();
      request.engine_case = io::CaseFromJson(entry.at("case"));
    } catch (const std::exception& e) {
      problem = QString::fromUtf8(e.what());
    }
    auto run = std::make_shared<RunRecord>(id, request);
    ProjectRun restored{run, true};
    if (entry.is_object()) {
      run->setName(QString::fromStdString(entry.value("name", "")));
      run->setNotes(QString::fromStdString(entry.value("notes", "")));
      restored.visible = !entry.value("hidden", false);
    }
    if (problem.isEmpty()) {
      try {
        Restore(*run, dir, key, entry.value("has_folder", false));
        const RunStatus status = StatusFromKey(entry.value("status", ""));
        const QString reason = QString::fromStdString(entry.value("reason", ""));
        if (status == RunStatus::kFinished && !reason.isEmpty()) run->Warn(reason.toStdString());
        run->finish(status, reason);
        run->setWallSeconds(entry.value("wall_time_s", 0.0));
      } catch (const std::exception& e) {
        problem = QString::fromUtf8(e.what());
        // Nothing half restored: a fresh record carries the inputs and the reason.
        run = std::make_shared<RunRecord>(id, request);
        run->setName(QString::fromStdString(entry.value("name", "")));
        run->setNotes(QString::fromStdString(entry.value("notes", "")));
        run->setStoredFolder(QPath(dir / key));
        restored.run = run;
      }
    }
    if (!problem.isEmpty()) {
      const QString which =
          run->name().isEmpty()
              ? QObject::tr("run %1 (%2)").arg(position).arg(QString::fromStdString(key))
              : QObject::tr("run %1 “%2”").arg(position).arg(run->name());
      const QString message = QObject::tr("not restored: %1").arg(problem);
      run->setRestoreError(problem, entry.dump());  // a save lists it again as it was
      run->finish(RunStatus::kFailed, message);
      run->setWallSeconds(0);
      loaded.problems << QObject::tr("%1 %2").arg(which, message);
    }
    if (!key.empty() && key == base_key) loaded.base_id = id;
    loaded.runs.push_back(restored);
  }
  return loaded;
}

}  // namespace filmdyn::ui
