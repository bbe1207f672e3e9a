// SPDX-License-Identifier: MIT
#include "scene_recipe.hpp"

#include "app/render_settings.hpp"

namespace collide::python {
namespace {

void applyDuration(const SceneRecipe& recipe, scene::SceneDesc& scene) {
  if (!recipe.duration_s) return;
  app::checkDuration(*recipe.duration_s, "duration", recipe.duration_typed);
  scene.duration_s = *recipe.duration_s;
}

}  // namespace

scene::SceneDesc loadRecipe(const SceneRecipe& recipe) {
  scene::SceneDesc loaded =
      recipe.is_text ? scene::parseSceneText(recipe.source, recipe.text_name, recipe.overrides)
                     : scene::loadScene(recipe.source, recipe.overrides);
  applyDuration(recipe, loaded);
  return loaded;
}

scene::SceneDesc loadForData(const SceneRecipe& recipe, std::unique_ptr<LanguageHold>& hold) {
  hold = std::make_unique<LanguageHold>(text::shippedLanguages().front());
  return loadRecipe(recipe);
}

scene::SceneDesc loadForPicture(const SceneRecipe& recipe, const std::string& lang,
                                std::unique_ptr<LanguageHold>& hold) {
  const text::Language* chosen = lang.empty() ? nullptr : &text::findLanguage(lang, "lang");
  hold.reset();
  hold = std::make_unique<LanguageHold>(chosen != nullptr ? *chosen
                                                          : text::shippedLanguages().front());
  scene::SceneDesc loaded = loadRecipe(recipe);
  if (chosen == nullptr && !loaded.lang.empty()) {
    // The scene picks its language: read it again in it, so a preset's words come in it.
    const text::Language& own = text::findLanguage(loaded.lang, "lang");
    hold.reset();
    hold = std::make_unique<LanguageHold>(own);
    loaded = loadRecipe(recipe);
  }
  if (chosen != nullptr) loaded.lang = chosen->tag;
  return loaded;
}

}  // namespace collide::python
