#include "ui/fields/field_maps.hpp"

#include <QObject>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string_view>

#include "core/base/angles.hpp"
#include "core/engine/case_schema.hpp"
#include "core/engine/error_estimate.hpp"

namespace filmdyn::ui {

namespace {

bool Turned(const JointFieldFrames& joint) {
  for (double r : joint.frame_rotation) {
    if (r != 0.0) return true;
  }
  return false;
}

// Periodic linear interpolation of (angle [°] in [0, 360), value) samples sorted by angle.
double Periodic(const std::vector<std::pair<double, double>>& samples, double angle) {
  const auto it = std::upper_bound(samples.begin(), samples.end(), angle,
                                   [](double a, const auto& s) { return a < s.first; });
  const auto& after = it == samples.end() ? samples.front() : *it;
  const auto& before = it == samples.begin() ? samples.back() : *(it - 1);
  double a0 = before.first, a1 = after.first;
  if (it == samples.begin()) a0 -= 360.0;
  if (it == samples.end()) a1 += 360.0;
  if (!(a1 > a0)) return before.second;
  const double f = (angle - a0) / (a1 - a0);
  return (1 - f) * before.second + f * after.second;
}

void SetLabels(const JointFieldFrames& joint, FilmMapData* d) {
  if (joint.name == "skirt") {
    SetSkirtMapLabels(d);
  } else {
    d->x_title = QObject::tr("Angle in the rod frame (bearing-fixed) [°]");
    d->x_marks = {{90.0, QObject::tr("rod side")}, {270.0, QObject::tr("cap side")}};
  }
  for (const auto& [a, b] : joint.no_film)
    d->no_film_x.push_back({a * kDegreesPerRadian, b * kDegreesPerRadian});
}

}  // namespace

QString JointTitle(const JointFieldFrames& joint) {
  if (joint.name == "skirt") return QObject::tr("Piston skirt");
  if (joint.name == "big_end") return QObject::tr("Big-end bearing");
  return QString::fromStdString(joint.name);
}

QString MissingArrayText(const JointFieldFrames& joint, const FieldArrayInfo& info) {
  const QString words = QString::fromUtf8(info.words);
  const engine::CaseField* field = engine::FindCaseField(joint.name + ".cavitation");
  if (std::string_view(info.name) == "fluid_fraction" && !joint.mass_conserving &&
      field != nullptr) {
    using lubrication::CavitationModel;
    return QObject::tr(
               "No %1 for the %2: its film was solved with \"%3\" cavitation "
               "(Swift–Stieber), which does not track the film's oil content. Choose "
               "\"%4\" as its %5 (case editor, %6 tab) and run again to see where the "
               "film is full and where it has broken up.")
        .arg(words, JointTitle(joint).toLower(),
             QString::fromUtf8(lubrication::ToString(CavitationModel::kReynolds)),
             QString::fromUtf8(lubrication::ToString(CavitationModel::kJfo)),
             QString::fromStdString(field->label).toLower(),
             QString::fromStdString(engine::FieldGroupTitle(field->group)));
  }
  if (std::string_view(info.name) == "deformation") {
    return QObject::tr(
               "No %1 for the %2: its surfaces are rigid. Choose \"elastic_layer\" or "
               "\"half_space\" as its surface compliance (case editor) and run again to see how "
               "far the surfaces give way under the film.")
        .arg(words, JointTitle(joint).toLower());
  }
  return QObject::tr("The %1 fields of this run have no %2.")
      .arg(JointTitle(joint).toLower(), words);
}

std::pair<double, double> ValueRange(const JointFieldFrames& joint, const FieldArrayInfo& info) {
  double lo = INFINITY, hi = -INFINITY;
  const size_t nx = joint.angle_lines.size();
  const bool grid = joint.HasGrid() && !joint.no_film.empty();
  for (const auto& frame : joint.frames) {
    const std::vector<double>* values = FindFieldArray(frame, info.name);
    if (!values) continue;
    for (size_t n = 0; n < values->size(); ++n) {
      const double v = (*values)[n];
      if (!std::isfinite(v) || (grid && joint.InNoFilm(joint.angle_lines[n % nx]))) continue;
      lo = std::min(lo, v * info.scale), hi = std::max(hi, v * info.scale);
    }
  }
  return {lo, hi};
}

double ColumnAngleDeg(const JointFieldFrames& joint, size_t column, size_t frame) {
  const double a = (joint.angle_lines[column] + joint.Rotation(frame)) * kDegreesPerRadian;
  if (!joint.periodic) return a;
  const double w = std::fmod(a, 360.0);
  return w < 0 ? w + 360.0 : w;
}

FilmMapData UnrolledMap(const JointFieldFrames& joint, size_t frame, const FieldArrayInfo& info) {
  FilmMapData d;
  if (!joint.HasGrid() || frame >= joint.frames.size()) return d;
  const std::vector<double>* values = FindFieldArray(joint.frames[frame], info.name);
  if (!values || values->size() != joint.mesh.points.size()) return d;
  const size_t nx = joint.angle_lines.size(), ny = joint.axial_lines.size();
  SetLabels(joint, &d);
  d.value_title = QString::fromUtf8(info.title);
  if (joint.name != "skirt") d.y_title = QObject::tr("Position across the width [mm]");
  for (double y : joint.axial_lines) d.y.push_back(y * 1e3);

  // Columns in body-frame order; a periodic joint closes at 0° and 360°.
  std::vector<size_t> order(nx);
  std::iota(order.begin(), order.end(), size_t(0));
  std::vector<double> angle(nx);
  for (size_t i = 0; i < nx; ++i) angle[i] = ColumnAngleDeg(joint, i, frame);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return angle[a] < angle[b]; });
  const bool close = joint.periodic;
  const double eps = 1e-9;
  const bool add_start = close && angle[order.front()] > eps;
  const bool add_end = close && angle[order.back()] < 360.0 - eps;
  // The value where the wrap-around element crosses 0° (= 360°): between the last and first.
  auto edge = [&](size_t j) {
    const double a0 = angle[order.back()], a1 = angle[order.front()] + 360.0;
    const double f = a1 > a0 ? (360.0 - a0) / (a1 - a0) : 0.0;
    return (1 - f) * (*values)[order.back() + nx * j] + f * (*values)[order.front() + nx * j];
  };
  if (add_start) d.x.push_back(0.0);
  for (size_t i : order) d.x.push_back(angle[i]);
  if (add_end) d.x.push_back(360.0);
  if (close && !add_end && d.x.back() < 360.0) d.x.back() = 360.0;
  d.values.reserve(d.x.size() * ny);
  for (size_t j = 0; j < ny; ++j) {
    if (add_start) d.values.push_back(edge(j) * info.scale);
    for (size_t i : order) d.values.push_back((*values)[i + nx * j] * info.scale);
    if (add_end) d.values.push_back(edge(j) * info.scale);
  }
  if (frame < joint.load.size()) {
    const auto& f = joint.load[frame];
    const double magnitude = std::hypot(f[0], f[1]);
    if (magnitude > 0) {
      double a = std::atan2(f[1], f[0]) * kDegreesPerRadian;
      if (a < 0) a += 360.0;
      d.x_line = a;
      d.x_line_label = QObject::tr("load %1 kN").arg(magnitude / 1e3, 0, 'f', 1);
    }
  }
  return d;
}

std::vector<double> ColumnExtremes(const JointFieldFrames& joint, size_t frame,
                                   const FieldArrayInfo& info) {
  const size_t nx = joint.angle_lines.size(), ny = joint.axial_lines.size();
  std::vector<double> out(nx, NAN);
  if (!joint.HasGrid() || frame >= joint.frames.size()) return out;
  const std::vector<double>* values = FindFieldArray(joint.frames[frame], info.name);
  if (!values || values->size() != nx * ny) return out;
  for (size_t i = 0; i < nx; ++i) {
    double e = info.minimum_matters ? INFINITY : -INFINITY;
    for (size_t j = 0; j < ny; ++j) {
      const double v = (*values)[i + nx * j];
      if (!std::isfinite(v)) continue;
      e = info.minimum_matters ? std::min(e, v) : std::max(e, v);
    }
    out[i] = std::isfinite(e) ? e * info.scale : NAN;
  }
  return out;
}

FilmMapData CrankAngleMap(const FieldFrames& frames, size_t joint_index,
                          const FieldArrayInfo& info) {
  FilmMapData d;
  if (joint_index >= frames.joints.size()) return d;
  const JointFieldFrames& joint = frames.joints[joint_index];
  if (!joint.HasGrid()) return d;
  SetLabels(joint, &d);
  const QString along =
      joint.name == "skirt" ? QObject::tr("along the skirt") : QObject::tr("across the width");
  d.value_title = QObject::tr("%1, %2 %3 [%4]")
                      .arg(QString::fromUtf8(info.words).left(1).toUpper() +
                               QString::fromUtf8(info.words).mid(1),
                           info.minimum_matters ? QObject::tr("smallest") : QObject::tr("largest"),
                           along, QString::fromUtf8(info.unit));
  d.y_title = QObject::tr("Crank angle [°CA]");
  d.y_ticks = {0, 90, 180, 270, 360, 450, 540, 630, 720};  // the strokes' dead centres
  // The sides stay named (thrust, anti-thrust); the map's y is crank angle, not the skirt's
  // length: no top or bottom edge labels.
  d.top = d.bottom = {};

  // Rows: the frames in crank-angle order (a reported cycle may start anywhere in 0–720 °CA).
  const size_t count = std::min(frames.crank_angle_deg.size(), joint.frames.size());
  std::vector<size_t> rows(count);
  std::iota(rows.begin(), rows.end(), size_t(0));
  std::stable_sort(rows.begin(), rows.end(), [&](size_t a, size_t b) {
    return frames.crank_angle_deg[a] < frames.crank_angle_deg[b];
  });
  const size_t nx = joint.angle_lines.size();
  const bool resample = joint.periodic && Turned(joint);
  if (resample) {
    for (size_t i = 0; i <= nx; ++i) d.x.push_back(360.0 * double(i) / double(nx));
  } else {
    for (size_t i = 0; i < nx; ++i) d.x.push_back(joint.angle_lines[i] * kDegreesPerRadian);
    if (joint.periodic) d.x.push_back(360.0);
  }
  for (size_t k : rows) {
    const double angle = frames.crank_angle_deg[k];
    if (!d.y.empty() && !(angle > d.y.back())) continue;  // keep the lines increasing
    const std::vector<double> extremes = ColumnExtremes(joint, k, info);
    d.y.push_back(angle);
    if (k < joint.load.size() && (joint.load[k][0] != 0 || joint.load[k][1] != 0)) {
      const double a = std::atan2(joint.load[k][1], joint.load[k][0]) * kDegreesPerRadian;
      d.points.push_back({a < 0 ? a + 360.0 : a, angle});
    }
    if (resample) {
      std::vector<std::pair<double, double>> samples;
      for (size_t i = 0; i < nx; ++i) samples.push_back({ColumnAngleDeg(joint, i, k), extremes[i]});
      std::sort(samples.begin(), samples.end());
      for (double x : d.x) d.values.push_back(Periodic(samples, std::fmod(x, 360.0)));
    } else {
      d.values.insert(d.values.end(), extremes.begin(), extremes.end());
      if (joint.periodic) d.values.push_back(extremes.front());
    }
  }
  // A whole cycle of equally spaced frames wraps round: the map reaches from 0 to 720 °CA (the
  // row after the last is the first one cycle on, the row before the first the last one cycle
  // back), as the x lines of a bearing close at 360°.
  const size_t row = d.x.size(), n = d.y.size();
  if (n >= 2 && d.values.size() == row * n) {
    const double step = (d.y.back() - d.y.front()) / double(n - 1);
    if (engine::SpanIsACycle(n, step * kRadiansPerDegree)) {
      const std::vector<double> first(d.values.begin(), d.values.begin() + long(row));
      const std::vector<double> last(d.values.end() - long(row), d.values.end());
      if (d.y.back() < 720.0 - 1e-9) {
        d.y.push_back(d.y.front() + 720.0);
        d.values.insert(d.values.end(), first.begin(), first.end());
      }
      if (d.y.front() > 1e-9) {
        d.y.insert(d.y.begin(), d.y[n - 1] - 720.0);
        d.values.insert(d.values.begin(), last.begin(), last.end());
      }
    }
  }
  if (!d.points.empty()) d.points_label = QObject::tr("load direction");
  return d;
}

}  // namespace filmdyn::ui
