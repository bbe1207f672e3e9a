#pragma once
// Turns physics snapshots into panels of a FrameModel: plans a camera and scales once per timeline
// (so the picture never jumps), then maps each sampled state to bodies, arrows, labels, the energy
// bar and readouts. Optionally in the centre-of-momentum frame.
#include <string>
#include <vector>

#include "compose/frame_text.hpp"
#include "compose/palette.hpp"
#include "compose/skid_view.hpp"
#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

// A bar segment below this share of the bar has no width (zero up to round-off): a legend entry
// such as "lost 0 J" in an elastic scene would point at nothing, so it is left out.
inline constexpr double kLabelledShare = 1e-9;

// Per-timeline drawing choices, fixed for every frame.
struct FramePlan {
  frame::ViewWindow view;         // covers all motion (in the drawing frame), walls included
  double arrow_m_per_mps = 0.25;  // world metres of arrow per m/s
  // Longest arrow drawn to scale, world metres; a body faster than that (a bullet beside its
  // block) gets an off-scale arrow with a break in its shaft. 0: no limit.
  double arrow_max_length_m = 0.0;
  double scale_arrow_mps = 0.0;  // the scale arrow's speed: a round value; 0: no arrows
  // The bar's length: KE + PE + lost at the start, and all the energy released in the run (the
  // largest total the scene reaches, so that nothing runs off the bar's end).
  double energy_full_scale_J = 1.0;
  double energy_start_J = 0.0;  // KE + PE at the start, J: where the released strip begins
  bool releases = false;        // energy can come in (physics::canReleaseEnergy): booked too
  bool friction = false;        // bodies slide with friction: what went to the surface too
  bool cloth = false;           // ... the cloth of rolling balls (KE counts their spin)
  bool drag = false;            // bodies feel air drag: what went to the air too
  bool potential = false;       // gravity: the bar shows potential energy too
  bool loses_energy = true;     // the run loses energy: the bar's loss gets a label slot
  bool springs = false;         // soft contacts: the bar holds one part for every spring
  // Each bar segment's widest label over the picture (planBarLegend), "" for one never labelled:
  // the room its legend entry keeps in every frame (frame::EnergySegment::label_room). Empty:
  // not planned, each frame's labels their own.
  std::vector<std::string> bar_rooms;
  // The bar legend's entries shot by shot (planBarLegend; empty: not planned): `shown[s][k]`
  // where segment k is labelled at some instant of the shot that starts at `starts_s[s]`. Such
  // an entry stays through its shot while its segment has any energy (kLabelledShare), though a
  // crowded bar labels so small a segment nowhere else: an entry does not come and go within a
  // shot (issue 37).
  struct BarShots {
    std::vector<double> starts_s;
    std::vector<std::vector<bool>> shown;
  };
  BarShots bar_shots;
  double potential_floor_J = 0.0;       // PE shown is PE - this (the lowest PE reached), J
  double momentum_full_scale_Ns = 1.0;  // farthest reach of the momentum chain
  // The box the momentum chain's points (start at 0, each partial sum) stay in over the run.
  core::Vec2 momentum_low_Ns = {0.0, 0.0}, momentum_high_Ns = {0.0, 0.0};
  core::Vec2 frame_velocity_mps = {0.0, 0.0};   // velocity of the drawing frame (COM frame)
  core::Vec2 initial_momentum_Ns = {0.0, 0.0};  // in the drawing frame
  std::vector<double> first_collision_s;        // per body; +inf if it never collides
  double flash_s = 0.15;                        // how long a contact flash lasts, simulated s
  struct Bond {
    double time_s;
    int body_a, body_b;
  };
  std::vector<Bond> bonds;   // bodies that stuck together (merged impacts), in time order
  double fastest_mps = 0.0;  // largest speed in the drawing frame
  std::vector<Skid> skids;   // bodies an impact set skidding with friction (skid_view.hpp)
  double longest_skid_m = 0.0;
  PictureFormats formats;  // units and decimals of every number on the picture
};

FramePlan planFrames(const scene::SceneDesc& scene, const physics::Timeline& timeline);

// The formats of a picture of these plans (several panels read in one unit).
PictureFormats formatsFor(const std::vector<const FramePlan*>& plans, double duration_s);

// Kinetic energy of each body in the drawing frame (J).
std::vector<double> bodyKineticEnergies(const physics::Timeline& timeline, const FramePlan& plan,
                                        const physics::Snapshot& snapshot);

// The panel at simulated time t_s; whole_run: the last state of a picture of the whole run (a
// strobe), whose readouts say "end" where a still says "now".
frame::PanelModel buildPanel(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                             const FramePlan& plan, const Theme& theme, double t_s,
                             bool whole_run = false);

// Bodies only (no labels, arrows, trails) at t_s: the images of a strobe photograph.
std::vector<frame::BodyModel> bodyImages(const scene::SceneDesc& scene,
                                         const physics::Timeline& timeline, const FramePlan& plan,
                                         const Theme& theme, double t_s);

}  // namespace collide::compose
