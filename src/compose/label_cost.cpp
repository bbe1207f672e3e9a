#include "compose/label_cost.hpp"

#include <algorithm>

namespace collide::compose {
double costAlone(const Label& label, std::size_t at, const std::optional<Leader>& leader,
                 const LabelScene& scene) {
  return costAlone(label, label.candidates[at], label.base_cost[at], leader, scene);
}

double costAlone(const Label& label, const Box& box, double base_cost,
                 const std::optional<Leader>& leader, const LabelScene& scene) {
  const Obstacles& obstacles = scene.obstacles;
  double total = base_cost + kHard * obstacles.hits(box);
  const std::vector<BodyOutline>& bodies = obstacles.bodies();
  // Clearly nearer what it names than anything else it could be read as naming: a mass label its
  // body, a readout its body or arrow (over the middle of a long arrow it may be as near the
  // body the arrow points at).
  const double nearer_by = std::max(1.0, kNearerOwnByLines * label.size.y());
  double own = bodies[label.body].distanceTo(box);
  const auto& arrow = scene.arrows[label.body];
  if (label.velocity && arrow) own = std::min(own, distance(box, arrow->first, arrow->second));
  total +=
      kHard * readAsOthers(box, own, label.body, bodies, scene.moves_with, scene.arrows, nearer_by);
  if (leader) {
    if ((leader->to - leader->from).norm() > kLongestLeaderLines * label.size.y()) total += kHard;
    total += kHard * obstacles.leaderHits(leader->from, leader->to, static_cast<int>(label.body),
                                          leader->to_arrow);
  }
  return total;
}

Leader leaderOf(const Label& label, const Box& box, const LabelScene& scene) {
  const core::Vec2 c = box.center();
  const auto& arrow = scene.arrows[label.body];
  core::Vec2 to;
  const bool to_arrow = label.velocity && arrow.has_value();
  if (to_arrow) {
    const core::Vec2 ab = arrow->second - arrow->first;
    const double t =
        std::clamp((c - arrow->first).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
    to = arrow->first + t * ab;
  } else {
    const BodyOutline& body = scene.obstacles.bodies()[label.body];
    if (body.disk) {
      const core::Vec2 center = body.bounds.center(), toward = c - center;
      to =
          center + 0.5 * (body.bounds.x1 - body.bounds.x0) * toward / std::max(toward.norm(), 1e-9);
    } else {
      to = nearestOnBox(body.bounds, c);
    }
  }
  return {nearestOnBox(box, to), to, to_arrow};
}

// Whether two label boxes of one text size stand on one line too near to read as two.
bool readsAsOneLine(const Box& a, const Box& b, double em_px) {
  const double line = std::max(a.y1 - a.y0, b.y1 - b.y0);
  if (std::abs(a.y1 - b.y1) >= kOneLineBaselineLines * line) return false;
  return std::max(a.x0 - b.x1, b.x0 - a.x1) < kOneLineLeastGapEm * em_px;
}

double shortOfApart(const Box& a, const Box& b, double em_px) {
  const double line = std::max(a.y1 - a.y0, b.y1 - b.y0);
  if (std::abs(a.y1 - b.y1) >= kOneLineBaselineLines * line) return 0.0;
  return std::max(0.0, kApartOnOneLineEm * em_px - std::max(a.x0 - b.x1, b.x0 - a.x1));
}

double cost(const Label& label, int k, const std::vector<Label>& labels, const LabelScene& scene,
            OwnCosts& own, const LineCosts& lines, double stop_at, double added_to) {
  const std::size_t at = static_cast<std::size_t>(k);
  const std::size_t index = static_cast<std::size_t>(&label - labels.data());
  const Box& box = label.candidates[at];
  const Obstacles& obstacles = scene.obstacles;
  own.keepFor(labels, scene);
  const std::optional<Leader>& leader = own.leader(labels, index, at, scene);
  double total = own.cost(index, at, [&] { return costAlone(label, at, leader, scene); });
  for (std::size_t other_index = 0; other_index < labels.size(); ++other_index) {
    // Rounding never makes a sum of terms >= 0 smaller than its part summed so far.
    if (added_to + total >= stop_at) return total;
    const Label& other = labels[other_index];
    if (&other == &label || other.chosen < 0) continue;
    const std::size_t o = static_cast<std::size_t>(other.chosen);
    const Box& other_box = other.candidates[o];
    if (!obstacles.textsApart(box, other_box)) total += kHard;
    if (readsAsOneLine(box, other_box, scene.em_px)) total += lines.one_line;
    // Mass labels only: readouts stand in a row over their arrows, where a row reads as such.
    if (lines.per_px_short > 0.0 && !label.velocity && !other.velocity) {
      total += lines.per_px_short * shortOfApart(box, other_box, scene.em_px);
    }
    // No leader strikes through the other's text, and no two leaders cross.
    const std::optional<Leader>& other_leader = own.leader(labels, other_index, o, scene);
    if (other_leader && nearerThan(box, other_leader->from, other_leader->to, 1.0)) total += kHard;
    if (leader && nearerThan(other_box, leader->from, leader->to, 1.0)) total += kHard;
    if (leader && other_leader &&
        segmentsNearerThan(leader->from, leader->to, other_leader->from, other_leader->to, 1.0)) {
      total += kHard;
    }
  }
  return total;
}

}  // namespace collide::compose
