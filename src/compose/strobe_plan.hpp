#pragma once
// A stroboscope photograph's plan: the rate it flashes at and the images of the bodies it shows.
// FrameSource::strobeFrame draws them; this file decides them.
#include <vector>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "physics/timeline.hpp"
#include "render/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

// One panel's run, as the strobe sees it.
struct StrobeSubject {
  const scene::SceneDesc& scene;
  const physics::Timeline& timeline;
  const FramePlan& plan;
  const Theme& theme;
};

inline constexpr int kMinStrobeImages = 6;
inline constexpr int kMaxStrobeImages = 2000;

// Flashes at t = k / rate_hz over [0, duration_s], the first at t = 0.
int strobeImageCount(double duration_s, double rate_hz);

// The fastest round rate (50, 40, 25, 20, 10, 8, 5, 4, 2.5, 2, 1, 0.5, 0.25 or 0.1 per second) at
// which no body's image overlaps its next one (images of a body at rest stack into one), with at
// least kMinStrobeImages images; else the slowest rate that still gives that many.
double chooseStrobeRate_hz(const std::vector<StrobeSubject>& panels, double duration_s);

// The earlier images (all but the last flash) of one panel, in flash order, earlier ones fainter.
std::vector<render::BodyModel> strobeGhosts(const StrobeSubject& panel, double duration_s,
                                            double rate_hz);

}  // namespace collide::compose
