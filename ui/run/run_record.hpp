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
  /// "Skirt-LBRBE 6000 rpm" (+ " #id" suffix added by the run list when names repeat).
  QString label() const;

  // RunSink (worker thread).
  void BeginCycle(int cycle) override;
  void Append(const RunSample& sample) override;
  void Progress(const RunProgress& progress) override;
  void Statistic(const std::string& name, double value) override;
  void Report(std::vector<RunSample> reported_cycle) override;
  void ReportFields(std::shared_ptr<const FieldFrames> fields) override;
  void Warn(const std::string& message) override;
  void SetWriters(RunWriters writers) override;
  void ReportErrorEstimate(const engine::ErrorEstimate& estimate) override;
  /// The estimate of the finished run (status "off" until one is reported).
  engine::ErrorEstimate errorEstimate() const;
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
  bool has_report_ = false;
  std::shared_ptr<const FieldFrames> fields_;
  QString warning_;
  engine::ErrorEstimate error_estimate_;
  RunWriters writers_;
  RunProgress progress_;
  std::map<std::string, double> statistics_;
  RunStatus status_ = RunStatus::kRunning;
  QString reason_;
  QElapsedTimer clock_;
  double wall_seconds_ = -1;
  std::atomic<long> version_{0};
};

using RunHandle = std::shared_ptr<RunRecord>;

}  // namespace filmdyn::ui
