#pragma once
// Options shared by every command that takes a SCENE: the scene argument and the duration override.
#include <CLI/CLI.hpp>
#include <string>

#include "app/render_settings.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct SceneOptions {
  std::string scene;
  double duration_s = 0.0;
  CLI::Option* duration_option = nullptr;  // count() > 0 when --duration was given

  void addTo(CLI::App& command);
  // The scene with overrides applied and validated. Throws core::InputError.
  scene::SceneDesc load() const;
};

// --size WIDTHxHEIGHT on rendering commands.
struct SizeOption {
  std::string text = "1280x720";
  void addTo(CLI::App& command);
  FrameSize parse() const { return parseFrameSize(text); }
};

}  // namespace collide::app
