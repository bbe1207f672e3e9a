#pragma once
// Internal to collide_scene: applying command-line overrides to a scene's TOML table before it is
// read, so an override is validated exactly like the same value written in the file.
#include "scene/scene_io.hpp"
#include "scene/toml_reader.hpp"

namespace collide::scene::detail {

// Applies one override to `table`, recording the nodes it puts in `origins`. A key path that names
// no place in the scene (body.9 in a two-body scene, a value that is not TOML) adds a problem.
void applyOverride(toml::table& table, const Override& change, Origins& origins,
                   Problems& problems);

// Parses scene text; malformed TOML throws SceneError "source:line:column: malformed TOML: ...".
// An empty source_name gives nodes without a source (their origin is Origins::fallback).
toml::table parseToml(const std::string& text, const std::string& source_name);

}  // namespace collide::scene::detail
