#include "compose/moving_as_one.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "compose/frame_text.hpp"
#include "text/number_format.hpp"
#include "text/wording.hpp"

namespace collide::compose {
namespace {

// Velocities this close (relative to the speed scale) are one motion: stuck partners share theirs
// exactly up to round-off.
constexpr double kSameVelocity = 1e-9;

int root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The name before " = " of a label such as "v₂′ = +1.98 m/s".
std::string nameOf(const std::string& label) {
  return label.substr(0, label.find(" = "));
}

// A rider much smaller than its host sits inside it, like a bullet embedded in a block: at the
// host's mid-height, its trailing end one half-length in from the face it entered by.
void embed(frame::BodyModel& rider, const frame::BodyModel& host) {
  const core::Vec2& r = rider.half_extent_m;
  const core::Vec2& h = host.half_extent_m;
  if (rider.shape != frame::BodyShape::kRectangle || host.shape != frame::BodyShape::kRectangle)
    return;
  if (!(3.0 * r.x() < h.x() && r.y() < h.y())) return;
  const double side = rider.center_m.x() < host.center_m.x() ? -1.0 : 1.0;
  rider.center_m.x() = host.center_m.x() + side * (h.x() - 2.0 * r.x());
  rider.center_m.y() = host.center_m.y();
}

}  // namespace

void showMovingAsOne(frame::PanelModel& panel, const std::vector<double>& masses_kg,
                     bool full_labels) {
  const int n = static_cast<int>(panel.bodies.size());
  if (panel.bonds.empty() || static_cast<int>(masses_kg.size()) != n) return;
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const frame::BondModel& bond : panel.bonds) {
    if (bond.body_a < 0 || bond.body_b < 0 || bond.body_a >= n || bond.body_b >= n) continue;
    parent[root(parent, bond.body_a)] = root(parent, bond.body_b);
  }
  std::vector<std::vector<int>> clusters(n);
  for (int i = 0; i < n; ++i) clusters[root(parent, i)].push_back(i);

  for (const std::vector<int>& members : clusters) {
    if (members.size() < 2) continue;
    // The heaviest member (the first of equals) speaks for the cluster.
    const int host = *std::max_element(members.begin(), members.end(),
                                       [&](int a, int b) { return masses_kg[a] < masses_kg[b]; });
    const core::Vec2 v = panel.bodies[host].velocity_mps;
    bool together = true;
    for (int i : members) {
      const double scale = std::max({1.0, v.norm(), panel.bodies[i].velocity_mps.norm()});
      together = together && (panel.bodies[i].velocity_mps - v).norm() <= kSameVelocity * scale;
    }
    if (!together) continue;
    double mass_kg = 0.0;
    std::string mass_names, velocity_names;
    for (int i : members) {  // in body order
      mass_kg += masses_kg[i];
      mass_names +=
          (mass_names.empty() ? "" : " + ") + text::symbol(text::Symbol::kMass) + subscript(i + 1);
      if (!panel.bodies[i].velocity_label.empty()) {
        velocity_names += nameOf(panel.bodies[i].velocity_label) + " = ";
      }
    }
    frame::BodyModel& body = panel.bodies[host];
    if (full_labels) body.label = mass_names + " = " + text::formatValue(mass_kg, "kg");
    if (!body.velocity_label.empty()) {
      const std::size_t value = body.velocity_label.find(" = ");
      if (value != std::string::npos) {
        body.velocity_label = velocity_names + body.velocity_label.substr(value + 3);
      }
    }
    for (int i : members) {
      if (i == host) continue;
      frame::BodyModel& rider = panel.bodies[i];
      rider.moves_with = host;
      rider.label.clear();
      rider.velocity_label.clear();
      embed(rider, body);
    }
    // Their bond would be a bar across one body.
    std::erase_if(panel.bonds, [&](const frame::BondModel& bond) {
      return bond.body_a >= 0 && bond.body_a < n && root(parent, bond.body_a) == root(parent, host);
    });
  }
}

}  // namespace collide::compose
