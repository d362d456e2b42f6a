#include "ui/run/run_controller.hpp"

#include <QMetaObject>
#include <QThread>
#include <exception>

#include "core/base/input_error.hpp"

namespace filmdyn::ui {

namespace {

// Forwards the backend's output into the record and wakes the GUI once per batch.
class NotifyingSink : public RunSink {
 public:
  NotifyingSink(RunRecord* record, RunController* controller)
      : record_(record), controller_(controller) {}
  void BeginCycle(int cycle) override {
    record_->BeginCycle(cycle);
    Notify();
  }
  void Append(const RunSample& sample) override {
    record_->Append(sample);
    Notify();
  }
  void Progress(const RunProgress& progress) override {
    record_->Progress(progress);
    Notify();
  }
  void Statistic(const std::string& name, double value) override {
    record_->Statistic(name, value);
  }
  void Warn(const std::string& message) override { record_->Warn(message); }
  void SetWriters(RunWriters writers) override { record_->SetWriters(std::move(writers)); }
  void ReportFields(std::shared_ptr<const FieldFrames> fields) override {
    record_->ReportFields(std::move(fields));
  }
  void ReportErrorEstimate(const engine::ErrorEstimate& estimate) override {
    record_->ReportErrorEstimate(estimate);
  }
  void ReportCycleScatter(const std::optional<engine::CycleScatter>& scatter) override {
    record_->ReportCycleScatter(scatter);
  }
  void ReportWarnings(std::vector<io::RunWarning> warnings) override {
    record_->ReportWarnings(std::move(warnings));
  }
  void ReportMotion(std::vector<RunSample> motion) override {
    record_->ReportMotion(std::move(motion));
  }
  void Report(std::vector<RunSample> reported_cycle) override {
    record_->Report(std::move(reported_cycle));
    Notify();
  }

 private:
  void Notify() {
    // One queued call per batch: later samples ride along until the GUI clears the flag.
    if (!record_->notify_pending.exchange(true)) {
      QMetaObject::invokeMethod(controller_, "onWorkerNotified", Qt::QueuedConnection);
    }
  }
  RunRecord* record_;
  RunController* controller_;
};

}  // namespace

RunController::RunController(QObject* parent) : QObject(parent) {
  qRegisterMetaType<filmdyn::ui::RunHandle>("filmdyn::ui::RunHandle");
  redraw_timer_.setSingleShot(true);
  redraw_timer_.setInterval(kRedrawIntervalMs);
  connect(&redraw_timer_, &QTimer::timeout, this, [this] {
    if (running_) {
      running_->notify_pending = false;
      emit runUpdated(running_);
    }
  });
  backend_ = CoreRunBackend();
}

RunController::~RunController() {
  if (thread_ != nullptr) {
    cancel_ = true;
    thread_->wait();
    delete thread_;
  }
}

RunHandle RunController::start(RunRequest request) {
  if (running_) return nullptr;
  auto record = std::make_shared<RunRecord>(next_id_++, std::move(request));
  running_ = record;
  cancel_ = false;
  RunBackend backend = backend_;
  RunRecord* raw = record.get();
  thread_ = QThread::create([this, backend, raw] {
    NotifyingSink sink(raw, this);
    // Everything is caught at the thread boundary and reported.
    try {
      if (!backend) throw std::runtime_error("no solver backend is configured");
      // The run's own end decides its status: a Cancel pressed once the solver had finished
      // (while the error estimate's companion ended) leaves a finished run finished.
      backend(raw->request(), cancel_, sink);
      raw->finish(RunStatus::kFinished, raw->warning());
    } catch (const RunCancelled&) {
      raw->finish(RunStatus::kCancelled, tr("cancelled by the user"));
    } catch (const InputError& e) {
      raw->finish(RunStatus::kFailed, tr("invalid input: %1").arg(e.what()));
    } catch (const std::exception& e) {
      raw->finish(cancel_ ? RunStatus::kCancelled : RunStatus::kFailed,
                  cancel_ ? tr("cancelled by the user") : QString::fromUtf8(e.what()));
    } catch (...) {
      raw->finish(RunStatus::kFailed, tr("unknown error in the solver"));
    }
  });
  thread_->setObjectName("filmdyn-run");
  connect(thread_, &QThread::finished, this, &RunController::onWorkerDone);
  emit runStarted(record);
  thread_->start();
  return record;
}

void RunController::cancel() { cancel_ = true; }

void RunController::onWorkerNotified() {
  if (!redraw_timer_.isActive()) redraw_timer_.start();
}

void RunController::onWorkerDone() {
  redraw_timer_.stop();
  thread_->wait();
  thread_->deleteLater();
  thread_ = nullptr;
  RunHandle finished = running_;
  running_.reset();
  if (finished) {
    finished->notify_pending = false;
    emit runUpdated(finished);
    emit runFinished(finished);
  }
}

}  // namespace filmdyn::ui
