#include "ui/run/run_record.hpp"

#include <QObject>

#include "ui/case_editor/case_parameters.hpp"
#include "ui/case_editor/parameter_table_model.hpp"

namespace filmdyn::ui {

QString RunStatusText(RunStatus status) {
  switch (status) {
    case RunStatus::kRunning:
      return QObject::tr("running");
    case RunStatus::kFinished:
      return QObject::tr("finished");
    case RunStatus::kFailed:
      return QObject::tr("failed");
    case RunStatus::kCancelled:
      return QObject::tr("cancelled");
  }
  return {};
}

RunRecord::RunRecord(int id, RunRequest request) : id_(id), request_(std::move(request)) {
  clock_.start();
}

QString RunLabel(const QString& model_key, double rpm) {
  QString model = model_key;
  for (const RunModel& m : RunModels()) {
    if (m.key == model_key) model = m.title;
  }
  return QObject::tr("%1 %2 rpm").arg(model, FormatDisplayNumber(rpm));
}

QString RunRecord::label() const {
  std::lock_guard lock(mutex_);
  if (!name_.isEmpty()) return name_;
  if (!automatic_label_.isEmpty()) return automatic_label_;
  return RunLabel(QString::fromStdString(request_.model), request_.rpm);
}

QString RunRecord::legendLabel() const {
  const RunStatus state = status();
  const QString plain = label();
  return state == RunStatus::kFinished ? plain
                                       : QString("%1 (%2)").arg(plain, RunStatusText(state));
}

QString RunRecord::name() const {
  std::lock_guard lock(mutex_);
  return name_;
}

void RunRecord::setName(const QString& name) {
  std::lock_guard lock(mutex_);
  name_ = name.trimmed();
  ++version_;
}

QString RunRecord::automaticLabel() const {
  std::lock_guard lock(mutex_);
  return automatic_label_;
}

void RunRecord::setAutomaticLabel(const QString& label) {
  std::lock_guard lock(mutex_);
  automatic_label_ = label;
}

QString RunRecord::differences() const {
  std::lock_guard lock(mutex_);
  return differences_;
}

void RunRecord::setDifferences(const QString& differences) {
  std::lock_guard lock(mutex_);
  differences_ = differences;
}

QString RunRecord::notes() const {
  std::lock_guard lock(mutex_);
  return notes_;
}

void RunRecord::setNotes(const QString& notes) {
  std::lock_guard lock(mutex_);
  notes_ = notes;
}

QString RunRecord::storedFolder() const {
  std::lock_guard lock(mutex_);
  return stored_folder_;
}

void RunRecord::setStoredFolder(const QString& folder) {
  std::lock_guard lock(mutex_);
  stored_folder_ = folder;
}

QString RunRecord::restoreError() const {
  std::lock_guard lock(mutex_);
  return restore_error_;
}

void RunRecord::setRestoreError(const QString& error, const std::string& entry) {
  std::lock_guard lock(mutex_);
  restore_error_ = error;
  restore_entry_ = entry;
  ++version_;
}

std::string RunRecord::restoreEntry() const {
  std::lock_guard lock(mutex_);
  return restore_entry_;
}

void RunRecord::setWallSeconds(double seconds) {
  std::lock_guard lock(mutex_);
  wall_seconds_ = seconds;
}

void RunRecord::BeginCycle(int cycle) {
  std::lock_guard lock(mutex_);
  if (!current_cycle_.empty()) last_complete_cycle_.swap(current_cycle_);
  current_cycle_.clear();
  progress_.cycle = cycle;
  progress_.cycle_fraction = 0;
  ++version_;
}

void RunRecord::Append(const RunSample& sample) {
  std::lock_guard lock(mutex_);
  current_cycle_.push_back(sample);
  ++version_;
}

void RunRecord::Progress(const RunProgress& progress) {
  std::lock_guard lock(mutex_);
  progress_ = progress;
  ++version_;
}

void RunRecord::Statistic(const std::string& name, double value) {
  std::lock_guard lock(mutex_);
  statistics_[name] = value;
}

void RunRecord::Report(std::vector<RunSample> reported_cycle) {
  std::lock_guard lock(mutex_);
  reported_ = std::move(reported_cycle);
  has_report_ = true;
  ++version_;
}

void RunRecord::ReportMotion(std::vector<RunSample> motion) {
  std::lock_guard lock(mutex_);
  motion_ = std::move(motion);
  ++version_;
}

void RunRecord::ReportFields(std::shared_ptr<const FieldFrames> fields) {
  std::lock_guard lock(mutex_);
  fields_ = std::move(fields);
}

void RunRecord::Warn(const std::string& message) {
  std::lock_guard lock(mutex_);
  warning_ = QString::fromStdString(message);
}

void RunRecord::ReportErrorEstimate(const engine::ErrorEstimate& estimate) {
  std::lock_guard lock(mutex_);
  error_estimate_ = estimate;
  ++version_;
}

engine::ErrorEstimate RunRecord::errorEstimate() const {
  std::lock_guard lock(mutex_);
  return error_estimate_;
}

void RunRecord::ReportCycleScatter(const std::optional<engine::CycleScatter>& scatter) {
  std::lock_guard lock(mutex_);
  cycle_scatter_ = scatter;
  ++version_;
}

std::optional<engine::CycleScatter> RunRecord::cycleScatter() const {
  std::lock_guard lock(mutex_);
  return cycle_scatter_;
}

void RunRecord::ReportWarnings(std::vector<io::RunWarning> warnings) {
  std::lock_guard lock(mutex_);
  engineering_warnings_ = std::move(warnings);
  ++version_;
}

std::vector<io::RunWarning> RunRecord::engineeringWarnings() const {
  std::lock_guard lock(mutex_);
  return engineering_warnings_;
}

void RunRecord::SetWriters(RunWriters writers) {
  std::lock_guard lock(mutex_);
  writers_ = std::move(writers);
}

namespace {

// Runs a folder writer of core, turning its exceptions into an error message.
bool CallWriter(const std::function<void(const std::string&)>& writer, const QString& directory,
                QString* error) {
  if (!writer) {
    if (error) *error = QObject::tr("this run has no output to write yet");
    return false;
  }
  try {
    writer(directory.toStdString());
  } catch (const std::exception& e) {
    if (error) *error = QString::fromUtf8(e.what());
    return false;
  }
  return true;
}

}  // namespace

bool RunRecord::writeRunFolder(const QString& directory, QString* error) const {
  std::function<void(const std::string&)> writer;
  {
    std::lock_guard lock(mutex_);
    writer = writers_.folder;
  }
  return CallWriter(writer, directory, error);
}

bool RunRecord::writeFields(const QString& directory, QString* error) const {
  std::function<void(const std::string&)> writer;
  {
    std::lock_guard lock(mutex_);
    writer = writers_.fields;
  }
  return CallWriter(writer, directory, error);
}

QByteArray RunRecord::resultsCsv() const {
  std::function<std::string()> writer;
  {
    std::lock_guard lock(mutex_);
    writer = writers_.csv;
  }
  if (!writer) return {};
  const std::string text = writer();
  return QByteArray(text.data(), qsizetype(text.size()));
}

QString RunRecord::warning() const {
  std::lock_guard lock(mutex_);
  return warning_;
}

std::shared_ptr<const FieldFrames> RunRecord::fields() const {
  std::lock_guard lock(mutex_);
  return fields_;
}

std::vector<RunSample> RunRecord::samples() const {
  std::lock_guard lock(mutex_);
  if (has_report_ && !reported_.empty()) return reported_;
  if (current_cycle_.empty()) return last_complete_cycle_;
  return current_cycle_;
}

std::vector<RunSample> RunRecord::motion() const {
  std::lock_guard lock(mutex_);
  return motion_;
}

RunProgress RunRecord::progress() const {
  std::lock_guard lock(mutex_);
  return progress_;
}

std::map<std::string, double> RunRecord::statistics() const {
  std::lock_guard lock(mutex_);
  return statistics_;
}

RunStatus RunRecord::status() const {
  std::lock_guard lock(mutex_);
  return status_;
}

QString RunRecord::reason() const {
  std::lock_guard lock(mutex_);
  return reason_;
}

void RunRecord::finish(RunStatus status, const QString& reason) {
  std::lock_guard lock(mutex_);
  status_ = status;
  reason_ = reason;
  wall_seconds_ = clock_.elapsed() / 1000.0;
  ++version_;
}

double RunRecord::elapsedSeconds() const {
  std::lock_guard lock(mutex_);
  return wall_seconds_ >= 0 ? wall_seconds_ : clock_.elapsed() / 1000.0;
}

}  // namespace filmdyn::ui
