// Checks across a scene whose values are each valid: no two bodies overlap at t = 0, every body is
// on the free side of every wall and inside the box, and 1D walls know which side is free.
#include <algorithm>
#include <cmath>

#include "scene/reader_parts.hpp"

namespace collide::scene::detail {
namespace {

constexpr int kMaxReported = 5;  // overlaps listed before the rest are summarised

// Half the extent of a body along a line: half a block's width, a disk's radius.
double halfExtent(const BodyDesc& body) {
  return body.shape == "disk" ? body.size_m : 0.5 * body.size_m;
}

// Touching is allowed; rounding in a hand-written position must not count as overlap.
double tolerance(double length_m) {
  return 1e-9 * std::max(1.0, std::abs(length_m));
}

class LayoutChecker {
 public:
  LayoutChecker(SceneDesc& scene, const LayoutNodes& nodes, const Origins& origins,
                Problems& problems)
      : scene_(scene), nodes_(nodes), origins_(origins), problems_(problems) {}

  void run() {
    checkOverlaps();
    for (std::size_t w = 0; w < scene_.walls.size(); ++w) checkWall(w);
    if (scene_.box) checkBox();
    for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
      if (scene_.bodies[i].pivot_m) checkString(i);
    }
  }

 private:
  void add(std::size_t body, const std::string& message) {
    const toml::node* at = nodes_.body_position[body];
    problems_.add(origins_.where(at) + ": body." + std::to_string(body + 1) +
                      ".position: " + valueText(*at) + ": " + message,
                  message);
  }

  std::string bodyName(std::size_t i) const {
    return "body " + std::to_string(i + 1) + " ('" + scene_.bodies[i].name + "')";
  }

  void checkOverlaps() {
    const std::vector<BodyDesc>& bodies = scene_.bodies;
    int reported = 0;
    // Sorted by left edge, a body can only overlap those that start before its right edge.
    std::vector<std::size_t> order(bodies.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const auto left = [&](std::size_t i) {
      return bodies[i].position_m.x() - halfExtent(bodies[i]);
    };
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return left(a) < left(b); });
    for (std::size_t p = 0; p < order.size() && reported < kMaxReported; ++p) {
      const std::size_t i = order[p];
      const double right = bodies[i].position_m.x() + halfExtent(bodies[i]);
      for (std::size_t q = p + 1; q < order.size() && left(order[q]) < right; ++q) {
        const std::size_t j = order[q];
        const double reach = halfExtent(bodies[i]) + halfExtent(bodies[j]);
        const double distance = scene_.dimensions == 1
                                    ? std::abs(bodies[j].position_m.x() - bodies[i].position_m.x())
                                    : (bodies[j].position_m - bodies[i].position_m).norm();
        if (distance >= reach - tolerance(reach)) continue;
        const std::size_t first = std::min(i, j), second = std::max(i, j);
        add(second, "overlaps " + bodyName(first) + " at t = 0 by " +
                        plainNumber(reach - distance) +
                        " m; allowed: bodies apart or touching "
                        "(centres at least " +
                        plainNumber(reach) + " m apart)");
        if (++reported == kMaxReported) break;
      }
    }
  }

  void checkWall(std::size_t w) {
    WallDesc& wall = scene_.walls[w];
    const std::vector<BodyDesc>& bodies = scene_.bodies;
    const std::string label = "wall " + std::to_string(w + 1) + " ('" + wall.name + "')";
    if (scene_.dimensions == 1 && !nodes_.wall_normal_given[w]) {
      // The free side is where the bodies are; they must all be on one side.
      bool any_left = false, any_right = false;
      for (const BodyDesc& body : bodies) {
        (body.position_m.x() < wall.position_m.x() ? any_left : any_right) = true;
      }
      if (any_left && any_right) {
        problems_.add(origins_.where(nodes_.wall_table[w]) + ": wall." + std::to_string(w + 1) +
                      ".normal: (missing): bodies on both sides of " + label +
                      "; allowed: normal = 1 (free side to the right) or -1 (to the left)");
        return;
      }
      wall.normal = {any_left ? -1.0 : 1.0, 0.0};
    }
    int reported = 0;
    for (std::size_t i = 0; i < bodies.size() && reported < kMaxReported; ++i) {
      const double clearance = (bodies[i].position_m - wall.position_m).dot(wall.normal);
      const double reach = halfExtent(bodies[i]);
      if (clearance >= reach - tolerance(reach)) continue;
      add(i, "behind or inside " + label + " at t = 0; allowed: the centre at least " +
                 plainNumber(reach) + " m on the free side of the wall");
      ++reported;
    }
  }

  // A body on a string: gravity pulls down, the pivot is outside every body and on the free
  // side of every wall (else the string would pass through the wall at t = 0).
  void checkString(std::size_t i) {
    const toml::node* at = nodes_.body_table[i];
    if (const toml::table* table = at->as_table(); table != nullptr && table->get("pivot")) {
      at = table->get("pivot");
    }
    const auto pivotProblem = [&](const std::string& message) {
      problems_.add(origins_.where(at) + ": body." + std::to_string(i + 1) +
                    ".pivot: " + valueText(*at) + ": " + message);
    };
    const core::Vec2 pivot = *scene_.bodies[i].pivot_m;
    const core::Vec2 g = scene_.gravity_mps2;
    if (!(g.x() == 0.0 && g.y() < 0.0)) {
      pivotProblem("a string needs gravity pulling down, and gravity is " + plainNumber(g.x()) +
                   ", " + plainNumber(g.y()) +
                   " m/s^2; allowed: with gravity = [0, -g], g > 0 (e.g. [0, -9.81])");
    }
    for (std::size_t j = 0; j < scene_.bodies.size(); ++j) {
      const BodyDesc& other = scene_.bodies[j];
      const double reach = halfExtent(other);
      if ((pivot - other.position_m).norm() > reach + tolerance(reach)) continue;
      pivotProblem(j == i ? "inside the body it holds (radius " + plainNumber(reach) +
                                " m); allowed: a pivot farther than the radius from its centre"
                          : "on " + bodyName(j) + "; allowed: a pivot clear of every body");
      return;
    }
    const std::vector<WallDesc> walls = allWalls(scene_);
    for (const WallDesc& wall : walls) {
      if ((pivot - wall.position_m).dot(wall.normal) >= -tolerance(pivot.norm())) continue;
      pivotProblem("the string of " + bodyName(i) + " crosses wall '" + wall.name +
                   "' at t = 0 (the pivot is behind it); allowed: a pivot on the free side of "
                   "every wall");
      return;
    }
  }

  void checkBox() {
    const BoxDesc& box = *scene_.box;
    int reported = 0;
    for (std::size_t i = 0; i < scene_.bodies.size() && reported < kMaxReported; ++i) {
      const BodyDesc& body = scene_.bodies[i];
      const double reach = halfExtent(body) - tolerance(body.size_m);
      bool inside = body.position_m.x() - reach >= box.min_m.x() &&
                    body.position_m.x() + reach <= box.max_m.x();
      if (scene_.dimensions == 2) {
        inside = inside && body.position_m.y() - reach >= box.min_m.y() &&
                 body.position_m.y() + reach <= box.max_m.y();
      }
      if (inside) continue;
      add(i, "not inside the box at t = 0; allowed: the whole body between box.min and box.max");
      ++reported;
    }
  }

  SceneDesc& scene_;
  const LayoutNodes& nodes_;
  const Origins& origins_;
  Problems& problems_;
};

}  // namespace

void checkLayout(SceneDesc& scene, const LayoutNodes& nodes, const Origins& origins,
                 Problems& problems) {
  LayoutChecker(scene, nodes, origins, problems).run();
}

}  // namespace collide::scene::detail
