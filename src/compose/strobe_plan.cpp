#include "compose/strobe_plan.hpp"

#include <algorithm>
#include <cmath>

namespace collide::compose {
namespace {

constexpr double kStrobeFirstAlpha = 0.18;  // opacity of the earliest strobe image
constexpr double kStrobeRates_hz[] = {50.0, 40.0, 25.0, 20.0, 10.0, 8.0,  5.0,
                                      4.0,  2.5,  2.0,  1.0,  0.5,  0.25, 0.1};

// Two images of one body overlap, unless it has not moved (they stack into one image).
bool imagesOverlap(const render::BodyModel& a, const render::BodyModel& b) {
  const core::Vec2 d = (b.center_m - a.center_m).cwiseAbs();
  const core::Vec2 size = a.half_extent_m + b.half_extent_m;
  if (d.norm() <= 1e-6 * size.norm()) return false;
  if (a.shape == render::BodyShape::kDisk) return d.norm() < size.x() * (1.0 - 1e-9);
  return d.x() < size.x() * (1.0 - 1e-9) && d.y() < size.y() * (1.0 - 1e-9);
}

std::vector<render::BodyModel> imagesAt(const StrobeSubject& panel, double t_s) {
  return bodyImages(panel.scene, panel.timeline, panel.plan, panel.theme, t_s);
}

}  // namespace

int strobeImageCount(double duration_s, double rate_hz) {
  return static_cast<int>(std::floor(duration_s * rate_hz + 1e-9)) + 1;
}

double chooseStrobeRate_hz(const std::vector<StrobeSubject>& panels, double duration_s) {
  const auto apart = [&](double rate_hz) {
    for (const StrobeSubject& panel : panels) {
      std::vector<render::BodyModel> last = imagesAt(panel, 0.0);
      for (int k = 1; k < strobeImageCount(duration_s, rate_hz); ++k) {
        std::vector<render::BodyModel> next = imagesAt(panel, k / rate_hz);
        for (std::size_t i = 0; i < next.size(); ++i) {
          if (imagesOverlap(last[i], next[i])) return false;
        }
        last = std::move(next);
      }
    }
    return true;
  };
  double enough = 0.0;  // the slowest rate seen that still gives kMinStrobeImages
  for (double rate : kStrobeRates_hz) {
    const int images = strobeImageCount(duration_s, rate);
    if (images > kMaxStrobeImages) continue;
    if (images < kMinStrobeImages) break;
    enough = rate;
    if (apart(rate)) return rate;
  }
  return enough > 0.0 ? enough : kStrobeRates_hz[0];
}

std::vector<render::BodyModel> strobeGhosts(const StrobeSubject& panel, double duration_s,
                                            double rate_hz) {
  const int images = std::min(kMaxStrobeImages, strobeImageCount(duration_s, rate_hz));
  std::vector<render::BodyModel> ghosts;
  for (int k = 0; k + 1 < images; ++k) {
    const double alpha =
        kStrobeFirstAlpha + (1.0 - kStrobeFirstAlpha) * k / std::max(1, images - 1);
    for (render::BodyModel body : imagesAt(panel, k / rate_hz)) {
      body.fill.a *= static_cast<float>(alpha);
      ghosts.push_back(body);
    }
  }
  return ghosts;
}

}  // namespace collide::compose
