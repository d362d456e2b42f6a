#pragma once
/// @file Round axis steps: 1, 2, 2.5 or 5 × 10ⁿ, the steps people read without effort. One
/// definition for the result plots' axes and the film maps' colour bars.
#include <QString>
#include <optional>
#include <utility>
#include <vector>

class QValueAxis;

namespace filmdyn::ui {

/// The smallest round step (1, 2, 2.5 or 5 × 10ⁿ) not below span / target; 1 for a bad span.
double RoundStep(double span, int target);

/// An axis range on whole steps.
struct RoundRange {
  double min = 0.0, max = 1.0, step = 0.2;
  int decimals = 1;  ///< digits after the point that show every tick exactly
};
/// [lo, hi] widened outwards to whole round steps, with about `target` intervals. A zero or
/// invalid span gets a unit-sized range around the value.
RoundRange RoundRangeCovering(double lo, double hi, int target);

/// Digits after the point needed to write multiples of `step` exactly (0 for 10, 1 for 0.5 and
/// 2.5, 2 for 0.25).
int DecimalsFor(double step);

/// Puts `axis` on [lo, hi] with a tick every `step` counted from 0 and labels with the decimals
/// the step needs: the value axes of the result plots and the study charts.
void SetRoundAxis(QValueAxis* axis, double lo, double hi, double step);
/// The same over `range`.
void SetRoundAxis(QValueAxis* axis, const RoundRange& range);

/// Round tick positions covering [lo, hi]: steps of 1, 2, 2.5 or 5 × 10ⁿ, about `target` of them.
std::vector<double> RoundTicks(double lo, double hi, int target = 6);

/// [lo, hi] widened to whole ticks of RoundTicks(lo, hi, target): the range of a colour bar
/// whose end numbers are round (a constant or empty range becomes [lo, lo + 1]).
std::pair<double, double> RoundedRange(double lo, double hi, int target = 5);

/// A value for a readout, with about 4 significant digits and no trailing zeros ("12.35", "0.5",
/// "1.2e-05"), followed by the unit when one is given.
QString FormatReadout(double value, const QString& unit = {});
/// A point of two values in one unit ("0.02, -11.22 kN", not "0.02296, -11.22 kN"): both with
/// the decimals that give the larger magnitude about 4 significant digits, then the unit.
QString FormatReadoutPair(double x, double y, const QString& unit = {});
/// Values in one unit the same way, joined by `separator` ("-0.04 / -11.22 / 22.17"), no unit:
/// FormatReadoutPair is this for two values and ", " (then its unit). A value that is not finite
/// reads "–"; zeros alone, or magnitudes of 1e6 and more or below 1e-4, each in FormatReadout's
/// form.
QString FormatReadoutValues(const std::vector<double>& values, const QString& separator);
/// The decimals FormatReadoutValues gives values in one unit (about 4 significant digits for the
/// largest finite magnitude, 0 to 6), or none where they read better each in 'g' form (no finite
/// value, zeros alone, magnitudes of 1e6 and more or below 1e-4). Values that are not finite are
/// ignored.
std::optional<int> CommonDecimals(const std::vector<double>& values);
/// A value with `decimals` decimals; one that rounds to zero reads without a sign ("0.00", not
/// "-0.00").
QString FixedDecimals(double value, int decimals);

}  // namespace filmdyn::ui
