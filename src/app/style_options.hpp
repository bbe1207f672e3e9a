#pragma once
// How a picture looks, on every rendering command: --theme, --font, --chart, --panels. They
// override the scene's view settings (which a scene file or --set view.KEY=... also sets).
#include <CLI/CLI.hpp>
#include <string>

#include "scene/scene_desc.hpp"

namespace collide::app {

struct StyleOptions {
  std::string theme;         // "light", "dark", "high-contrast"; empty: the scene's
  std::string font;          // a TrueType/OpenType file; empty: DejaVu Sans
  std::string chart;         // "energy", "momentum", "force" or "none"; empty: the scene's
  std::string panels;        // "KEY=V1,V2,..." e.g. "restitution=1,0.5,0"; empty: the scene's
  bool calibration = false;  // a calibration stick and the origin (ViewDesc::calibration)
  bool working = false;      // --working: the working panel beside the scene

  void addTo(CLI::App& command);
  // Checks every option (core::InputError naming it, the value and what is allowed), applies
  // them to scene.view and makes --font the font of every renderer created afterwards.
  void applyTo(scene::SceneDesc& scene) const;
};

}  // namespace collide::app
