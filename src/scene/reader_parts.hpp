#pragma once
// Internal to collide_scene: the pieces of the scene reader, one file each.
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

// [view]: reads into scene.view.
void readView(Fields& view, ViewDesc& out);

// [restitution_law] and [contact].
void readRestitutionLaw(Fields& law, RestitutionLawDesc& out);
void readContact(Fields& contact, ContactDesc& out);

// Checks across the scene once every value is valid on its own: bodies overlapping at t = 0,
// bodies behind a wall or outside the box, 1D wall normals inferred from where the bodies are.
void checkLayout(SceneDesc& scene, const LayoutNodes& nodes, const Origins& origins,
                 Problems& problems);

}  // namespace collide::scene::detail
