#include "physics/energy_books.hpp"

#include <algorithm>
#include <cmath>

namespace collide::physics {
namespace {

// Kinetic plus gravitational energy of the movable partners of a contact, lab frame, J.
double pairEnergy(const Timeline& timeline, const Snapshot& snapshot, int a, int b) {
  const WorldDef& world = timeline.world();
  double energy = 0.0;
  for (int body : {a, b}) {
    if (body < 0) continue;
    const BodyDef& def = world.bodies[static_cast<std::size_t>(body)];
    const BodyState& state = snapshot.bodies[static_cast<std::size_t>(body)];
    energy += bodyKineticEnergy_J(def, state, {0.0, 0.0}) -
              def.mass_kg * world.gravity_mps2.dot(state.position_m);
  }
  return energy;
}

// The overlap at t on the cubic Hermite curve through the recorded overlaps and rates: the curve
// the bodies' positions follow between samples, so the spring agrees with where they are drawn.
double overlapAt(const SoftContact& contact, double t_s) {
  const std::vector<ContactForceSample>& samples = contact.samples;
  auto after = std::upper_bound(samples.begin(), samples.end(), t_s,
                                [](double t, const ContactForceSample& s) { return t < s.time_s; });
  if (after == samples.begin()) return 0.0;
  if (after == samples.end()) return std::max(0.0, samples.back().overlap_m);
  const ContactForceSample &p = *(after - 1), &q = *after;
  const double h = q.time_s - p.time_s;
  const double x = (t_s - p.time_s) / h;
  const double h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x);
  const double h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
  const double s = h00 * p.overlap_m + h10 * h * p.overlap_rate_mps + h01 * q.overlap_m +
                   h11 * h * q.overlap_rate_mps;
  return std::max(0.0, s);
}

}  // namespace

double bodyKineticEnergy_J(const BodyDef& def, const BodyState& state,
                           const core::Vec2& frame_velocity) {
  double energy = 0.5 * def.mass_kg * (state.velocity_mps - frame_velocity).squaredNorm();
  if (def.shape == Shape::kDisk) {
    // A disk turning with a stuck cluster also spins about its own centre: I = m r² / 2.
    const double inertia = 0.5 * def.mass_kg * def.size_m * def.size_m;
    energy += 0.5 * inertia * state.angular_velocity_radps * state.angular_velocity_radps;
    // A rolling ball's spin about the table's axes: I = 2/5 m r^2.
    energy += 0.2 * def.mass_kg * def.size_m * def.size_m * state.spin_radps.squaredNorm();
  }
  return energy;
}

double EnergyBooks::kineticTotal_J() const {
  double sum = 0.0;
  for (double e : kinetic_J) sum += e;
  return sum;
}

double EnergyBooks::springTotal_J() const {
  double sum = 0.0;
  for (const SpringEnergy& spring : springs) sum += spring.energy_J;
  return sum;
}

double EnergyBooks::total_J() const {
  return kineticTotal_J() + gravity_J + springTotal_J() + lost_J + surface_J + air_J + internal_J;
}

EnergyBooks energyBooks(const Timeline& timeline, double t_s, const core::Vec2& frame_velocity_mps,
                        double gravity_floor_J) {
  const Snapshot snapshot = timeline.sample(t_s);
  const WorldDef& world = timeline.world();
  EnergyBooks books;
  books.time_s = snapshot.time_s;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    books.kinetic_J.push_back(
        bodyKineticEnergy_J(world.bodies[i], snapshot.bodies[i], frame_velocity_mps));
  }
  books.gravity_J = world.gravity_mps2.squaredNorm() > 0.0
                        ? timeline.potentialEnergy(snapshot) - gravity_floor_J
                        : 0.0;
  books.lost_J = snapshot.energy_lost_J;
  books.released_J = snapshot.energy_released_J;
  books.surface_J = snapshot.energy_to_surface_J;
  books.air_J = snapshot.energy_to_air_J;
  books.internal_J = snapshot.internal_energy_J;
  const std::vector<CollisionEvent>& events = timeline.collisions();
  for (const SoftContact& contact : timeline.softContacts()) {
    const double t = snapshot.time_s;
    if (t < contact.start_s || t >= contact.end_s) continue;
    // The snapshot booked this contact's whole loss when it began; what has gone so far is what
    // the partners' energy lacks beyond the spring's store.
    const std::size_t index = static_cast<std::size_t>(contact.collision_index);
    const double booked =
        index < events.size() ? events[index].energy_lost_J : contact.energy_lost_measured_J;
    SpringEnergy spring{contact.collision_index, contact.body_a, contact.body_b,
                        overlapAt(contact, t), 0.0};
    spring.energy_J = contact.stiffness * std::pow(spring.overlap_m, contact.exponent + 1.0) /
                      (contact.exponent + 1.0);
    const double before =
        pairEnergy(timeline, timeline.sample(contact.start_s), contact.body_a, contact.body_b);
    const double now = pairEnergy(timeline, snapshot, contact.body_a, contact.body_b);
    const double dissipated = std::clamp(before - now - spring.energy_J, 0.0, booked);
    books.lost_J += dissipated - booked;
    books.springs.push_back(spring);
  }
  return books;
}

}  // namespace collide::physics
