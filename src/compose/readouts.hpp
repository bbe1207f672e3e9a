#pragma once
// A panel's readouts from the energy books and the picture's number formats: the energy bar
// (kinetic energy per body, potential energy of gravity, each compressed spring, energy lost, all
// adding up to the energy at the start as displayed) and the caption under it.
#include <string>
#include <vector>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "frame/frame_model.hpp"
#include "physics/energy_books.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

// The books at t_s in the plan's drawing frame, gravity counted from the plan's floor.
// The names of the energy bar's and energy chart's parts, in the active language.
std::string springWord();
std::string internalWord();
std::string lostWord();
std::string releasedWord();
std::string surfaceWord(bool cloth = false);  // cloth: rolling balls' table
std::string airWord();
std::string spinWord();

physics::EnergyBooks panelBooks(const physics::Timeline& timeline, const FramePlan& plan,
                                double t_s);

// Each body's kinetic energy of spin about its own centre at the books' time, J, where the
// scene's bodies can spin (2D disks that stick and turn as one rigid body, balls rolling on a
// cloth); empty elsewhere. The
// books' kinetic energy of a body holds it beside ½·m·v² of its centre: the bar and the energy
// chart show it apart, as "spin", so a KE₁ reads ½·m₁·v₁², which a reader checks against the v₁
// the picture shows (stick-2d's KE₁ read 0.367 J where ½·1 kg·(0.827 m/s)² is 0.342 J).
std::vector<double> spinEnergies_J(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                                   const FramePlan& plan, const physics::EnergyBooks& books);

// The bar's segments and labels. Each label shows three significant figures in the picture's
// energy unit (its own prefix when far below it), rounded together so that the numbers shown add
// up to the energy at the start as the caption writes it (text::formatParts). Where energy can
// come in (plan.releases), a strip under the parts shows what was released so far, from the
// start's energy on, in its own colour and legend entry: the parts then add up to both.
// spin_J (spinEnergies_J): each body's spin, shown apart from its KE; empty: none.
frame::EnergyBar energyBar(const scene::SceneDesc& scene, const FramePlan& plan, const Theme& theme,
                           const physics::EnergyBooks& books,
                           const std::vector<double>& spin_J = {});

// A coil for each spring of the books, between the partners' centres (to the wall's face for a
// wall), on a panel whose bodies and walls are already placed. A contact of a glider compresses
// its bumpers instead: each glider's two bumpers, shortened by their share of the compression.
void addSprings(const scene::SceneDesc& scene, const physics::EnergyBooks& books,
                frame::PanelModel& panel);

// Body body_i's two bumpers if it is a glider (none otherwise), left and right of its drawn block
// on a panel whose bodies and walls are placed, each shortened by its share of the compression.
std::vector<frame::SpringModel> gliderBumpers(const scene::SceneDesc& scene,
                                              const physics::EnergyBooks& books,
                                              const frame::PanelModel& panel, std::size_t body_i);

// "t = 1.060 s: energy lost 0.680 J of 1.38 J (49.5%); v₁ = +0.250 m/s, v₂ = +1.00 m/s", with
// the moving frame before the velocities when the picture is drawn in one; "lost" as the bar
// writes it (spin_J as the bar was given it). Nothing lost (yet) is said in words:
// "t = 0.00 s: no energy lost (total 1.38 J)".
std::string panelCaption(const scene::SceneDesc& scene, const FramePlan& plan, const Theme& theme,
                         const physics::EnergyBooks& books,
                         const std::vector<std::string>& velocity_texts,
                         const std::vector<double>& spin_J = {});

}  // namespace collide::compose
