#include "core/lubrication/film_integrals.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace filmdyn::lubrication {

namespace {
void RequireNodeField(const char* what, Eigen::Index size, int nodes) {
  if (size != nodes) {
    throw std::logic_error(std::string("IntegrateFilm: ") + what + " has " + std::to_string(size) +
                           " values for " + std::to_string(nodes) + " nodes");
  }
}

void RequireNodeField(const char* what, const Eigen::VectorXd* field, int nodes) {
  if (!field) throw std::logic_error(std::string("IntegrateFilm: no ") + what + " field");
  RequireNodeField(what, field->size(), nodes);
}
}  // namespace

FilmIntegrals IntegrateFilm(const ReynoldsFem& fem, const ReynoldsSolution& fields,
                            const ReynoldsParams& params, const FilmIntegralSpec& spec) {
  const int n = fem.NodeCount();
  const int n_loads = static_cast<int>(spec.load_directions.size());
  const int n_arms = static_cast<int>(spec.friction_arms.size());
  if (n_loads > FilmIntegrals::kMaxLoads || n_arms > ElementFriction::kMaxMoments) {
    throw std::logic_error("IntegrateFilm: more load directions or friction arms than capacity");
  }
  if (!(spec.symmetry > 0.0)) throw std::logic_error("IntegrateFilm: symmetry must be > 0");
  const bool jfo = fem.options().cavitation == CavitationModel::kJfo;
  const Eigen::VectorXd& h = fem.film_thickness();
  const auto& fac = fem.factors();
  const Eigen::VectorXd &p = fields.pressure, &pc_node = fields.contact_pressure;
  RequireNodeField("film thickness", h.size(), n);
  RequireNodeField("factors", static_cast<Eigen::Index>(fac.size()), n);
  RequireNodeField("pressure", p.size(), n);
  RequireNodeField("contact pressure", pc_node.size(), n);
  RequireNodeField("cavitated", static_cast<Eigen::Index>(fields.cavitated.size()), n);
  if (jfo) RequireNodeField("fluid fraction", fields.fluid_fraction.size(), n);
  for (const Eigen::VectorXd* d : spec.load_directions) RequireNodeField("load direction", d, n);
  for (const ScaledField& w : spec.friction_arms) RequireNodeField("friction arm", w.field, n);

  // Friction (eq. 31, Patir & Cheng 1979 shear-stress factors) from the element means of the
  // nodal Couette terms theta (Phi_f +- Phi_fs)/h, of Phi_fp h and of p_c, and the element's
  // (constant) pressure gradient along the sliding axis. The asperity part mu_f p_c opposes the
  // relative sliding. With Reynolds cavitation the Couette shear acts over the whole film (as in
  // Raimondi & Boyd's friction variable); with JFO it is scaled by the fluid fraction theta.
  // Summed two ways: part by part over the whole film (FilmFriction), and element by element
  // (ElementFriction), where each element's own traction meets its arm. Every quantity has its
  // own accumulator, summed in element order: a result does not depend on which other
  // directions or arms were asked for.
  const double mu = params.viscosity, u = params.u_diff;
  const double mu_f = params.film ? params.film->boundary_friction() : 0.0;
  const double sgn = (u > 0) - (u < 0);
  const bool along_x = fem.sliding_axis() == 0;
  // Per node once (a node belongs to up to six elements): the Couette terms, and the data of the
  // caller's fields.
  std::vector<double> couette(2 * static_cast<size_t>(n));
  // With a pressure-dependent viscosity or shear thinning the Couette shear of a node takes its
  // own mu: the terms carry mu/mu0, and mu (params.viscosity) stays mu0.
  const PressureViscosity* pv =
      params.pressure_viscosity != nullptr && params.pressure_viscosity->active()
          ? params.pressure_viscosity
          : nullptr;
  const CrossLaw* shear = params.shear_thinning != nullptr && params.shear_thinning->active()
                              ? params.shear_thinning
                              : nullptr;
  for (int k = 0; k < n; ++k) {
    const double theta_f = jfo ? fields.fluid_fraction[k] : 1.0;
    double ratio = pv != nullptr ? pv->Ratio(p[k]) : 1.0;
    if (shear != nullptr) ratio *= shear->InFilm(u, h[k]);
    couette[2 * k] = ratio * theta_f * (fac[k].shear_f + fac[k].shear_fs) / h[k];
    couette[2 * k + 1] = ratio * theta_f * (fac[k].shear_f - fac[k].shear_fs) / h[k];
  }
  std::array<const double*, FilmIntegrals::kMaxLoads> direction{};
  for (int i = 0; i < n_loads; ++i) direction[i] = spec.load_directions[i]->data();
  std::array<const double*, ElementFriction::kMaxMoments> arm{};
  for (int i = 0; i < n_arms; ++i) arm[i] = spec.friction_arms[i].field->data();

  std::array<double, FilmIntegrals::kMaxLoads> load{}, contact_load{};
  FilmFriction parts;
  ElementFriction by_element;
  for (const auto& e : fem.elements()) {
    const auto& dnds = along_x ? e.dndx : e.dndy;
    double couette1 = 0.0, couette2 = 0.0, hfp = 0.0, dpds = 0.0, pc = 0.0, pt = 0.0;
    std::array<double, FilmIntegrals::kMaxLoads> d_sum{}, pt_d{}, pc_d{};
    std::array<double, ElementFriction::kMaxMoments> arm_sum{};
    for (int a = 0; a < 3; ++a) {
      const int k = e.node[a];
      const double ptot = p[k] + pc_node[k];
      couette1 += couette[2 * k];
      couette2 += couette[2 * k + 1];
      hfp += fac[k].shear_fp * h[k];
      dpds += dnds[a] * p[k];
      pc += pc_node[k];
      pt += ptot;
      for (int i = 0; i < n_loads; ++i) {
        const double d = direction[i][k];
        d_sum[i] += d;
        pt_d[i] += ptot * d;
        pc_d[i] += pc_node[k] * d;
      }
      for (int i = 0; i < n_arms; ++i) arm_sum[i] += arm[i][k];
    }
    // Products of P1 fields integrate exactly: int a b dA = A/12 (sum a sum b + sum a_i b_i).
    const double a12 = e.area / 12.0;
    for (int i = 0; i < n_loads; ++i) {
      load[i] += a12 * (pt * d_sum[i] + pt_d[i]);
      contact_load[i] += a12 * (pc * d_sum[i] + pc_d[i]);
    }
    const double poiseuille = e.area * 0.5 * (hfp / 3.0) * dpds;
    parts.couette_surface1 += e.area * couette1 / 3.0;
    parts.couette_surface2 += e.area * couette2 / 3.0;
    parts.poiseuille += poiseuille;
    parts.contact += e.area * pc / 3.0;
    const double boundary = sgn * mu_f * e.area * pc / 3.0;
    const double tau_area = -mu * u * e.area * couette1 / 3.0 - poiseuille - boundary;
    by_element.force += tau_area;
    by_element.contact_force -= boundary;
    for (int i = 0; i < n_arms; ++i) {
      by_element.moment[i] += tau_area * spec.friction_arms[i].scale * arm_sum[i] / 3.0;
    }
  }

  FilmIntegrals r;
  const double sym = spec.symmetry;
  for (int i = 0; i < n_loads; ++i) {
    r.load[i] = sym * load[i];
    r.contact_load[i] = sym * contact_load[i];
  }
  FilmFriction& f = r.friction;
  f.couette_surface1 = sym * parts.couette_surface1;
  f.couette_surface2 = sym * parts.couette_surface2;
  f.poiseuille = sym * parts.poiseuille;
  f.contact = sym * parts.contact;
  f.surface1 = -mu * u * f.couette_surface1 - f.poiseuille - sgn * mu_f * f.contact;
  f.surface2 = mu * u * f.couette_surface2 - f.poiseuille + sgn * mu_f * f.contact;
  r.element_friction.force = sym * by_element.force;
  r.element_friction.contact_force = sym * by_element.contact_force;
  for (int i = 0; i < n_arms; ++i) r.element_friction.moment[i] = sym * by_element.moment[i];

  // Nodal extremes and areas (lumped: the cavitated set is a set of nodes).
  r.moft = 1e300;
  double cavitated_area = 0.0, film_area = 0.0;
  const auto& area = fem.lumped_area();
  for (int k = 0; k < n; ++k) {
    if (h[k] < r.moft) {
      r.moft = h[k];
      r.moft_node = k;
    }
    if (p[k] > r.max_pressure) {
      r.max_pressure = p[k];
      r.max_pressure_node = k;
    }
    r.max_contact_pressure = std::max(r.max_contact_pressure, pc_node[k]);
    film_area += area[k];
    if (fields.cavitated[k])
      cavitated_area += area[k] * (jfo ? 1.0 - fields.fluid_fraction[k] : 1.0);
  }
  r.cavitated_area = sym * cavitated_area;
  r.film_area = sym * film_area;
  return r;
}

}  // namespace filmdyn::lubrication
