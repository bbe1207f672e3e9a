// SPDX-License-Identifier: MIT
#pragma once
// A Python Scene as the engine reads it: where it comes from (a preset, a scene file or scene
// text) and the overrides applied in order, as `--set` and the two-body shortcuts apply them. It
// is read again for every use, so each use reads it in its own language, as the program does.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host_work.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"

namespace collide::python {

struct SceneRecipe {
  std::string source;     // preset name or scene file path; or the scene text itself
  bool is_text = false;   // `source` is TOML text
  std::string text_name;  // the text's name in messages ("scene.toml"), its stem the scene's name
  std::vector<scene::Override> overrides;
  std::optional<double> duration_s;  // as --duration: after the overrides
  std::string duration_typed;        // how it was given, for the message
};

// The scene in the active language, overrides applied and validated. Throws scene::SceneError.
scene::SceneDesc loadRecipe(const SceneRecipe& recipe);

// The scene for data (JSON, CSV): read in English, as `collide data` reads it.
scene::SceneDesc loadForData(const SceneRecipe& recipe, std::unique_ptr<LanguageHold>& hold);

// The scene for a picture, read in the language of its words as the picture commands read it:
// `lang` (a shipped tag, checked), else the scene's own `lang`, else English. `hold` keeps that
// language active while the picture is drawn. Throws core::InputError.
scene::SceneDesc loadForPicture(const SceneRecipe& recipe, const std::string& lang,
                                std::unique_ptr<LanguageHold>& hold);

}  // namespace collide::python
