// The 2D engine's broad phase: a uniform grid of cells at least one disk diameter wide, so that
// two disks in contact always sit in the same or neighbouring cells. A disk predicts impacts only
// with the disks of its 3 x 3 block of cells, and its next crossing into another cell is one more
// event (kind kCrossing), kept apart in crossing_queue_, one per disk, replaced in place when the
// disk's crossing is predicted again; the engine takes the earlier of the two queues' first events
// in the one total order of events.
// Each event then costs a few dozen predictions instead of one per body: O(log N) per event for
// the queue, not O(N). See plane_engine.hpp.
//
// The grid's size and origin are a pure function of the world (its initial positions), so a run
// re-simulated from a checkpoint uses the same cells; the outer cells reach to infinity, so a disk
// that leaves the initial extent stays in a cell. Predictions stay pure functions of the unit
// states, so which cell a disk is filed in never changes an event time, only which predictions
// are made, and every contact is among them.
#include <algorithm>
#include <cmath>

#include "physics/plane_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

// Below this many disks one prediction per pair costs less than keeping the grid.
constexpr int kGridMinBodies = 32;
// Cells a little wider than the largest diameter: contact distances stay inside one cell even
// after the rounding of a crossing time.
constexpr double kCellMargin = 1.01;

}  // namespace

void PlaneEngine::setUpGrid() {
  grid_ = false;
  const WorldDef& world = model_.world;
  const int n = static_cast<int>(world.bodies.size());
  // Drag: cells are crossed where the parabola says; drag's motion is no parabola.
  if (n < kGridMinBodies || world.contact_model == ContactModel::kSpringDamper || model_.has_drag) {
    return;
  }
  // Only single, non-spinning disks are filed in cells (a checkpoint may hold clusters).
  for (const UnitState& unit : state_.units) {
    if (unit.alive && unit.omega_radps != 0.0) return;
  }
  for (int id = 0; id < static_cast<int>(members_.size()); ++id) {
    if (state_.units[id].alive && members_[id].size() != 1) return;
  }
  double largest_m = 0.0;
  double lo_x = world.bodies[0].position_m.x(), hi_x = lo_x;
  double lo_y = world.bodies[0].position_m.y(), hi_y = lo_y;
  for (int i = 0; i < n; ++i) {
    largest_m = std::max(largest_m, model_.half_size_m[i]);
    lo_x = std::min(lo_x, world.bodies[i].position_m.x());
    hi_x = std::max(hi_x, world.bodies[i].position_m.x());
    lo_y = std::min(lo_y, world.bodies[i].position_m.y());
    hi_y = std::max(hi_y, world.bodies[i].position_m.y());
  }
  // One diameter, which ran faster per collision than cells of one disk's share of the area or
  // larger (bench/results.md, "Figures behind the code"), but no more than about four cells per
  // disk.
  const double area = std::max((hi_x - lo_x) * (hi_y - lo_y), 0.0);
  cell_m_ = std::max(2.0 * kCellMargin * largest_m, std::sqrt(area / (4.0 * n)));
  if (!(cell_m_ > 0.0) || !std::isfinite(cell_m_)) return;
  origin_x_ = lo_x - cell_m_;
  origin_y_ = lo_y - cell_m_;
  cells_x_ = std::min(4096, static_cast<int>((hi_x - lo_x) / cell_m_) + 3);
  cells_y_ = std::min(4096, static_cast<int>((hi_y - lo_y) / cell_m_) + 3);
  cell_bodies_.assign(static_cast<std::size_t>(cells_x_) * cells_y_, {});
  body_cell_x_.assign(n, 0);
  body_cell_y_.assign(n, 0);
  crossing_s_.assign(n, kNever);
  for (int i = 0; i < n; ++i) {
    const core::Vec2 x = kinematics(i, state_.units[state_.bodies[i].unit].t_ref_s).x;
    body_cell_x_[i] = cellIndex(x.x(), origin_x_, cells_x_);
    body_cell_y_[i] = cellIndex(x.y(), origin_y_, cells_y_);
    cell_bodies_[body_cell_y_[i] * cells_x_ + body_cell_x_[i]].push_back(i);
  }
  fileWallsInCells(largest_m);
  grid_ = true;
}

// Which walls a disk can touch while its centre stays in a cell: those whose distance from the
// cell's nearest point is within the largest radius (and a margin for the rounding of crossing
// times). A wall impact from anywhere else comes after the disk's next crossing, where it is
// predicted again, so leaving it out changes no event, only the predictions made (measured: the
// 500-disk bench predicted four walls for every disk it touched, almost all beyond reach).
void PlaneEngine::fileWallsInCells(double largest_m) {
  const std::vector<WallDef>& walls = model_.world.walls;
  cell_walls_.clear();
  if (walls.size() > 32) return;
  cell_walls_.assign(static_cast<std::size_t>(cells_x_) * cells_y_, 0u);
  const double reach_m = largest_m + 0.01 * cell_m_;
  // The extent of cell k along one axis; the outer cells reach to infinity.
  auto bounds = [&](int k, int cells, double origin, double& lo, double& hi) {
    lo = k == 0 ? -kNever : origin + k * cell_m_;
    hi = k == cells - 1 ? kNever : origin + (k + 1) * cell_m_;
  };
  // Along one axis, the least of normal * (x - point) over [lo, hi].
  auto least = [](double normal, double lo, double hi, double point) {
    if (normal == 0.0) return 0.0;
    return normal * ((normal > 0.0 ? lo : hi) - point);
  };
  for (int cy = 0; cy < cells_y_; ++cy) {
    double y_lo, y_hi;
    bounds(cy, cells_y_, origin_y_, y_lo, y_hi);
    for (int cx = 0; cx < cells_x_; ++cx) {
      double x_lo, x_hi;
      bounds(cx, cells_x_, origin_x_, x_lo, x_hi);
      std::uint32_t mask = 0;
      for (std::size_t w = 0; w < walls.size(); ++w) {
        const WallDef& wall = walls[w];
        const double nearest = least(wall.normal.x(), x_lo, x_hi, wall.point_m.x()) +
                               least(wall.normal.y(), y_lo, y_hi, wall.point_m.y());
        if (!(nearest > reach_m)) mask |= 1u << w;
      }
      cell_walls_[cy * cells_x_ + cx] = mask;
    }
  }
}

int PlaneEngine::cellIndex(double x, double origin, int cells) const {
  const double k = std::floor((x - origin) / cell_m_);
  if (!(k > 0.0)) return 0;
  return k >= cells - 1 ? cells - 1 : static_cast<int>(k);
}

void PlaneEngine::dropGrid() {
  grid_ = false;
  crossing_queue_.clear();
  cell_bodies_.clear();
  cell_walls_.clear();
}

// The first time the disk's centre reaches an inner face of its cell, moving outwards.
void PlaneEngine::predictCrossing(int body) {
  const UnitState& unit = state_.units[state_.bodies[body].unit];
  const core::Vec2 x = unit.x_ref_m;  // single disk: the unit's centre
  const core::Vec2 v = unit.v_mps, a = unit.a_mps2;
  double best = kNever;
  int direction = -1;
  auto consider = [&](double tau, int code) {
    if (tau < best) best = tau, direction = code;
  };
  const int cx = body_cell_x_[body], cy = body_cell_y_[body];
  if (cx + 1 < cells_x_) {
    consider(firstClosingRoot(origin_x_ + (cx + 1) * cell_m_ - x.x(), -v.x(), -0.5 * a.x()), 0);
  }
  if (cx > 0) consider(firstClosingRoot(x.x() - (origin_x_ + cx * cell_m_), v.x(), 0.5 * a.x()), 1);
  if (cy + 1 < cells_y_) {
    consider(firstClosingRoot(origin_y_ + (cy + 1) * cell_m_ - x.y(), -v.y(), -0.5 * a.y()), 2);
  }
  if (cy > 0) consider(firstClosingRoot(x.y() - (origin_y_ + cy * cell_m_), v.y(), 0.5 * a.y()), 3);
  crossing_s_[body] = direction >= 0 ? unit.t_ref_s + best : kNever;
  // Beyond the run's end, as push() leaves out events there.
  if (direction >= 0 && crossing_s_[body] <= model_.world.duration_s) {
    crossing_queue_.set(body, crossing_s_[body], direction);
  } else {
    crossing_queue_.remove(body);
  }
}

void PlaneEngine::crossCell(const Event& event) {
  const int body = event.a;
  std::vector<int>& from = cell_bodies_[body_cell_y_[body] * cells_x_ + body_cell_x_[body]];
  from.erase(std::find(from.begin(), from.end(), body));
  switch (event.b) {
    case 0:
      ++body_cell_x_[body];
      break;
    case 1:
      --body_cell_x_[body];
      break;
    case 2:
      ++body_cell_y_[body];
      break;
    default:
      --body_cell_y_[body];
      break;
  }
  cell_bodies_[body_cell_y_[body] * cells_x_ + body_cell_x_[body]].push_back(body);
  // The disks of its new neighbourhood; pairs it already had are predicted again, to the same
  // times (pure functions of the states), and the copies are dropped when they come due.
  predictCrossing(body);
  const int id = state_.bodies[body].unit;
  forNeighbours(body, [&](int other) {
    if (state_.bodies[other].unit != id) pushPair(body, other);
  });
  pushWalls(body);
}

}  // namespace collide::physics::detail
