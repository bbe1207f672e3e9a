// The ideal-gas preset: a few hundred equal disks in a box, elastic everywhere. Collisions
// exchange energy between disks until their speeds follow the two-dimensional Maxwell-Boltzmann
// distribution, shown beside the box as a histogram (chart "speed").
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "scene/preset_builders.hpp"
#include "text/translate.hpp"

namespace collide::scene::detail {
namespace {

constexpr double kBoxHalfWidthM = 0.6, kBoxHalfHeightM = 0.45;
constexpr double kDiskRadiusM = 0.012;  // 300 disks cover 12 % of the box
constexpr double kDiskMassKg = 0.01;
constexpr double kTopSpeedMps = 2.0;   // initial speeds spread evenly over [0, 2] m/s
constexpr std::uint64_t kSeed = 1859;  // Maxwell's paper on the distribution of velocities

}  // namespace

// Disks on a jittered lattice (never overlapping), each with a speed drawn evenly from
// [0, kTopSpeedMps] in a random direction, from a fixed seed: the same scene on every machine.
// Uniform speeds have mean square 4/3 (m/s)^2, so the equilibrium it relaxes to is the Rayleigh
// distribution with sigma^2 = <v^2> / 2 = 2/3 (m/s)^2, peaking at sigma = 0.82 m/s.
SceneDesc idealGas(const Parameters& parameters) {
  const int disks = static_cast<int>(parameters.at("disks"));
  SceneDesc scene;
  scene.name = "ideal-gas";
  scene.title = text::tr("An ideal gas: speeds relax to Maxwell-Boltzmann");
  scene.dimensions = 2;
  scene.duration_s = 10.0;
  scene.restitution = 1.0;
  scene.box = BoxDesc{{-kBoxHalfWidthM, -kBoxHalfHeightM}, {kBoxHalfWidthM, kBoxHalfHeightM}, 1.0};
  // Columns and rows in the box's proportions, enough for every disk.
  int columns = 1, rows = 1;
  while (columns * rows < disks) {
    if (columns * kBoxHalfHeightM <= rows * kBoxHalfWidthM) {
      ++columns;
    } else {
      ++rows;
    }
  }
  const double pitch_x = 2.0 * kBoxHalfWidthM / columns, pitch_y = 2.0 * kBoxHalfHeightM / rows;
  const double jitter_x = 0.45 * pitch_x - kDiskRadiusM, jitter_y = 0.45 * pitch_y - kDiskRadiusM;
  std::mt19937_64 dice(kSeed);
  // Uniform on [0, 1) from the top 53 bits (std::uniform_real_distribution differs between
  // standard libraries).
  auto uniform = [&dice] { return static_cast<double>(dice() >> 11) * 0x1.0p-53; };
  for (int k = 0; k < disks; ++k) {
    const double x = -kBoxHalfWidthM + pitch_x * (k % columns + 0.5);
    const double y = -kBoxHalfHeightM + pitch_y * (k / columns + 0.5);
    const core::Vec2 position{x + jitter_x * (2.0 * uniform() - 1.0),
                              y + jitter_y * (2.0 * uniform() - 1.0)};
    const double speed = kTopSpeedMps * uniform(), angle = 2.0 * std::numbers::pi * uniform();
    scene.bodies.push_back(body(
        text::fill(text::trc("preset body", "disk {number}"), {{"number", std::to_string(k + 1)}}),
        "disk", kDiskMassKg, kDiskRadiusM, position,
        {speed * std::cos(angle), speed * std::sin(angle)}));
  }
  scene.view.chart = true;
  scene.view.chart_quantity = "speed";
  return scene;
}

}  // namespace collide::scene::detail
