#pragma once
// Options shared by every command that takes a SCENE: the scene argument, --duration, --set
// KEY=VALUE and the two-body shortcuts (--m1 --m2 --v1 --v2 --e --theta1 --theta2).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "app/render_settings.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"

namespace collide::app {

// --set and the shortcuts, without a SCENE (batch uses them for many scenes).
struct OverrideOptions {
  std::vector<std::string> sets;  // "KEY=VALUE", in the order given
  // Shortcut values as typed, so the scene reader validates them like a file value; empty = not
  // given. Masses in kg, speeds in m/s (1D: signed velocity), angles in degrees from +x (2D).
  std::string m1, m2, v1, v2, e, theta1, theta2;

  void addTo(CLI::App& command);
  // Every --set in order, then the shortcuts (m1, m2, e, v1, theta1, v2, theta2). Throws
  // scene::SceneError for a --set that is not KEY=VALUE.
  std::vector<scene::Override> overrides() const;
};

struct SceneOptions {
  std::string scene;
  double duration_s = 0.0;
  CLI::Option* duration_option = nullptr;  // count() > 0 when --duration was given
  std::string lang;                        // --lang: empty = the scene's `lang`, else English
  // False for commands that write only data (CSV, JSON: never in a language): --lang is checked
  // and changes nothing, and the scene is read in English whatever its `lang`.
  bool words = true;
  OverrideOptions changes;

  void addTo(CLI::App& command);
  // addTo in two parts, so a command can list its output between them: SCENE, then --duration,
  // --set and the shortcuts.
  void addSceneArgument(CLI::App& command);
  void addChanges(CLI::App& command);
  // The scene with overrides applied and validated, in its language (--lang, else the scene's
  // `lang`, else English), which it makes the active language: a preset's titles and names
  // come in it. Throws core::InputError, also for a --lang that is not shipped (before reading
  // the scene).
  scene::SceneDesc load() const;
};

// --lang TAG, the language of the words on pictures and in text, on `command`.
void addLanguageOption(CLI::App& command, std::string& tag);

// --size WIDTHxHEIGHT on rendering commands.
struct SizeOption {
  std::string text = "1280x720";
  void addTo(CLI::App& command);
  FrameSize parse() const { return parseFrameSize(text); }
};

}  // namespace collide::app
