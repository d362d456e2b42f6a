// The GUI's solver backend: core's run job (core/engine/run_job), the same call `filmdyn run`
// makes; only the monitor differs. The monitor streams every output step into the sink; the
// reported cycle of the result replaces the streamed samples at the end.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/base/input_error.hpp"
#include "core/engine/run_job.hpp"
#include "core/io/case_file.hpp"
#include "core/io/field_output.hpp"
#include "core/io/results_writer.hpp"
#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/skirt_solver.hpp"
#include "ui/run/run_backend.hpp"
#include "ui/run/sample_conversion.hpp"

namespace filmdyn::ui {

namespace {

// results.csv columns from a crank-train sample: core's row (io::RowFromSample, what
// `filmdyn run` writes) through the one row-to-sample mapping, so GUI and files agree.
RunSample ToRunSample(const engine::CrankTrainSample& cs, engine::Model model,
                      double cycle_start_time) {
  return RunSampleFromRow(io::RowFromSample(cs, model, cycle_start_time));
}

// Collects the film fields of the cycle being computed (a new cycle starts afresh), keeping at
// most kMaxFrames per cycle so a 1 °CA run does not hold 720 copies in memory.
class FieldCollector {
 public:
  static constexpr int kMaxFrames = 240;

  FieldCollector(const engine::EngineCase& c, int steps_per_cycle)
      : skirt_radius_(c.skirt.piston_radius),
        bearing_radius_(c.big_end.bearing_radius),
        stride_(std::max(1, (steps_per_cycle + kMaxFrames - 1) / kMaxFrames)) {}

  void Add(const engine::FieldFrame& frame) {
    if (frame.cycle != cycle_) {
      cycle_ = frame.cycle;
      frames_ = std::make_shared<FieldFrames>();
    }
    if (frame.step % stride_ != 0) return;
    if (frames_->joints.empty()) {
      if (frame.skirt)
        frames_->joints.push_back(MakeJoint("skirt", frame.skirt->mesh(), skirt_radius_, M_PI));
      if (frame.bearing)  // the whole width, also when the solver computes the symmetric half
        frames_->joints.push_back(MakeJoint("big_end", frame.bearing->full_width().mesh,
                                            bearing_radius_, 2 * M_PI));
    }
    frames_->crank_angle_deg.push_back(frame.crank_angle_deg);
    frames_->time.push_back(frame.time);
    size_t j = 0;
    if (frame.skirt)
      Append(frames_->joints[j++], frame.skirt->fields(), frame.skirt->film_thickness());
    if (frame.bearing)
      Append(frames_->joints[j++], frame.bearing->fields(), frame.bearing->film_thickness(),
             &frame.bearing->full_width().source);
  }

  std::shared_ptr<const FieldFrames> Result() const { return frames_; }

 private:
  // Unrolls the film plane (x = R·angle, y axial) onto the cylinder of radius R.
  static JointFieldFrames MakeJoint(const std::string& name, const lubrication::TriMesh& mesh,
                                    double radius, double max_angle) {
    JointFieldFrames joint;
    joint.name = name;
    for (int n = 0; n < mesh.NodeCount(); ++n) {
      const double angle = std::min(mesh.x[size_t(n)] / radius, max_angle);
      joint.mesh.points.push_back(
          {radius * std::cos(angle), radius * std::sin(angle), mesh.y[size_t(n)]});
    }
    joint.mesh.triangles = mesh.triangles;
    return joint;
  }

  // `source`: the solver node of each displayed node (nullptr = the same numbering).
  static void Append(JointFieldFrames& joint, const lubrication::ReynoldsSolution& fields,
                     const Eigen::VectorXd& film, const std::vector<int>* source = nullptr) {
    auto vec = [source](const Eigen::VectorXd& v) {
      if (!source) return std::vector<double>(v.data(), v.data() + v.size());
      std::vector<double> out(source->size());
      for (std::size_t k = 0; k < source->size(); ++k) out[k] = v[(*source)[k]];
      return out;
    };
    joint.frames.push_back({{"pressure", vec(fields.pressure)},
                            {"contact_pressure", vec(fields.contact_pressure)},
                            {"film_thickness", vec(film)}});
  }

  double skirt_radius_, bearing_radius_;
  int stride_;
  int cycle_ = 0;
  std::shared_ptr<FieldFrames> frames_;
};

engine::PressureCurve CurveForSpeed(const engine::EngineCase& c, double rpm) {
  // Core's rule: the curve at that speed or a blend of the two neighbouring speeds; the editor
  // keeps curves inline (file curves are read into tables when a case is opened).
  io::LoadedCase loaded;
  loaded.value = c;
  loaded.source = "GUI";
  return io::PressureCurveForSpeed(loaded, rpm);
}

}  // namespace

RunBackend CoreRunBackend() {
  return [](const RunRequest& request, const std::atomic<bool>& cancel, RunSink& sink) {
    const engine::Model model = engine::ParseModel(request.model);
    engine::EngineCase c = request.engine_case;
    engine::ApplyModel(model, &c);
    engine::RunConfig config =
        engine::MakeRunConfig(c, model, request.rpm, CurveForSpeed(c, request.rpm));
    const int steps_per_cycle = std::max(1, int(std::lround(4 * M_PI / c.solver.output_interval)));
    FieldCollector collector(c, steps_per_cycle);
    // The GUI's frames and core's recorder (for the run folder's fields/, as `filmdyn run`).
    auto recorder = std::make_shared<io::FieldRecorder>();
    // The view's frames beside the recorder's: for the memory check.
    config.field_copies =
        1.0 + std::min(1.0, double(FieldCollector::kMaxFrames) / double(steps_per_cycle));
    if (model != engine::Model::kIdeal) {
      config.field_callback = [&collector,
                               record = recorder->Callback()](const engine::FieldFrame& f) {
        collector.Add(f);
        record(f);
      };
    }
    int cycle = 0;
    const engine::RunMonitor monitor = [&](const engine::RunProgress& p) {
      // The run-in only reports progress; the plots start with the first cycle.
      if (!p.run_in && p.cycle != cycle) {
        cycle = p.cycle;
        sink.BeginCycle(cycle);
      }
      if (p.sample && !p.run_in) sink.Append(ToRunSample(*p.sample, model, p.cycle_start_time));
      RunProgress progress;
      progress.run_in = p.run_in;
      progress.cycle = p.cycle;
      progress.max_cycles = p.max_cycles;
      progress.cycle_fraction = p.crank_angle_deg / 720.0;  // < 0 in the run-in
      progress.fraction = p.fraction;
      progress.remaining = p.remaining;
      sink.Progress(progress);
      return !cancel.load();
    };
    const engine::RunResult result = engine::RunJob(config, monitor, &cancel);
    std::vector<RunSample> reported;
    const double report_start = result.samples.empty() ? 0.0 : result.samples.front().time;
    for (const engine::CrankTrainSample& sample : result.samples) {
      reported.push_back(ToRunSample(sample, model, report_start));
    }
    sink.Report(std::move(reported));
    // A cancelled run stays in the run list with its curves and figures; its film fields (one
    // cycle of frames, tens of MB on fine meshes) are dropped, so that runs started and cancelled
    // again and again do not pile up memory.
    const bool cancelled = result.status == engine::RunStatus::kCancelled;
    if (cancelled) recorder = std::make_shared<io::FieldRecorder>();
    auto shared_config = std::make_shared<engine::RunConfig>(config);
    shared_config->field_callback = nullptr;  // refers to this call's collector
    auto shared_result = std::make_shared<engine::RunResult>(result);
    const std::string case_name = c.name;
    RunWriters writers;
    writers.folder = [shared_config, shared_result, recorder, case_name](const std::string& dir) {
      io::WriteRunFolder(dir, case_name, *shared_config, *shared_result,
                         [&](const std::vector<io::OutputRow>&) {
                           if (recorder->skirt_frames() + recorder->bearing_frames() > 0)
                             recorder->Write(std::filesystem::path(dir) / "fields");
                         });
    };
    writers.fields = [recorder, cancelled](const std::string& dir) {
      if (recorder->skirt_frames() + recorder->bearing_frames() == 0) {
        throw std::runtime_error(cancelled ? "a cancelled run keeps no film fields"
                                           : "this run has no film fields (ideal joints)");
      }
      recorder->Write(dir);
    };
    writers.csv = [shared_config, shared_result, model, report_start]() {
      std::vector<io::OutputRow> rows;
      for (const auto& sample : shared_result->samples) {
        rows.push_back(io::RowFromSample(sample, model, report_start));
      }
      std::ostringstream out;
      io::WriteResultsCsv(out, rows);
      return out.str();
    };
    sink.SetWriters(std::move(writers));
    if (auto fields = collector.Result(); !cancelled && fields && !fields->empty())
      sink.ReportFields(fields);
    sink.Statistic("cycles", result.cycles);
    sink.Statistic("cycles to steady state", result.cycles_to_steady_state);
    sink.Statistic("cycle change", result.cycle_change);
    sink.Statistic("steps", double(result.stats.steps));
    sink.Statistic("rejected steps", double(result.stats.rejected_steps));
    sink.Statistic("max constraint violation", result.max_constraint_violation);
    sink.Statistic("Reynolds solves", double(result.reynolds_solves));
    sink.ReportErrorEstimate(result.error_estimate);
    switch (result.status) {
      case engine::RunStatus::kCompleted:
      case engine::RunStatus::kCancelled:
        return;
      case engine::RunStatus::kNotConverged:
        // Results are usable but not periodic: a finished run whose reason says so.
        sink.Warn(result.message);
        return;
      case engine::RunStatus::kTimeLimit:
      case engine::RunStatus::kFailed:
        throw std::runtime_error(result.message);
    }
  };
}

}  // namespace filmdyn::ui
