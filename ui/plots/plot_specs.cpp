#include "ui/plots/plot_specs.hpp"

#include <QObject>
#include <cmath>

namespace filmdyn::ui {

namespace {

using Samples = std::vector<RunSample>;

bool Finite(double a, double b) { return std::isfinite(a) && std::isfinite(b); }

// y(column) × scale against crank angle.
PlotCurve VsAngle(const QString& name, Column column, double scale) {
  return {name, [column, scale](const Samples& samples) {
            CurvePoints out;
            out.xy.reserve(qsizetype(samples.size()));
            for (const RunSample& s : samples) {
              const double y = s[column] * scale, angle = s[Column::kCrankAngle];
              if (Finite(y, angle)) {
                out.xy.append(QPointF(angle, y));
                out.crank_angle.push_back(angle);
              }
            }
            return out;
          }};
}

// (minuend − subtrahend) × scale against crank angle: e.g. the hydrodynamic part of the FPL.
PlotCurve DifferenceVsAngle(const QString& name, Column minuend, Column subtrahend, double scale) {
  return {name, [=](const Samples& samples) {
            CurvePoints out;
            for (const RunSample& s : samples) {
              const double y = (s[minuend] - s[subtrahend]) * scale;
              const double angle = s[Column::kCrankAngle];
              if (Finite(y, angle)) {
                out.xy.append(QPointF(angle, y));
                out.crank_angle.push_back(angle);
              }
            }
            return out;
          }};
}

PlotCurve XY(const QString& name, Column x_column, double x_scale, Column y_column,
             double y_scale) {
  return {name, [=](const Samples& samples) {
            CurvePoints out;
            for (const RunSample& s : samples) {
              const double x = s[x_column] * x_scale, y = s[y_column] * y_scale;
              if (Finite(x, y) && std::isfinite(s[Column::kCrankAngle])) {
                out.xy.append(QPointF(x, y));
                out.crank_angle.push_back(s[Column::kCrankAngle]);
              }
            }
            return out;
          }};
}

// A phase portrait: a column against its time derivative, drawn through the run's motion
// samples. The rate column where it has values; runs saved before it was recorded have only the
// column: central differences in time of their output samples then.
PlotCurve Phase(const QString& name, Column column, Column rate_column, double scale,
                double rate_scale) {
  PlotCurve curve = XY(name, column, scale, rate_column, rate_scale);
  curve.from_motion = true;
  curve.points = [=, exact = curve.points](const Samples& samples) {
    CurvePoints out = exact(samples);
    if (!out.xy.isEmpty()) return out;
    for (size_t k = 1; k + 1 < samples.size(); ++k) {
      const double dt = samples[k + 1][Column::kTime] - samples[k - 1][Column::kTime];
      const double rate = (samples[k + 1][column] - samples[k - 1][column]) / dt;
      const double x = samples[k][column] * scale;
      if (Finite(x, rate) && dt > 0 && std::isfinite(samples[k][Column::kCrankAngle])) {
        out.xy.append(QPointF(x, rate * rate_scale));
        out.crank_angle.push_back(samples[k][Column::kCrankAngle]);
      }
    }
    return out;
  };
  return curve;
}

// `curve`, drawn only for runs with `film`.
PlotCurve Of(FilmOf film, PlotCurve curve) {
  curve.film = film;
  return curve;
}

PlotSpec VsCrankAngle(QString id, QString title, QString y_title, QString y_unit,
                      std::vector<PlotCurve> curves, bool non_negative = false) {
  PlotSpec spec;
  spec.id = std::move(id);
  spec.title = std::move(title);
  spec.x_title = QObject::tr("crank angle [°CA]");
  spec.x_unit = QObject::tr("°CA");
  spec.y_title = std::move(y_title);
  spec.y_unit = std::move(y_unit);
  spec.non_negative = non_negative;
  spec.curves = std::move(curves);
  return spec;
}

PlotSpec Portrait(QString id, QString title, QString x_title, QString x_unit, QString y_title,
                  QString y_unit, std::vector<PlotCurve> curves) {
  PlotSpec spec;
  spec.id = std::move(id);
  spec.title = std::move(title);
  spec.x_title = std::move(x_title);
  spec.x_unit = std::move(x_unit);
  spec.y_title = std::move(y_title);
  spec.y_unit = std::move(y_unit);
  spec.crank_angle_axis = false;
  spec.curves = std::move(curves);
  return spec;
}

std::vector<PlotSpec> Make() {
  std::vector<PlotSpec> plots;
  plots.push_back(VsCrankAngle("piston_lateral", QObject::tr("Piston lateral displacement e₀"),
                               QObject::tr("lateral e₀ [µm]"), "µm",
                               {Of(FilmOf::kSkirt, VsAngle("e₀", Column::kPistonLateral, 1e6))}));
  plots.push_back(VsCrankAngle("piston_tilt", QObject::tr("Piston tilt γ"),
                               QObject::tr("tilt γ [mrad]"), "mrad",
                               {Of(FilmOf::kSkirt, VsAngle("γ", Column::kPistonTilt, 1e3))}));
  plots.push_back(
      VsCrankAngle("piston_lateral_velocity", QObject::tr("Piston lateral velocity ė₀"),
                   QObject::tr("velocity ė₀ [mm/s]"), "mm/s",
                   {Of(FilmOf::kSkirt, VsAngle("ė₀", Column::kPistonLateralVelocity, 1e3))}));
  plots.push_back(VsCrankAngle(
      "piston_tilt_rate", QObject::tr("Piston tilt rate dγ/dt"), QObject::tr("dγ/dt [rad/s]"),
      "rad/s", {Of(FilmOf::kSkirt, VsAngle("dγ/dt", Column::kPistonTiltRate, 1.0))}));
  {
    PlotCurve path = XY("orbit", Column::kJournalEccX, 1e6, Column::kJournalEccY, 1e6);
    path.from_motion = true;
    path.film = FilmOf::kBigEnd;
    PlotSpec orbit = Portrait("journal_orbit", QObject::tr("Journal orbit (rod frame)"),
                              QObject::tr("journal centre x [µm]"), "µm",
                              QObject::tr("journal centre y [µm]"), "µm", {path});
    orbit.equal_axes = true;
    orbit.clearance_circle = true;
    plots.push_back(orbit);
  }
  {
    PlotSpec polar =
        Portrait("bigend_load_polar", QObject::tr("Big-end load diagram (rod frame)"),
                 QObject::tr("F_x on the rod [kN]"), "kN", QObject::tr("F_y on the rod [kN]"), "kN",
                 {XY("load", Column::kBigEndForceRodX, 1e-3, Column::kBigEndForceRodY, 1e-3)});
    polar.equal_axes = true;
    plots.push_back(polar);
  }
  plots.push_back(
      VsCrankAngle("liner_forces", QObject::tr("Liner (skirt) forces"),
                   QObject::tr("force on the skirt [N]"), "N",
                   {VsAngle("normal", Column::kSkirtNormalForce, 1.0),
                    Of(FilmOf::kSkirt, VsAngle("friction", Column::kSkirtFrictionForce, 1.0))}));
  // The crank pin's force on the rod in the global frame (the load diagram beside it shows the
  // same force in the rod's frame: its curves are named for that frame).
  plots.push_back(VsCrankAngle(
      "bigend_forces", QObject::tr("Big-end force (global frame) and gas force"),
      QObject::tr("force [kN]"), "kN",
      {VsAngle("F_x", Column::kBigEndForceX, 1e-3), VsAngle("F_y", Column::kBigEndForceY, 1e-3),
       VsAngle("gas", Column::kGasForce, 1e-3)}));
  plots.push_back(VsCrankAngle(
      "moft", QObject::tr("Minimum oil-film thickness"), QObject::tr("MOFT [µm]"), "µm",
      {VsAngle("skirt", Column::kSkirtMoft, 1e6), VsAngle("big end", Column::kBearingMoft, 1e6)},
      true));
  plots.push_back(VsCrankAngle("fpl", QObject::tr("Friction power loss"),
                               QObject::tr("friction power [W]"), "W",
                               {Of(FilmOf::kSkirt, VsAngle("skirt", Column::kSkirtFpl, 1.0)),
                                Of(FilmOf::kBigEnd, VsAngle("big end", Column::kBearingFpl, 1.0))},
                               true));
  plots.push_back(VsCrankAngle(
      "friction_split", QObject::tr("Friction power: film shear and asperity contact"),
      QObject::tr("friction power [W]"), "W",
      {Of(FilmOf::kSkirt,
          DifferenceVsAngle("skirt, film", Column::kSkirtFpl, Column::kSkirtContactFpl, 1.0)),
       Of(FilmOf::kSkirt, VsAngle("skirt, asperities", Column::kSkirtContactFpl, 1.0)),
       Of(FilmOf::kBigEnd,
          DifferenceVsAngle("big end, film", Column::kBearingFpl, Column::kBearingContactFpl, 1.0)),
       Of(FilmOf::kBigEnd, VsAngle("big end, asperities", Column::kBearingContactFpl, 1.0))},
      true));
  plots.push_back(VsCrankAngle(
      "peak_pressure", QObject::tr("Peak film pressure"), QObject::tr("peak film pressure [MPa]"),
      "MPa",
      {VsAngle("skirt", Column::kSkirtPeakPressure, 1e-6),
       VsAngle("big end", Column::kBearingPeakPressure, 1e-6),
       // Mass-conserving films: what the steps between rows saw.
       VsAngle("skirt, steps between samples", Column::kSkirtStepPeakPressure, 1e-6),
       VsAngle("big end, steps between samples", Column::kBearingStepPeakPressure, 1e-6)},
      true));
  plots.push_back(VsCrankAngle("peak_contact_pressure",
                               QObject::tr("Peak asperity contact pressure"),
                               QObject::tr("peak contact pressure [MPa]"), "MPa",
                               {VsAngle("skirt", Column::kSkirtPeakContactPressure, 1e-6),
                                VsAngle("big end", Column::kBearingPeakContactPressure, 1e-6)},
                               true));
  // Oil through each film (mass-conserving cavitation makes them balance over a cycle).
  plots.push_back(VsCrankAngle("bigend_oil_flow", QObject::tr("Big-end oil flow"),
                               QObject::tr("oil flow [cm³/s]"), "cm³/s",
                               {VsAngle("supply", Column::kBearingSupplyFlow, 1e6),
                                VsAngle("side leakage", Column::kBearingSideFlow, 1e6)}));
  plots.push_back(VsCrankAngle(
      "skirt_oil_flow", QObject::tr("Skirt oil flow"), QObject::tr("oil flow [cm³/s]"), "cm³/s",
      {VsAngle("in", Column::kSkirtInflow, 1e6), VsAngle("out", Column::kSkirtOutflow, 1e6)},
      true));
  plots.push_back(VsCrankAngle("skirt_wetted_fraction", QObject::tr("Skirt wetted fraction"),
                               QObject::tr("oil-covered share of the panels [-]"), "",
                               {VsAngle("skirt", Column::kSkirtWettedFraction, 1.0)}, true));
  {
    PlotSpec eps = Portrait(
        "phase_eps", QObject::tr("Big-end phase portrait ε / dε/dt"),
        QObject::tr("eccentricity ratio ε [-]"), "", QObject::tr("rate dε/dt [1/s]"), "1/s",
        {Of(FilmOf::kBigEnd, Phase("ε", Column::kBearingEps, Column::kBearingEpsRate, 1.0, 1.0))});
    eps.x_non_negative = true;
    plots.push_back(eps);
  }
  plots.push_back(Portrait(
      "phase_tilt", QObject::tr("Piston phase portrait γ / dγ/dt"), QObject::tr("tilt γ [mrad]"),
      "mrad", QObject::tr("dγ/dt [rad/s]"), "rad/s",
      {Of(FilmOf::kSkirt, Phase("γ", Column::kPistonTilt, Column::kPistonTiltRate, 1e3, 1.0))}));
  return plots;
}

}  // namespace

const std::vector<PlotSpec>& StandardPlots() {
  static const std::vector<PlotSpec> plots = Make();
  return plots;
}

}  // namespace filmdyn::ui
