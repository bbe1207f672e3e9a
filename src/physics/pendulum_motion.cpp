#include "physics/pendulum_motion.hpp"

#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

#include "physics/toi.hpp"

namespace collide::physics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Incomplete elliptic integral of the first kind F(phi, k) for |phi| <= pi/2; k = 1 is the
// separatrix's limit atanh(sin phi), which Boost refuses.
double ellipticF(double phi_rad, double modulus) {
  if (modulus >= 1.0) return std::atanh(std::sin(phi_rad));
  return boost::math::ellint_1(modulus, phi_rad);
}

double completeK(double modulus) {
  return modulus >= 1.0 ? kInfinity : boost::math::ellint_1(modulus);
}

struct Jacobi {
  double sn, cn, dn;
};

Jacobi jacobi(double modulus, double u) {
  if (modulus >= 1.0) {
    const double sech = 1.0 / std::cosh(u);
    return {std::tanh(u), sech, sech};
  }
  double cn = 0.0, boost_dn = 0.0;
  const double sn = boost::math::jacobi_elliptic(modulus, u, &cn, &boost_dn);
  // Boost 1.74's dn is off near u = K (by 0.4 % at k = 0.5, where sn and cn are exact to
  // 1e-16), so dn comes from dn^2 = k'^2 + k^2 cn^2, a sum of two non-negative terms.
  const double complement_sq = (1.0 - modulus) * (1.0 + modulus);
  return {sn, cn, std::sqrt(complement_sq + modulus * modulus * cn * cn)};
}

}  // namespace

PendulumArc::PendulumArc(double length_m, double gravity_m_s2, PendulumState start)
    : length_m_(length_m),
      gravity_m_s2_(gravity_m_s2),
      omega0_rad_s_(std::sqrt(gravity_m_s2 / length_m)),
      start_(start) {
  assert(length_m > 0.0 && gravity_m_s2 > 0.0 && "PendulumArc: length and gravity must be > 0");
  const double half_sin = std::sin(0.5 * start.angle_rad);
  const double speed_term = start.angular_velocity_rad_s / (2.0 * omega0_rad_s_);
  h_ = speed_term * speed_term + half_sin * half_sin;
  if (h_ == 0.0 || (h_ >= 1.0 && start.angular_velocity_rad_s == 0.0)) {
    kind_ = PendulumKind::kRest;  // at the bottom at rest, or balanced at the top
    return;
  }
  if (h_ < 1.0) {
    kind_ = PendulumKind::kLibration;
    modulus_ = std::sqrt(h_);
    quarter_ = completeK(modulus_);
    // sin(theta/2) = k sn(u), cos(theta/2) = dn(u), omega = 2 k omega0 cn(u). The start's
    // amplitude angle phi (sn = sin phi) from atan2 stays accurate at the turning points, where
    // an asin of sin(theta/2)/k would lose half the digits.
    const double wrapped = std::remainder(start.angle_rad, 2.0 * kPi);
    turns0_ = start.angle_rad - wrapped;
    const double phi = std::atan2(std::sin(0.5 * wrapped), std::fabs(speed_term));
    phase0_ = ellipticF(phi, modulus_);
    if (start.angular_velocity_rad_s < 0.0) phase0_ = 2.0 * quarter_ - phase0_;  // cn < 0
    return;
  }
  kind_ = PendulumKind::kRotation;
  // theta/2 = am(v) + n pi with v = direction sqrt(h) omega0 t + v0 and modulus 1/sqrt(h):
  // sin(theta/2) = sn(v) (up to the sign of n pi), omega = 2 direction sqrt(h) omega0 dn(v).
  modulus_ = h_ == 1.0 ? 1.0 : 1.0 / std::sqrt(h_);
  quarter_ = completeK(modulus_);
  direction_ = start.angular_velocity_rad_s > 0.0 ? 1.0 : -1.0;
  const double half = 0.5 * start.angle_rad;
  turns0_ = std::round(half / kPi);
  phase0_ = ellipticF(half - turns0_ * kPi, modulus_);
}

PendulumState PendulumArc::at(double t_s) const {
  // The start itself, exactly: a bob let go at rest has angular velocity 0, not the 1e-16 the
  // elliptic functions give back at their starting phase.
  if (t_s == 0.0) return start_;
  switch (kind_) {
    case PendulumKind::kRest:
      return start_;
    case PendulumKind::kLibration: {
      // Reduce the argument by whole periods 4K first, so a hundred swings lose no digits.
      double u = omega0_rad_s_ * t_s + phase0_;
      u -= 4.0 * quarter_ * std::floor(u / (4.0 * quarter_));
      const Jacobi j = jacobi(modulus_, u);
      return {turns0_ + 2.0 * std::atan2(modulus_ * j.sn, j.dn),
              2.0 * modulus_ * omega0_rad_s_ * j.cn};
    }
    case PendulumKind::kRotation: {
      const double rate = std::sqrt(h_) * omega0_rad_s_;
      double v = direction_ * rate * t_s + phase0_;
      double half_turns = turns0_;
      if (std::isfinite(quarter_)) {
        // am(v + 2K) = am(v) + pi: reduce v into [-K, K), where cn >= 0 and am = atan2(sn, cn).
        const double whole = std::floor((v + quarter_) / (2.0 * quarter_));
        v -= 2.0 * quarter_ * whole;
        half_turns += whole;
      }
      const Jacobi j = jacobi(modulus_, v);
      return {2.0 * (std::atan2(j.sn, j.cn) + half_turns * kPi), 2.0 * direction_ * rate * j.dn};
    }
  }
  return start_;
}

double PendulumArc::period_s() const {
  switch (kind_) {
    case PendulumKind::kRest:
      return 2.0 * kPi / omega0_rad_s_;
    case PendulumKind::kLibration:
      return 4.0 * quarter_ / omega0_rad_s_;
    case PendulumKind::kRotation:
      return 2.0 * quarter_ / (std::sqrt(h_) * omega0_rad_s_);
  }
  return kInfinity;
}

double PendulumArc::amplitude_rad() const {
  if (kind_ == PendulumKind::kLibration) return 2.0 * std::asin(modulus_);
  if (kind_ == PendulumKind::kRotation) return kPi;
  return std::fabs(start_.angle_rad);
}

double PendulumArc::tensionPerMass_m_s2(PendulumState state) const {
  return length_m_ * state.angular_velocity_rad_s * state.angular_velocity_rad_s +
         gravity_m_s2_ * std::cos(state.angle_rad);
}

std::optional<double> PendulumArc::slackTime_s() const {
  // Tension / m = g (4 h + 1 - 6 sin^2(theta/2)): it falls as the body rises and reaches zero at
  // sin^2(theta/2) = (4 h + 1) / 6, inside the reachable range only for 1/2 < h < 5/4.
  if (kind_ == PendulumKind::kRest || !(h_ > 0.5 && h_ < 1.25)) return std::nullopt;
  const double slack_half_sin = std::sqrt((4.0 * h_ + 1.0) / 6.0);
  if (kind_ == PendulumKind::kLibration) {
    // |sn(u)| = slack_half_sin / k while |sn| grows: at u = w + 2K n.
    const double w = ellipticF(std::asin(slack_half_sin / modulus_), modulus_);
    const double n = std::floor((phase0_ - w) / (2.0 * quarter_)) + 1.0;
    return (w + 2.0 * quarter_ * n - phase0_) / omega0_rad_s_;
  }
  const double rate = std::sqrt(h_) * omega0_rad_s_;
  const double w = ellipticF(std::asin(slack_half_sin), modulus_);
  if (!std::isfinite(quarter_)) {  // the separatrix: it passes the slack angle at most once
    const double target = direction_ * w;
    const double dv = direction_ * (target - phase0_);
    if (dv > 0.0) return dv / rate;
    return std::nullopt;
  }
  // Rising means |sn(v)| growing as v moves in the direction of travel.
  if (direction_ > 0.0) {
    const double n = std::floor((phase0_ - w) / (2.0 * quarter_)) + 1.0;
    return (w + 2.0 * quarter_ * n - phase0_) / rate;
  }
  const double n = std::ceil((phase0_ + w) / (2.0 * quarter_)) - 1.0;
  return (phase0_ - (-w + 2.0 * quarter_ * n)) / rate;
}

core::Vec2 pendulumPosition_m(double length_m, double angle_rad) {
  return {length_m * std::sin(angle_rad), -length_m * std::cos(angle_rad)};
}

core::Vec2 pendulumVelocity_m_s(double length_m, PendulumState state) {
  const double speed = length_m * state.angular_velocity_rad_s;
  // + 0.0 turns a -0 (a bob at rest on the left) into 0, so data shows a bob at rest as 0.
  return {speed * std::cos(state.angle_rad) + 0.0, speed * std::sin(state.angle_rad) + 0.0};
}

PendulumState pendulumStateOf(core::Vec2 offset_m, core::Vec2 velocity_m_s) {
  const double cross = offset_m.x() * velocity_m_s.y() - offset_m.y() * velocity_m_s.x();
  return {std::atan2(offset_m.x(), -offset_m.y()), cross / offset_m.squaredNorm()};
}

std::optional<double> tautTime_s(double length_m, double gravity_m_s2, core::Vec2 offset_m,
                                 core::Vec2 velocity_m_s) {
  // |r(t)|^2 - L^2 = f0 + f1 t + f2 t^2 + f3 t^3 + f4 t^4 for r(t) = r0 + v0 t - g t^2 / 2 y.
  const core::Vec2 accel{0.0, -gravity_m_s2};
  const double speed = velocity_m_s.norm();
  double f[5] = {offset_m.squaredNorm() - length_m * length_m, 2.0 * offset_m.dot(velocity_m_s),
                 velocity_m_s.squaredNorm() + offset_m.dot(accel), velocity_m_s.dot(accel),
                 0.25 * gravity_m_s2 * gravity_m_s2};
  // Starting on the circle, t = 0 is a root; divide it out as often as the motion there allows,
  // so the first root found is the return, not the start (round-off would make spurious roots
  // within nanoseconds of it). Tolerances scale with the terms they compare.
  const double tol = 1e-12;
  int skip = 0;
  if (std::fabs(f[0]) <= tol * length_m * length_m) {
    skip = 1;
    if (f[1] > tol * 2.0 * length_m * speed) return 0.0;  // moving outwards: taut at once
    if (f[1] >= -tol * 2.0 * length_m * speed) {
      skip = 2;
      const double scale = speed * speed + gravity_m_s2 * length_m;
      if (f[2] > tol * scale) return 0.0;  // the string would pull at once
      if (f[2] >= -tol * scale) {
        // Zero tension and no radial velocity: where a swing goes slack. The flight returns to
        // the circle at t = -f3 / f4 = 4 v0y / g.
        if (!(velocity_m_s.y() > 0.0)) return 0.0;
        return 4.0 * velocity_m_s.y() / gravity_m_s2;
      }
    }
  } else if (f[0] > 0.0) {
    return 0.0;  // outside the circle: the string is taut already
  }
  // Gap L^2 - |r|^2 (divided by t^skip) is positive now; its first fall to zero is the answer.
  double gap[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
  const int degree = 4 - skip;
  for (int k = 0; k <= degree; ++k) gap[k] = -f[k + skip];
  // Beyond t_max the fall g t^2 / 2 alone has carried the body out of the circle.
  const double t_max =
      1.5 * (speed + std::sqrt(speed * speed + 4.0 * gravity_m_s2 * length_m)) / gravity_m_s2;
  const double t = detail::firstClosingRootPoly(gap, degree, t_max);
  if (!std::isfinite(t)) return std::nullopt;
  return t;
}

StringJerk stringJerk(core::Vec2 offset_m, core::Vec2 velocity_m_s, double restitution) {
  const core::Vec2 outward = offset_m.normalized();
  const double radial = velocity_m_s.dot(outward);
  if (radial <= 0.0) return {velocity_m_s, 0.0};  // not pulling on the string
  return {velocity_m_s - (1.0 + restitution) * radial * outward,
          0.5 * (1.0 - restitution * restitution) * radial * radial};
}

}  // namespace collide::physics
