#pragma once
// A scene as the user describes it: plain data with units, before any simulation. Presets and
// scene files (TOML, docs/scene-format.md) produce it; the app turns it into a physics world and a
// view. Every field has a default; scene/scene_io.hpp validates what a user wrote.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/vec.hpp"

namespace collide::scene {

// Bad scene input (unknown preset, invalid value). Exit 2. The message is the first problem, one
// line; problems() lists every problem found (`collide check` prints a few of each kind).
class SceneError : public core::InputError {
 public:
  using core::InputError::InputError;
  // `kinds`: per problem, what is wrong, alike for problems of one sort (empty: each its own).
  SceneError(const std::string& message, std::vector<std::string> problems,
             std::vector<std::string> kinds = {})
      : core::InputError(message), problems_(std::move(problems)), kinds_(std::move(kinds)) {}
  // Every problem, one line each; just what() when the error was raised on its own.
  std::vector<std::string> problems() const {
    return problems_.empty() ? std::vector<std::string>{what()} : problems_;
  }
  // Per problem of problems(), its kind.
  std::vector<std::string> kinds() const {
    return kinds_.size() == problems_.size() && !kinds_.empty() ? kinds_ : problems();
  }

 private:
  std::vector<std::string> problems_, kinds_;
};

struct Rgb {
  int r = 0, g = 0, b = 0;  // 0..255
  bool operator==(const Rgb&) const = default;
};

struct BodyDesc {
  std::string name;
  // "block" (width size_m), "disk" (radius size_m) or, in 1D, "glider": a block of width size_m
  // whose two ends are spring bumpers (it collides like a block; the bumpers are drawn)
  std::string shape = "block";
  double mass_kg = 1.0;                // > 0
  double size_m = 0.5;                 // block width or disk radius, > 0
  core::Vec2 position_m = {0.0, 0.0};  // centre; y = 0 in 1D
  core::Vec2 velocity_mps = {0.0, 0.0};
  std::optional<Rgb> color;  // default: the palette colour for its index
  // 2D: the body hangs from this fixed point on a massless, inextensible string as long as the
  // distance to its centre (a scene file may give `length` and `angle` instead of `position`).
  std::optional<core::Vec2> pivot_m;
  // With pivot_m, when the body was placed by its string: the string's length and its angle from
  // straight down (degrees, counter-clockwise), so that it is written back as such.
  std::optional<double> string_length_m;
  double string_angle_deg = 0.0;
  // Sliding friction with the surface (1D): kinetic mu, and static mu (default: the kinetic one).
  double friction = 0.0;
  std::optional<double> static_friction;
  // Air drag: linear F = -k v (kg/s) and quadratic F = -c |v| v (kg/m, 1D only).
  double drag_linear_kgps = 0.0;
  double drag_quadratic_kgpm = 0.0;
  // Rolling balls (SceneDesc::rolling): rolling resistance's mu, and how the ball is struck:
  // "follow" (rolling, the default), "stop" (no spin) or "draw" (backspin as large as rolling's).
  double rolling_friction = 0.0;
  std::string spin;  // empty: "follow"
  bool operator==(const BodyDesc&) const = default;
};

struct WallDesc {
  std::string name;
  core::Vec2 position_m = {0.0, 0.0};  // any point on the wall (1D: x only)
  core::Vec2 normal = {1.0, 0.0};      // unit, points into the free side (1D: (+-1, 0))
  std::optional<double> restitution;   // e in [0, 1]; default: the scene's restitution
  bool operator==(const WallDesc&) const = default;
};

// An enclosing box: four walls in 2D (left, right, bottom, top), two in 1D (left, right).
struct BoxDesc {
  core::Vec2 min_m = {0.0, 0.0};      // lower-left corner (1D: left end, y unused)
  core::Vec2 max_m = {1.0, 1.0};      // upper-right corner (1D: right end, y unused)
  std::optional<double> restitution;  // e of its walls; default: the scene's restitution
  bool operator==(const BoxDesc&) const = default;
};

// e for one pair of bodies, overriding SceneDesc::restitution.
struct PairDesc {
  int body_a = 0;            // 0-based index into SceneDesc::bodies
  int body_b = 1;            // 0-based, != body_a
  double restitution = 1.0;  // in [0, 1]
  bool operator==(const PairDesc&) const = default;
};

// Stored energy (a compressed spring, a charge) released at time_s between two touching bodies of
// a 1D scene, pushing them apart: energy_J, or a separation speed (exactly one is given).
struct ReleaseDesc {
  int body_a = 0;  // 0-based, the one on the left
  int body_b = 1;  // 0-based, the one on the right, touching body_a at t = 0
  double time_s = 0.0;
  std::optional<double> energy_J;   // Q, > 0
  std::optional<double> speed_mps;  // or: the separation speed it adds, > 0
  bool operator==(const ReleaseDesc&) const = default;
};

enum class RestitutionLawKind {
  kConstant,        // e as given, at every impact speed
  kSpeedThreshold,  // e0 up to threshold_speed, e0 * (threshold / u)^exponent above it
  kTable,           // e from (speed, e) points, linear in between, clamped at the ends
};

// How a pair's or wall's e depends on the normal impact speed u.
struct RestitutionLawDesc {
  RestitutionLawKind kind = RestitutionLawKind::kConstant;
  double threshold_speed_mps = 1.0;              // kSpeedThreshold: > 0
  double exponent = 0.25;                        // kSpeedThreshold: >= 0
  std::vector<std::pair<double, double>> table;  // kTable: (speed m/s >= 0, e), speeds increasing
  bool operator==(const RestitutionLawDesc&) const = default;
};

enum class ContactModelKind {
  kImpulse,       // rigid bodies, instantaneous impulse
  kSpringDamper,  // a linear spring and dashpot during a finite contact
};

enum class InelasticMode {
  kSlip,   // 2D, e = 0: normal components equalize, the disks slide on
  kStick,  // 2D, e = 0: the disks join into one rotating rigid cluster
};

struct ContactDesc {
  ContactModelKind model = ContactModelKind::kImpulse;
  double duration_s = 0.01;  // kSpringDamper: how long one contact lasts, > 0
  InelasticMode inelastic = InelasticMode::kSlip;
  double collapse_time_s = 1e-9;  // impacts closer together than this become inelastic; >= 0
  bool operator==(const ContactDesc&) const = default;
};

// How a scene is shown. Defaults give the plain single-panel picture; every field is optional in
// a scene file and can be overridden from the command line.
struct ViewDesc {
  std::string theme = "light";  // "light", "dark" or "high-contrast"
  // Comparison panels: one time-aligned panel per value of `panel_parameter`, a settable scene key
  // such as "restitution" or "body.2.mass" (values {1, 0.5, 0}); empty values = a single panel.
  std::string panel_parameter;
  std::vector<double> panel_values;
  bool chart = false;                     // a chart panel beside the animation
  std::string chart_quantity = "energy";  // "energy", "momentum", "force"; "speed": histogram
  bool momentum_diagram = false;          // 2D: momentum vectors tip to tail with their sum
  bool center_of_mass = false;            // marker at the centre of mass
  double trail_s = 0.0;                   // fading trails this many seconds long; 0 = none
  bool center_of_momentum_frame = false;  // draw in the frame where total momentum is zero
  double slow_motion_factor = 1.0;        // >= 1: playback slowed by this much around collisions
  double strobe_rate_hz = 0.0;  // images per second in `collide strobe`; 0: chosen so images do not
                                // overlap (compose::FrameSource::strobeRate_hz)
  bool arc_trail = false;       // bodies on strings: the arc swept so far, dotted
  // A strobe of this scene is a cloud of images that teaches nothing (a break of sixteen balls):
  // the instant, s, of the still that shows it best instead, which `batch` (its png without
  // --at, its strobe) and a lesson draw; `collide strobe` still draws the strobe and says so.
  // None: the strobe teaches.
  std::optional<double> best_still_s;
  // A calibration stick of a round length and a cross at the origin, fixed in the frame, for
  // measuring the video in Tracker (docs/data-format.md).
  bool calibration = false;
  bool working = false;  // the first impact's working beside the scene (collide solve)
  bool operator==(const ViewDesc&) const = default;
};

struct SceneDesc {
  std::string name;   // preset or file stem, used in output names
  std::string title;  // shown on frames and in metadata, placeholders filled in
  // The title as written, when it has {KEY} placeholders (e.g. "e = {restitution}") that take the
  // scene's values, so a title stays true under --set and sweeps; empty otherwise.
  std::string title_template;
  // The language of the pictures' and captions' words: a shipped BCP 47 tag ("de", "ar"); empty:
  // not chosen by the scene (English unless --lang chooses).
  std::string lang;
  int dimensions = 1;       // 1 or 2
  double duration_s = 4.0;  // simulated time, > 0
  core::Vec2 gravity_mps2 = {0.0, 0.0};
  double restitution = 1.0;  // default e for every pair, in [0, 1] (to 10: super_elastic)
  // e above 1 allowed: the scene says that impacts release stored energy (super-elastic).
  bool super_elastic = false;
  double string_restitution = 0.0;  // e of a slack string snapping taut, in [0, 1]
  // What presses the bodies onto the surface they slide on (friction's normal force m g_n).
  double surface_gravity_mps2 = 9.81;
  // Rolling balls on a cloth (2D): the disks are balls that slide until they roll.
  bool rolling = false;
  // Molecules with insides (2D): each disk's internal degrees of freedom, 0 (none), 1 or 2; disk
  // impacts then trade energy with the disks' insides (docs/physics.md).
  int internal_dof = 0;
  std::vector<BodyDesc> bodies;
  std::vector<WallDesc> walls;
  std::optional<BoxDesc> box;
  std::vector<PairDesc> pairs;        // later entries win
  std::vector<ReleaseDesc> releases;  // in the order written
  RestitutionLawDesc restitution_law;
  ContactDesc contact;
  ViewDesc view;
  // The preset parameters this scene was generated with (e.g. {"digits", 3} for pi-blocks).
  std::map<std::string, double> parameters;
  bool operator==(const SceneDesc&) const = default;
};

// Where a string of `length_m` at `angle_deg` from straight down (counter-clockwise) holds a body,
// relative to its pivot.
core::Vec2 hangingOffset(double length_m, double angle_deg);

// Every wall the physics sees: the scene's walls, then the box's ("box left", "box right"
// and in 2D "box bottom", "box top").
std::vector<WallDesc> allWalls(const SceneDesc& scene);

// e of a wall: its own, or the scene's default.
inline double wallRestitution(const SceneDesc& scene, const WallDesc& wall) {
  return wall.restitution.value_or(scene.restitution);
}

// A number a preset takes, e.g. pi-blocks' digits.
struct PresetParameter {
  std::string name;
  std::string description;  // one line, with the unit
  double default_value = 0.0;
  double min = 0.0, max = 0.0;  // inclusive
  bool integer = true;
};

struct PresetInfo {
  std::string name;
  std::string summary;  // one line for `collide presets`
  std::vector<PresetParameter> parameters;
};

// Every built-in preset, in the order `collide presets` lists them.
const std::vector<PresetInfo>& presetList();

// The preset's scene with its default parameters, read and validated like a file (placeholders
// in its title filled in). Throws SceneError naming the unknown name, with near matches, if none.
SceneDesc loadPreset(const std::string& name);

// The preset as its builder makes it from `parameters` (name -> value, already checked against
// the preset's ranges; missing ones take their defaults), before reading: the title may still
// hold placeholders. Throws SceneError for an unknown name.
SceneDesc makePreset(const std::string& name, const std::map<std::string, double>& parameters);

// Throws SceneError "scene: 'NAME': no such preset or file; did you mean ...".
[[noreturn]] void throwUnknownPreset(const std::string& name);

// The preset's info, or nullptr.
const PresetInfo* findPreset(const std::string& name);

}  // namespace collide::scene
