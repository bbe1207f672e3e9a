#pragma once
// A scene as the user describes it: plain data with units, before any simulation. Presets and
// (later) scene files produce it; the app turns it into a physics world and a view.
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/vec.hpp"

namespace collide::scene {

// Bad scene input (unknown preset, invalid value). Exit 2.
class SceneError : public core::InputError {
 public:
  using core::InputError::InputError;
};

struct Rgb {
  int r = 0, g = 0, b = 0;  // 0..255
};

struct BodyDesc {
  std::string name;
  std::string shape = "block";         // "block" (1D) or "disk" (2D)
  double mass_kg = 1.0;                // > 0
  double size_m = 0.5;                 // block width or disk radius
  core::Vec2 position_m = {0.0, 0.0};  // centre
  core::Vec2 velocity_mps = {0.0, 0.0};
  std::optional<Rgb> color;  // default: the palette colour for its index
};

struct WallDesc {
  std::string name;
  core::Vec2 position_m = {0.0, 0.0};
  core::Vec2 normal = {1.0, 0.0};  // points into the free side
  double restitution = 1.0;
};

// How a scene is shown. Defaults give the plain single-panel picture; every field is optional in
// a scene file and can be overridden from the command line.
struct ViewDesc {
  std::string theme = "light";  // "light", "dark" or "high-contrast"
  // Comparison panels: one time-aligned panel per value of `panel_parameter` (e.g. "restitution"
  // with values {1, 0.5, 0}); empty values = a single panel.
  std::string panel_parameter;
  std::vector<double> panel_values;
  bool chart = false;                     // energy-versus-time chart panel beside the animation
  bool momentum_diagram = false;          // 2D: momentum vectors tip to tail with their sum
  bool center_of_mass = false;            // marker at the centre of mass
  double trail_s = 0.0;                   // fading trails this many seconds long; 0 = none
  bool center_of_momentum_frame = false;  // draw in the frame where total momentum is zero
  double slow_motion_factor = 1.0;        // >= 1: playback slowed by this much around collisions
  double strobe_rate_hz = 25.0;           // images per second in `collide strobe`
};

struct SceneDesc {
  std::string name;         // preset or file stem, used in output names
  std::string title;        // shown on frames and in metadata
  int dimensions = 1;       // 1 or 2
  double duration_s = 4.0;  // simulated time, > 0
  core::Vec2 gravity_mps2 = {0.0, 0.0};
  double restitution = 1.0;  // default e for every pair, in [0, 1]
  std::vector<BodyDesc> bodies;
  std::vector<WallDesc> walls;
  ViewDesc view;
};

struct PresetInfo {
  std::string name;
  std::string summary;  // one line for `collide presets`
};

// Every built-in preset, in the order `collide presets` lists them.
const std::vector<PresetInfo>& presetList();

// The preset's scene. Throws SceneError naming the unknown name, with near matches, if none.
SceneDesc loadPreset(const std::string& name);

}  // namespace collide::scene
