#pragma once
// Internal to collide_scene: the pieces of the scene reader, one file each.
#include <optional>
#include <vector>

#include "scene/fields.hpp"

namespace collide::scene::detail {

// The TOML nodes behind bodies and walls, so that checks across the scene (overlap, walls) can
// point at the line that placed a body.
struct LayoutNodes {
  std::vector<const toml::node*> body_position;  // per body: its `position`, or its table
  std::vector<const toml::node*> body_table;     // per body: its [[body]] table
  std::vector<const toml::node*> wall_table;     // per wall
  std::vector<bool> wall_normal_given;           // per wall: false = infer from the bodies (1D)
  const toml::node* box = nullptr;               // the [box] table, if any
};

// A body placed as the target of another (`struck_by`), resolved once every body is read.
struct Aim {
  std::size_t body = 0;                 // the target, 0-based
  const toml::table* table = nullptr;   // its [[body]] table
  const toml::node* striker = nullptr;  // `struck_by` as written: a number from 1 or a name
  std::optional<double> b_fraction;     // impact parameter as a fraction of the summed radii
  std::optional<double> b_length_m;     // or as a length
  double gap_m = 0.0;                   // how far the striker travels before they touch
};

// A body's size: `width` (block, glider) or `radius` (disk), or the older `size`.
void readBodySize(Fields& body, BodyDesc& out);
// A body's velocity: `velocity`, or `speed` with `heading`.
void readBodyVelocity(Fields& body, BodyDesc& out, int dimensions);
// `friction` and `static_friction` (at least the kinetic one; none on a string).
void readBodyFriction(Fields& body, BodyDesc& out);
// What friction cannot go with: soft contacts, gravity in a plane (2D: a level table).
void checkFriction(Fields& top, const SceneDesc& scene);
// `rolling_mu` and `spin` (rolling balls).
void readBodyRolling(Fields& body, BodyDesc& out);
// What a rolling table cannot go with: 1D, gravity in the plane, soft or sticking contacts,
// strings, drag, molecules with insides; and rolling keys on a table that does not roll.
void checkRolling(Fields& top, const SceneDesc& scene);
// `drag_linear` and `drag_quadratic` (none on a string).
void readBodyDrag(Fields& body, BodyDesc& out);
// What drag cannot go with: soft contacts, friction, quadratic drag in 2D or with gravity along
// the line.
void checkDrag(Fields& top, const SceneDesc& scene);
// `struck_by`, `impact_parameter` and `gap`, when given.
std::optional<Aim> readAim(Fields& body, std::size_t index, int dimensions);
// Places the aimed body relative to body `striker` (0-based); `body` reads its table.
void placeAimed(SceneDesc& scene, const Aim& aim, int striker, Fields& body);

// [view]: reads into scene.view.
void readView(Fields& view, ViewDesc& out);

// [restitution_law] and [contact].
void readRestitutionLaw(Fields& law, RestitutionLawDesc& out);
void readContact(Fields& contact, ContactDesc& out);

// [[release]] tables (after the bodies are placed), sorted by time; then, once [contact] is read,
// the checks on e above 1 (super_elastic = true: rigid impacts of free bodies only).
void readReleases(const toml::array& tables, const Origins& origins, Problems& problems,
                  SceneDesc& scene);
void checkSuperElastic(Fields& top, const SceneDesc& scene);
// internal > 0 (molecules with insides): a plane, rigid impacts, no strings, and e = 1 between
// bodies (their impacts conserve energy; walls keep their own e).
void checkInternal(Fields& top, const SceneDesc& scene);

// Checks across the scene once every value is valid on its own: bodies overlapping at t = 0,
// bodies behind a wall or outside the box, 1D wall normals inferred from where the bodies are.
void checkLayout(SceneDesc& scene, const LayoutNodes& nodes, const Origins& origins,
                 Problems& problems);

}  // namespace collide::scene::detail
