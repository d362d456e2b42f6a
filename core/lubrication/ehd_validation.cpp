#include "core/lubrication/ehd_validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/lubrication/bearing_solver.hpp"
#include "core/lubrication/film_compliance.hpp"
#include "core/lubrication/reynolds_fem.hpp"
#include "core/lubrication/tri_mesh.hpp"

namespace filmdyn::lubrication {

namespace {

// p along the slider for the flow per width q; the sign of p(L): +1 when positive (q too small;
// also when p runs away upward), -1 when negative (q too large; also when the film closes, which
// only a strongly negative pressure does).
int Shoot(const InclinedSlider& s, double layer, double q, int steps, std::vector<double>* p) {
  const double dx = s.length / steps;
  auto slope = [&](double x, double pressure) -> double {
    const double h = s.h_inlet + (s.h_outlet - s.h_inlet) * x / s.length + layer * pressure;
    if (!(h > 0.0)) return NAN;
    return 6.0 * s.viscosity * (s.speed * h - 2.0 * q) / (h * h * h);
  };
  p->assign(static_cast<std::size_t>(steps) + 1, 0.0);
  double v = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double x = i * dx;
    const double k1 = slope(x, v);
    const double k2 = slope(x + 0.5 * dx, v + 0.5 * dx * k1);
    const double k3 = slope(x + 0.5 * dx, v + 0.5 * dx * k2);
    const double k4 = slope(x + dx, v + dx * k3);
    v += dx / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (v > 1e12) return 1;
    if (!std::isfinite(v) || v < -1e12) return -1;
    (*p)[static_cast<std::size_t>(i) + 1] = v;
  }
  return (*p).back() > 0.0 ? 1 : -1;
}

}  // namespace

ElasticSliderReference ElasticSliderByShooting(const InclinedSlider& s, double layer, int steps) {
  // p(L) falls as q rises: bisection on q between a flow that leaves p(L) > 0 (the outlet film's
  // Couette flow U h_o / 2 at most: the rigid slider's flow is above it) and one that leaves it
  // < 0 (the inlet's, enlarged until it does).
  std::vector<double> p;
  double lo = 0.25 * s.speed * s.h_outlet, hi = 0.5 * s.speed * s.h_inlet;
  while (Shoot(s, layer, hi, steps, &p) > 0) hi *= 1.5;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (Shoot(s, layer, mid, steps, &p) < 0)
      hi = mid;
    else
      lo = mid;
    if (hi - lo <= 1e-15 * hi) break;
  }
  Shoot(s, layer, 0.5 * (lo + hi), steps, &p);
  ElasticSliderReference r;
  const double dx = s.length / steps;
  for (int i = 0; i <= steps; ++i) {
    const double w = (i == 0 || i == steps) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    r.load += w * p[static_cast<std::size_t>(i)];
  }
  r.load *= dx / 3.0;
  r.peak_pressure = *std::max_element(p.begin(), p.end());
  r.max_deformation = layer * r.peak_pressure;
  return r;
}

ElasticSliderFem SolveElasticSliderFem(const InclinedSlider& s, double thickness, double modulus,
                                       double poisson, int n) {
  SliderStrip strip = MakeSliderStrip(s, n);
  ReynoldsFem& fem = *strip.fem;
  const TriMesh& m = fem.mesh();
  ComplianceSpec spec;
  spec.model = ComplianceModel::kElasticLayer;
  spec.layer_thickness = thickness;
  spec.layer_modulus = modulus;
  spec.layer_poisson = poisson;
  spec.tolerance = 1e-8;  // the film to 1e-8 of its thinnest: below the comparison's tolerance
  ElasticFilm film(SurfaceCompliance::Build(spec, m, std::nullopt), spec);
  const ElasticSolveStats& stats = film.Solve(fem, strip.params);
  ElasticSliderFem out;
  out.converged = stats.converged;
  out.load = fem.Integrate(fem.solution().pressure) / SliderStrip::kStripWidth;
  out.peak_pressure = fem.solution().pressure.maxCoeff();
  out.max_deformation = stats.max_deformation;
  return out;
}

std::vector<verification::ValidationRow> EhdValidationRows() {
  std::vector<verification::ValidationRow> rows;
  // Love's rectangle: a square of side 2a under uniform p deflects its centre by
  // 2.24 p a (1 - nu^2) / E and its corners by 1.12 (Johnson 1985, §3.2; to Johnson's 3 digits).
  const double a = 1e-3;
  const std::string johnson = "Johnson, Contact Mechanics (1985) §3.2";
  rows.push_back({"ehd", "uniformly loaded square: centre deflection / (p a (1-nu^2)/E)", johnson,
                  BoussinesqRectangle(-a, a, -a, a) / (std::numbers::pi * a), 2.24, 0.005, false});
  rows.push_back({"ehd", "uniformly loaded square: corner deflection / (p a (1-nu^2)/E)", johnson,
                  BoussinesqRectangle(0.0, 2.0 * a, 0.0, 2.0 * a) / (std::numbers::pi * a), 1.12,
                  0.005, false});
  // The inclined slider on a 2 mm lining of E = 3 GPa, nu = 0.3: the lining gives way by about
  // half the outlet film (2.4 of 5 um) and the load falls to half the rigid slider's.
  const InclinedSlider slider;
  const double t = 2e-3, e = 3e9, nu = 0.3;
  constexpr int kCells = 400;
  const ElasticSliderReference ref =
      ElasticSliderByShooting(slider, LayerCompliance(t, e, nu), 40000);
  const ElasticSliderFem fem = SolveElasticSliderFem(slider, t, e, nu, kCells);
  const std::string src = "1-D Reynolds with h = h_rigid + t_c p, shooting (RK4, 40 000 steps)";
  const std::string what =
      fmt::format("slider on an elastic lining (2 mm, 3 GPa, nu 0.3; {} cells): ", kCells);
  rows.push_back(
      {"ehd", what + "load per width", src, fem.converged ? fem.load : NAN, ref.load, 1e-4});
  rows.push_back({"ehd", what + "peak pressure", src, fem.peak_pressure, ref.peak_pressure, 1e-3});
  rows.push_back(
      {"ehd", what + "max deformation", src, fem.max_deformation, ref.max_deformation, 1e-3});
  // Infinitely stiff lining: the rigid slider's load (closed form) to 1e-10 of the FEM's own.
  const ElasticSliderFem stiff = SolveElasticSliderFem(slider, t, 1e30, nu, kCells);
  const SliderFem rigid = SolveSliderFem(slider, PressureViscosity{}, kCells);
  rows.push_back({"ehd", "slider on an infinitely stiff lining: load / rigid slider's load",
                  "the rigid solve", stiff.load / rigid.load, 1.0, 1e-10});
  // A mass-conserving (JFO) film on an elastic lining where no film reforms (the steady bearing,
  // its film starting full at its largest gap) is the Reynolds film: the two discretisations of
  // the Couette flow differ at second order where the deformation makes the gap vary across the
  // width (1.3e-3 on this mesh, 3.3e-4 on twice as fine; docs/validation/ehd.md, item 11).
  BearingConfig lined;
  lined.geometry = {0.025, 0.02, 25e-6};
  lined.viscosity = 0.01;
  lined.mesh = {96, 16, true};
  lined.compliance.model = ComplianceModel::kElasticLayer;
  lined.compliance.layer_thickness = 1e-3;
  lined.compliance.layer_modulus = 5e9;
  lined.compliance.layer_poisson = 0.3;
  lined.compliance.tolerance = 1e-7;
  BearingConfig lined_jfo = lined;
  lined_jfo.solver.cavitation = CavitationModel::kJfo;
  BearingState state;
  state.eps = 0.8;
  state.omega_journal = 314.0;
  const BearingResult reynolds = BearingSolver(lined).Solve(state);
  BearingSolver jfo_solver(lined_jfo);
  const BearingResult& jfo = jfo_solver.Solve(state);
  const bool both = reynolds.elastic.converged && jfo.elastic.converged;
  rows.push_back({"ehd",
                  "bearing on an elastic lining (1 mm, 5 GPa; eps 0.8, 96 x 16 cells): JFO load / "
                  "Reynolds load",
                  "the Reynolds film (no film reforms)", both ? jfo.load / reynolds.load : NAN, 1.0,
                  3e-3});
  return rows;
}

}  // namespace filmdyn::lubrication
