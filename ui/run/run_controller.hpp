#pragma once
/// @file Runs a backend on a worker thread (never the GUI thread), one run at a time, with a
/// cancel flag. The worker only appends under a mutex and posts one notification per batch;
/// the GUI coalesces notifications with a ~40 ms single-shot timer (as PlotJuggler does).
#include <QObject>
#include <QTimer>
#include <atomic>
#include <memory>

#include "ui/run/run_record.hpp"

class QThread;

namespace filmdyn::ui {

class RunController : public QObject {
  Q_OBJECT

 public:
  explicit RunController(QObject* parent = nullptr);
  ~RunController() override;  ///< cancels and joins a running worker

  void setBackend(RunBackend backend) { backend_ = std::move(backend); }
  bool isRunning() const { return running_ != nullptr; }
  RunHandle current() const { return running_; }

  /// Starts a run; returns its record (nullptr if one is already running).
  RunHandle start(RunRequest request);

  /// A run id no run of this controller has or will get (for runs read back from a project).
  int takeId() { return next_id_++; }

  /// Coalescing interval [ms].
  static constexpr int kRedrawIntervalMs = 40;

 public slots:
  void cancel();

 signals:
  void runStarted(filmdyn::ui::RunHandle run);
  /// New samples or progress, at most every kRedrawIntervalMs.
  void runUpdated(filmdyn::ui::RunHandle run);
  void runFinished(filmdyn::ui::RunHandle run);

 public:
  /// Called (queued) by the worker once per batch of samples.
  Q_INVOKABLE void onWorkerNotified();

 private:
  void onWorkerDone();

  RunBackend backend_;
  RunHandle running_;
  QThread* thread_ = nullptr;
  std::atomic<bool> cancel_{false};
  QTimer redraw_timer_;
  int next_id_ = 1;
};

}  // namespace filmdyn::ui
