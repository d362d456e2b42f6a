#include "core/engine/slider_crank_reference.hpp"

#include <cmath>
#include <numbers>

namespace filmdyn::engine {

namespace {
double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}
}  // namespace

SliderCrankReference ExactSliderCrank(const CrankTrainGeometry& g, double phi, double omega,
                                      double gas_force) {
  SliderCrankReference r;
  const double l1 = g.crank_radius, l2 = g.rod_length;
  // Horizontal span from crank pin to piston pin, s = C_p + L1 sin φ, and its rates.
  const double s = g.pin_offset + l1 * std::sin(phi);
  const double s_dot = l1 * omega * std::cos(phi);
  const double s_ddot = -l1 * omega * omega * std::sin(phi);
  const double d = std::sqrt(l2 * l2 - s * s);  // vertical span
  r.piston_position = l1 * std::cos(phi) + d;
  r.piston_velocity = -l1 * omega * std::sin(phi) - s * s_dot / d;
  r.piston_acceleration = -l1 * omega * omega * std::cos(phi) - (s_dot * s_dot + s * s_ddot) / d -
                          s * s * s_dot * s_dot / (d * d * d);
  r.rod_angle = -std::asin(s / l2);
  r.rod_angular_velocity = -s_dot / d;
  r.rod_angular_acceleration = -s_ddot / d - s * s_dot * s_dot / (d * d * d);

  // Newton–Euler. Rod unit vector big end → small end and its second derivative.
  const double th = r.rod_angle, th_dot = r.rod_angular_velocity,
               th_ddot = r.rod_angular_acceleration;
  const Eigen::Vector2d e(-std::sin(th), std::cos(th));
  const Eigen::Vector2d e_ddot = th_ddot * Eigen::Vector2d(-std::cos(th), -std::sin(th)) +
                                 th_dot * th_dot * Eigen::Vector2d(std::sin(th), -std::cos(th));
  const Eigen::Vector2d crank_pin = l1 * Eigen::Vector2d(-std::sin(phi), std::cos(phi));
  const Eigen::Vector2d a_crank_pin =
      l1 * omega * omega * Eigen::Vector2d(std::sin(phi), -std::cos(phi));
  const Eigen::Vector2d a_rod = a_crank_pin + g.rod_com_from_big_end * e_ddot;
  const Eigen::Vector2d up(0.0, 1.0);
  const double m2 = g.rod_mass, m3 = g.piston_mass;
  // Piston, Y: m3 ÿ = P_y − F_gas − m3 g.
  const double pin_y = m3 * (r.piston_acceleration + g.gravity) + gas_force;
  // Rod about its CoM: J2 θ̈ = −L_c e × (m2 a_rod + m2 g ŷ) − L2 e × P  (P = rod on piston).
  const Eigen::Vector2d rod_inertial = m2 * (a_rod + g.gravity * up);
  const double pin_x = (g.rod_inertia * th_ddot + g.rod_com_from_big_end * Cross(e, rod_inertial) +
                        l2 * e.x() * pin_y) /
                       (l2 * e.y());
  r.pin_force = {pin_x, pin_y};
  // Rod translation: m2 a_rod = B − P − m2 g ŷ.
  r.big_end_force = rod_inertial + r.pin_force;
  // Piston, X (no lateral acceleration): 0 = P_x + N.
  r.liner_force_x = -pin_x;
  // Piston moments about the pin: (G3 − pin) × m3 (a + g ŷ) = M_L + (axis − pin) × (0, −F_gas).
  r.liner_moment_about_pin =
      (g.piston_com_lateral_offset - g.pin_offset) * m3 * (r.piston_acceleration + g.gravity) -
      g.pin_offset * gas_force;
  // Crank about the main journal (constant speed): 0 = T + B × (−B_f) + G1 × (−m1 g ŷ).
  const Eigen::Vector2d crank_com =
      g.crank_com_radius * Eigen::Vector2d(-std::sin(phi), std::cos(phi));
  r.crank_torque = Cross(crank_pin, r.big_end_force) + g.crank_mass * g.gravity * crank_com.x();
  return r;
}

double Stroke(const CrankTrainGeometry& g) {
  const double e2 = g.pin_offset * g.pin_offset;
  return std::sqrt((g.rod_length + g.crank_radius) * (g.rod_length + g.crank_radius) - e2) -
         std::sqrt((g.rod_length - g.crank_radius) * (g.rod_length - g.crank_radius) - e2);
}

double SweptVolume(const CrankTrainGeometry& g) {
  return std::numbers::pi * g.liner_radius * g.liner_radius * Stroke(g);
}

}  // namespace filmdyn::engine
