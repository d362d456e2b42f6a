#pragma once
/// @file One run kept by the GUI: its inputs (a copy of the case), streamed samples, progress,
/// statistics, status and reason. The worker thread writes under a mutex; the GUI thread reads
/// copies (PlotJuggler's pattern), so neither ever waits long for the other.
#include <QElapsedTimer>
#include <QString>
#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "ui/run/run_backend.hpp"

namespace filmdyn::ui {

enum class RunStatus { kRunning, kFinished, kFailed, kCancelled };
/// "Skirt-LBRBE 6000 rpm": a run's label from its model key ("skirt-lbrbe") and speed.
QString RunLabel(const QString& model_key, double rpm);
QString RunStatusText(RunStatus status);

class RunRecord : public RunSink {
 public:
  RunRecord(int id, RunRequest request);

  int id() const { return id_; }
  const RunRequest& request() const { return request_; }
  /// The one label of the run in every legend, table and view: the name the user gave it, else
  /// the automatic label (what differs from the base run), else model and speed ("Skirt-LBRBE
  /// 6000 rpm"). The run table keeps labels unique among its runs.
  QString label() const;
  /// The label in the legends (on screen and in exported plots) and the field view: label(), with
  /// the run's state when its curves are not those of a run that ended normally — "… (running)",
  /// "… (cancelled)", "… (failed)" — so that a picture of partial curves says so.
  QString legendLabel() const;
  /// The user's name for the run; empty = the automatic label.
  QString name() const;
  void setName(const QString& name);
  /// The automatic label, set by the run table ("μ 10 mPa·s · 4000 rpm"; the base run's model
  /// and speed), unique among the runs.
  QString automaticLabel() const;
  void setAutomaticLabel(const QString& label);
  /// What differs from the base run ("" for none; the table shows "base run" for the base).
  QString differences() const;
  void setDifferences(const QString& differences);
  /// Free text of the user about the run.
  QString notes() const;
  void setNotes(const QString& notes);
  /// A run read back from a saved project: the folder holding its files (results.csv,
  /// summary.json, fields/), which its writers copy from; empty for a run of this session.
  QString storedFolder() const;
  void setStoredFolder(const QString& folder);
  /// Why a saved run could not be read back (empty when it was, or for a run of this session).
  QString restoreError() const;
  /// `entry`: the run's entry of the project's runs index (JSON), which a save lists again as it
  /// was.
  void setRestoreError(const QString& error, const std::string& entry = {});
  std::string restoreEntry() const;
  /// The wall time a restored run took when it ran [s] (its summary.json).
  void setWallSeconds(double seconds);

  // RunSink (worker thread).
  void BeginCycle(int cycle) override;
  void Append(const RunSample& sample) override;
  void Progress(const RunProgress& progress) override;
  void Statistic(const std::string& name, double value) override;
  void Report(std::vector<RunSample> reported_cycle) override;
  void ReportMotion(std::vector<RunSample> motion) override;
  void ReportFields(std::shared_ptr<const FieldFrames> fields) override;
  void Warn(const std::string& message) override;
  void SetWriters(RunWriters writers) override;
  void ReportErrorEstimate(const engine::ErrorEstimate& estimate) override;
  void ReportCycleScatter(const std::optional<engine::CycleScatter>& scatter) override;
  void ReportWarnings(std::vector<io::RunWarning> warnings) override;
  /// The engineering warnings of the finished run (empty until it is reported).
  std::vector<io::RunWarning> engineeringWarnings() const;
  /// The estimate of the finished run (status "off" until one is reported).
  engine::ErrorEstimate errorEstimate() const;
  /// The scatter of its headline figures over its last cycles (none until reported).
  std::optional<engine::CycleScatter> cycleScatter() const;
  /// Writes the run folder as `filmdyn run` does; false with *error when it cannot (or when
  /// the backend provided no writer).
  bool writeRunFolder(const QString& directory, QString* error) const;
  /// Writes the fields/ files of the run (as in its run folder) into `directory`; false with
  /// *error when it cannot or the run has none.
  bool writeFields(const QString& directory, QString* error) const;
  /// results.csv text in core's format, or empty when the backend provided no writer.
  QByteArray resultsCsv() const;
  QString warning() const;
  /// The reported cycle's film fields, or nullptr (ideal joints, or not finished).
  std::shared_ptr<const FieldFrames> fields() const;

  /// The samples to show: the reported cycle once the backend reported it, otherwise the cycle
  /// in progress (or the last complete one at a cycle start). Copy, safe on any thread.
  std::vector<RunSample> samples() const;
  /// The reported cycle's motion samples (empty until reported, and for a run that has none):
  /// only the motion columns (io::MotionColumns) are set. Copy, safe on any thread.
  std::vector<RunSample> motion() const;
  /// Monotonic counter bumped by every change (lets viewers skip redundant redraws).
  long version() const { return version_.load(); }
  RunProgress progress() const;
  std::map<std::string, double> statistics() const;

  RunStatus status() const;
  QString reason() const;
  void finish(RunStatus status, const QString& reason);
  double elapsedSeconds() const;

  /// Set by the worker after each batch; cleared by the GUI when it schedules a redraw.
  std::atomic<bool> notify_pending{false};

 private:
  const int id_;
  const RunRequest request_;
  mutable std::mutex mutex_;
  std::vector<RunSample> current_cycle_;
  std::vector<RunSample> last_complete_cycle_;
  std::vector<RunSample> reported_;
  std::vector<RunSample> motion_;
  bool has_report_ = false;
  std::shared_ptr<const FieldFrames> fields_;
  QString warning_;
  engine::ErrorEstimate error_estimate_;
  std::optional<engine::CycleScatter> cycle_scatter_;
  std::vector<io::RunWarning> engineering_warnings_;
  RunWriters writers_;
  RunProgress progress_;
  std::map<std::string, double> statistics_;
  RunStatus status_ = RunStatus::kRunning;
  QString reason_;
  QString name_;
  QString automatic_label_;
  QString differences_;
  QString notes_;
  QString stored_folder_;
  QString restore_error_;
  std::string restore_entry_;
  QElapsedTimer clock_;
  double wall_seconds_ = -1;
  std::atomic<long> version_{0};
};

using RunHandle = std::shared_ptr<RunRecord>;

}  // namespace filmdyn::ui
