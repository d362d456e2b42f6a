#include "ui/plots/plot_specs.hpp"

#include <QObject>
#include <cmath>

namespace filmdyn::ui {

namespace {

using Samples = std::vector<RunSample>;

// y(column) × scale against crank angle.
PlotCurve VsAngle(const QString& name, Column column, double scale) {
  return {name, [column, scale](const Samples& samples) {
            QList<QPointF> points;
            points.reserve(qsizetype(samples.size()));
            for (const RunSample& s : samples) {
              const double y = s[column] * scale;
              if (std::isfinite(y) && std::isfinite(s[Column::kCrankAngle])) {
                points.append(QPointF(s[Column::kCrankAngle], y));
              }
            }
            return points;
          }};
}

PlotCurve XY(const QString& name, Column x_column, double x_scale, Column y_column,
             double y_scale) {
  return {name, [=](const Samples& samples) {
            QList<QPointF> points;
            for (const RunSample& s : samples) {
              const double x = s[x_column] * x_scale, y = s[y_column] * y_scale;
              if (std::isfinite(x) && std::isfinite(y)) points.append(QPointF(x, y));
            }
            return points;
          }};
}

// Phase portrait of a column against its time derivative (central differences in time).
PlotCurve Phase(const QString& name, Column column, double scale, double rate_scale) {
  return {name, [=](const Samples& samples) {
            QList<QPointF> points;
            for (size_t k = 1; k + 1 < samples.size(); ++k) {
              const double dt = samples[k + 1][Column::kTime] - samples[k - 1][Column::kTime];
              const double rate = (samples[k + 1][column] - samples[k - 1][column]) / dt;
              const double x = samples[k][column] * scale;
              if (std::isfinite(x) && std::isfinite(rate) && dt > 0) {
                points.append(QPointF(x, rate * rate_scale));
              }
            }
            return points;
          }};
}

std::vector<PlotSpec> Make() {
  const QString ca = QObject::tr("crank angle [°CA]");
  std::vector<PlotSpec> plots;
  plots.push_back({"piston_lateral",
                   QObject::tr("Piston lateral displacement e₀"),
                   ca,
                   QObject::tr("e₀ [µm]"),
                   true,
                   false,
                   {VsAngle("e₀", Column::kPistonLateral, 1e6)}});
  plots.push_back({"piston_tilt",
                   QObject::tr("Piston tilt γ"),
                   ca,
                   QObject::tr("γ [mrad]"),
                   true,
                   false,
                   {VsAngle("γ", Column::kPistonTilt, 1e3)}});
  plots.push_back({"secondary_rates",
                   QObject::tr("Secondary-motion rates"),
                   ca,
                   QObject::tr("ė₀ [mm/s], γ̇ [rad/s]"),
                   true,
                   false,
                   {VsAngle("ė₀ [mm/s]", Column::kPistonLateralVelocity, 1e3),
                    VsAngle("γ̇ [rad/s]", Column::kPistonTiltRate, 1.0)}});
  plots.push_back({"journal_orbit",
                   QObject::tr("Journal orbit (rod frame)"),
                   QObject::tr("x [µm]"),
                   QObject::tr("y [µm]"),
                   false,
                   true,
                   {XY("orbit", Column::kJournalEccX, 1e6, Column::kJournalEccY, 1e6)}});
  plots.push_back({"liner_forces",
                   QObject::tr("Liner (skirt) forces"),
                   ca,
                   QObject::tr("[N]"),
                   true,
                   false,
                   {VsAngle("normal", Column::kSkirtNormalForce, 1.0),
                    VsAngle("friction", Column::kSkirtFrictionForce, 1.0)}});
  plots.push_back(
      {"bigend_forces",
       QObject::tr("Big-end force"),
       ca,
       QObject::tr("[kN]"),
       true,
       false,
       {VsAngle("F_x", Column::kBigEndForceX, 1e-3), VsAngle("F_y", Column::kBigEndForceY, 1e-3),
        VsAngle("gas", Column::kGasForce, 1e-3)}});
  plots.push_back(
      {"moft",
       QObject::tr("Minimum oil-film thickness"),
       ca,
       QObject::tr("MOFT [µm]"),
       true,
       false,
       {VsAngle("skirt", Column::kSkirtMoft, 1e6), VsAngle("big end", Column::kBearingMoft, 1e6)}});
  plots.push_back(
      {"fpl",
       QObject::tr("Friction power loss"),
       ca,
       QObject::tr("FPL [W]"),
       true,
       false,
       {VsAngle("skirt", Column::kSkirtFpl, 1.0), VsAngle("big end", Column::kBearingFpl, 1.0)}});
  plots.push_back({"phase_eps",
                   QObject::tr("Phase portrait ε / ε̇"),
                   QObject::tr("ε [-]"),
                   QObject::tr("ε̇ [1/s]"),
                   false,
                   false,
                   {Phase("ε", Column::kBearingEps, 1.0, 1.0)}});
  plots.push_back({"phase_tilt",
                   QObject::tr("Phase portrait γ / γ̇"),
                   QObject::tr("γ [mrad]"),
                   QObject::tr("γ̇ [rad/s]"),
                   false,
                   false,
                   {XY("γ", Column::kPistonTilt, 1e3, Column::kPistonTiltRate, 1.0)}});
  return plots;
}

}  // namespace

const std::vector<PlotSpec>& StandardPlots() {
  static const std::vector<PlotSpec> plots = Make();
  return plots;
}

}  // namespace filmdyn::ui
