#include "physics/soft_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

namespace collide::physics::detail {

namespace {

struct Phase {
  double s, w;  // overlap (m) and its rate (m/s)
};

constexpr int kStepsPerContact = 400;
constexpr double kDimensionlessDuration = 3.141592653589793;  // X'' = -X lasts pi

}  // namespace

double ContactLaw::force_N(double s_m, double w_mps) const {
  if (s_m <= 0.0) return 0.0;
  return stiffness * std::pow(s_m, exponent) * std::max(0.0, 1.0 + damping_per_mps * w_mps);
}

ContactLaw huntCrossleyFor(double m_eff_kg, double u_mps, double e, double duration_s) {
  constexpr double kExponent = 1.0;
  // The dimensionless contact X'' = -X^n (1 + d X'), X(0) = 0, X'(0) = 1: its restitution falls
  // from 1 at d = 0 as d grows. Bisection on d for the requested e, remembered per e (a bouncing
  // ball asks for the same e at every bounce); the result depends on e alone.
  struct Dimensionless {
    double damping = 0.0;   // d
    double duration = 0.0;  // of the contact, in units of 1 / omega
  };
  thread_local std::map<double, Dimensionless> solved;
  // Integrated with the step the real contact will take (its duration over 400), so the real
  // contact repeats these steps scaled and meets e to round-off: a first pass finds the duration
  // with a nominal step, a second the damping with that duration's step.
  double step_duration = kDimensionlessDuration;
  auto contact = [&](double d) {
    const ContactLaw unit{1.0, kExponent, d};
    return integrateSoftContact(1.0, 1.0, 0.0, unit, step_duration);
  };
  auto bisect = [&] {
    double low = 0.0, high = 1.0;
    while (high < 1e6 && contact(high).separation_speed_mps > e) high *= 2.0;
    for (int iteration = 0; iteration < 48 && e < 1.0; ++iteration) {
      const double mid = 0.5 * (low + high);
      (contact(mid).separation_speed_mps > e ? low : high) = mid;
    }
    return e < 1.0 ? 0.5 * (low + high) : 0.0;
  };
  auto found = solved.find(e);
  if (found == solved.end()) {
    step_duration = contact(bisect()).duration_s;
    const double d = bisect();
    found = solved.emplace(e, Dimensionless{d, contact(d).duration_s}).first;
  }
  // Time scale: t = tau / omega, overlap scale u / omega, with omega^(n+1) = (k / m) u^(n-1).
  const double omega = found->second.duration / duration_s;
  ContactLaw law;
  law.exponent = kExponent;
  law.stiffness = m_eff_kg * std::pow(omega, kExponent + 1.0) / std::pow(u_mps, kExponent - 1.0);
  law.damping_per_mps = found->second.damping / u_mps;
  return law;
}

SoftContactPath integrateSoftContact(double m_eff_kg, double closing_speed_mps, double a_push_mps2,
                                     const ContactLaw& law, double duration_s) {
  auto accel = [&](const Phase& p) { return -law.force_N(p.s, p.w) / m_eff_kg + a_push_mps2; };
  constexpr int kMaxSteps = 50 * kStepsPerContact;  // a contact that never ends is reported
  const double h = duration_s / kStepsPerContact;

  SoftContactPath path;
  Phase p{0.0, closing_speed_mps};
  auto record = [&](double t, const Phase& q) {
    path.time_s.push_back(t);
    path.overlap_m.push_back(q.s);
    path.overlap_rate_mps.push_back(q.w);
    path.force_N.push_back(law.force_N(q.s, q.w));
  };
  record(0.0, p);
  for (int step = 1; step <= kMaxSteps; ++step) {
    // Classical RK4 on (s, w).
    const Phase k1{p.w, accel(p)};
    const Phase p2{p.s + 0.5 * h * k1.s, p.w + 0.5 * h * k1.w};
    const Phase k2{p2.w, accel(p2)};
    const Phase p3{p.s + 0.5 * h * k2.s, p.w + 0.5 * h * k2.w};
    const Phase k3{p3.w, accel(p3)};
    const Phase p4{p.s + h * k3.s, p.w + h * k3.w};
    const Phase k4{p4.w, accel(p4)};
    const Phase next{p.s + h / 6.0 * (k1.s + 2 * k2.s + 2 * k3.s + k4.s),
                     p.w + h / 6.0 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w)};
    if (next.s <= 0.0 && next.w < 0.0) {
      // The overlap returned to zero inside this step: find the crossing on the cubic Hermite
      // interpolant of s (exact to the order of the integrator) by bisection.
      auto hermite = [&](double x, double& s, double& w) {
        const double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
        const double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
        s = h00 * p.s + h10 * h * p.w + h01 * next.s + h11 * h * next.w;
        const double d00 = 6 * x * x - 6 * x, d10 = 3 * x * x - 4 * x + 1;
        const double d01 = -6 * x * x + 6 * x, d11 = 3 * x * x - 2 * x;
        w = (d00 * p.s + d01 * next.s) / h + d10 * p.w + d11 * next.w;
      };
      double lo = 0.0, hi = 1.0, s = 0.0, w = 0.0;
      for (int iteration = 0; iteration < 60; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        hermite(mid, s, w);
        (s > 0.0 ? lo : hi) = mid;
      }
      hermite(hi, s, w);
      const double t_end = (step - 1 + hi) * h;
      record(t_end, Phase{0.0, w});
      path.separated = true;
      path.duration_s = t_end;
      path.separation_speed_mps = -w;
      return path;
    }
    p = next;
    record(step * h, p);
  }
  return path;
}

std::string softMismatchMessage(const SoftContact& record) {
  char text[256];
  std::snprintf(text, sizeof text,
                "soft contact of collision %lld: measured e %.4g (requested %.4g), energy lost "
                "%.4g J (requested %.4g J) differ by more than 1%%",
                static_cast<long long>(record.collision_index), record.restitution_measured,
                record.restitution_requested, record.energy_lost_measured_J,
                record.energy_lost_requested_J);
  return text;
}

SoftOutcome resolveSoftContact(const SoftSide& a, const SoftSide& b, const core::Vec2& n, double e,
                               double contact_duration_s, double t_s) {
  SoftOutcome out;
  const double inv_sum = a.inverse_mass_per_kg + b.inverse_mass_per_kg;
  const double m_eff = 1.0 / inv_sum;
  const double u = (a.v_mps - b.v_mps).dot(n);         // closing speed
  const double a_push = (a.a_mps2 - b.a_mps2).dot(n);  // closing acceleration
  const ContactLaw law = huntCrossleyFor(m_eff, u, e, contact_duration_s);
  const SoftContactPath path = integrateSoftContact(m_eff, u, a_push, law, contact_duration_s);
  if (!path.separated) return out;
  out.resolved = true;
  out.duration_s = path.duration_s;
  const double share_a = a.inverse_mass_per_kg * m_eff, share_b = b.inverse_mass_per_kg * m_eff;
  auto stateAt = [&](std::size_t k, core::Vec2& xa, core::Vec2& va, core::Vec2& xb,
                     core::Vec2& vb) {
    const double tau = path.time_s[k];
    // Approach lost to the spring so far: free closing travel minus the overlap.
    const double lost = u * tau + 0.5 * a_push * tau * tau - path.overlap_m[k];
    const double lost_rate = u + a_push * tau - path.overlap_rate_mps[k];
    xa = a.x_m + a.v_mps * tau + 0.5 * a.a_mps2 * tau * tau - share_a * lost * n;
    va = a.v_mps + a.a_mps2 * tau - share_a * lost_rate * n;
    xb = b.x_m + b.v_mps * tau + 0.5 * b.a_mps2 * tau * tau + share_b * lost * n;
    vb = b.v_mps + b.a_mps2 * tau + share_b * lost_rate * n;
  };
  if (share_a > 0.0) out.track_a = std::make_shared<Track>();
  if (share_b > 0.0) out.track_b = std::make_shared<Track>();
  SoftContact& record = out.record;
  for (std::size_t k = 0; k < path.time_s.size(); ++k) {
    core::Vec2 xa, va, xb, vb;
    stateAt(k, xa, va, xb, vb);
    const double t = t_s + path.time_s[k];
    if (out.track_a) {
      out.track_a->time_s.push_back(t);
      out.track_a->position_m.push_back(xa);
      out.track_a->velocity_mps.push_back(va);
    }
    if (out.track_b) {
      out.track_b->time_s.push_back(t);
      out.track_b->position_m.push_back(xb);
      out.track_b->velocity_mps.push_back(vb);
    }
    record.samples.push_back({t, path.force_N[k], path.overlap_m[k], path.overlap_rate_mps[k]});
    out.x_a_m = xa, out.v_a_mps = va, out.x_b_m = xb, out.v_b_mps = vb;
  }
  record.start_s = t_s;
  record.end_s = t_s + path.duration_s;
  record.stiffness = law.stiffness;
  record.exponent = law.exponent;
  record.damping_per_mps = law.damping_per_mps;
  record.restitution_requested = e;
  record.restitution_measured = path.separation_speed_mps / u;
  record.energy_lost_requested_J = 0.5 * m_eff * (1.0 - e * e) * u * u;
  // Measured: mechanical energy (kinetic plus the potential of each side's own acceleration)
  // before minus after, for the movable sides.
  double lost = 0.0;
  auto side = [&](const SoftSide& s, const core::Vec2& x1, const core::Vec2& v1) {
    if (s.inverse_mass_per_kg == 0.0) return;
    const double m = 1.0 / s.inverse_mass_per_kg;
    lost += 0.5 * m * (s.v_mps - v1).dot(s.v_mps + v1) + m * s.a_mps2.dot(x1 - s.x_m);
  };
  side(a, out.x_a_m, out.v_a_mps);
  side(b, out.x_b_m, out.v_b_mps);
  record.energy_lost_measured_J = lost;
  const double scale = 0.5 * m_eff * u * u;
  const bool e_ok = std::abs(record.restitution_measured - e) <= 0.01 * e;
  const bool loss_ok = std::abs(lost - record.energy_lost_requested_J) <=
                       0.01 * std::max(record.energy_lost_requested_J, 0.01 * scale);
  out.within_tolerance = e_ok && loss_ok;
  return out;
}

void fileSoftContact(const Recorder& out, SoftOutcome& soft, std::int64_t index, int body_a,
                     int body_b, double t_s) {
  soft.record.collision_index = index;
  soft.record.body_a = body_a;
  soft.record.body_b = body_b;
  if (!soft.within_tolerance) {
    out.warn({WarningKind::kSoftContactMismatch, index, t_s, softMismatchMessage(soft.record)});
  }
  out.fileSoft(soft.record);
}

}  // namespace collide::physics::detail
