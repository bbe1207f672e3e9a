#pragma once
// Scene files (TOML, see docs/scene-format.md), presets and command-line overrides, all turned into
// a validated SceneDesc through one reader. Every problem is reported as
//   where: key: value: what is allowed
// where `where` is file:line:column for a scene file, the override (e.g. "--set body.2.mass=-1")
// for a command-line value, or "preset NAME" for a value that came from a built-in preset.
#include <optional>
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"

namespace collide::scene {

// Limits that keep every run finite. Durations match the app's --duration limit.
inline constexpr double kMaxDurationS = 3600.0;
inline constexpr int kMaxBodies = 1000;
inline constexpr int kMaxWalls = 100;
inline constexpr double kMaxMassKg = 1e18;  // pi-blocks with 9 digits needs 1e16
inline constexpr double kMaxLengthM = 1e6;  // positions and sizes
inline constexpr double kMaxSpeedMps = 1e6;
inline constexpr double kMaxGravityMps2 = 1e4;
inline constexpr double kMaxFriction = 10.0;  // coefficients of friction
inline constexpr double kMaxDrag = 1e18;      // drag coefficients, kg/s and kg/m (as masses)
inline constexpr double kMaxEnergyJ = 1e30;   // a release: the heaviest pair at the top speed
// e above 1 (super_elastic = true); the physics makes impacts beyond 1000 times the scene's
// speeds elastic, so that the speeds stay finite.
inline constexpr double kMaxSuperElasticRestitution = 10.0;
inline constexpr int kMaxPanels = 6;

// One change to a scene value from the command line.
struct Override {
  enum class Kind {
    kValue,      // key = value, value in TOML syntax (a bare word is taken as a string)
    kSpeed,      // key "body.N": the speed of body N (1D: the signed velocity), in m/s; 2D keeps
                 // the direction of motion
    kDirection,  // key "body.N": the direction of motion of body N in degrees counter-clockwise
                 // from +x, keeping the speed (2D only)
  };
  std::string key;     // e.g. "restitution", "body.2.mass", "view.theme", "digits"
  std::string value;   // e.g. "0.3", "[1, 2]", "dark"
  std::string origin;  // how the user wrote it, for messages: "--set body.2.mass=3", "--m2 3"
  Kind kind = Kind::kValue;
  // kValue only: the number itself, set as it is (`value` then only shows it in messages), for
  // values that never were text (comparison panels' values): nothing is printed and read back.
  std::optional<double> number = std::nullopt;
};

// Parses "KEY=VALUE" as written after --set (or --sweep's per-value form). Throws SceneError for a
// missing '=' or an empty key or value.
Override parseSetExpression(const std::string& text, const std::string& option = "--set");

// A SCENE argument: a preset name, or a path to a .toml scene file (anything with a '/' or a
// .toml ending, or an existing file). Overrides apply in order after the file; preset parameters
// (e.g. digits) are applied first, when the preset is built. Throws SceneError listing every
// problem found.
// `notes`, when given, receives how keys other than position and velocity set each body's start
// (speed and heading, struck_by, length and angle) and the older keys read (size).
SceneDesc loadScene(const std::string& scene_arg, const std::vector<Override>& overrides = {},
                    std::vector<std::string>* notes = nullptr);

// Reads scene text as if from a file named `source_name` (used in messages). For tests and
// fuzzers; the name of the scene defaults to the stem of source_name.
SceneDesc parseSceneText(const std::string& text, const std::string& source_name,
                         const std::vector<Override>& overrides = {});

// The scene with overrides applied and validated again (sweeps, comparison panels). `label` names
// the scene in messages. Throws SceneError.
SceneDesc withOverrides(const SceneDesc& scene, const std::vector<Override>& overrides);

// One comparison panel's scene: `scene` with view.panel_parameter set to `value`.
struct SceneVariant {
  SceneDesc scene;
  double value = 0.0;
};

// The scenes of a comparison picture, one per view.panel_values in order, each `scene` with its
// panel parameter set to that value (as a number, validated as if written in the file) and
// without panels of its own; a scene without panels gives itself. Throws SceneError.
std::vector<SceneVariant> panelVariants(const SceneDesc& scene);

// The scene as a TOML scene file that parseSceneText reads back to an equal SceneDesc.
std::string sceneToToml(const SceneDesc& scene);

// docs/scene.schema.json: a JSON Schema (draft 7) of scene files, made from the reader's field
// table, for editors; a test keeps the committed file equal to it.
std::string sceneJsonSchema();

// `collide presets show NAME`: the preset as a commented scene file to copy and edit. A preset
// with parameters is written as `preset = "NAME"` with its parameters, the generated scene below
// in comments. `lang` (a shipped tag, or empty) is written as the scene's `lang`; the words come in
// the active language. Throws SceneError for an unknown name.
std::string presetToml(const std::string& name, const std::string& lang = "");

}  // namespace collide::scene
