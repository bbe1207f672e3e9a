#include "app/scene_options.hpp"

#include "text/language.hpp"

namespace collide::app {

void OverrideOptions::addTo(CLI::App& command) {
  command.add_option("--set", sets,
                     "Change a scene value, KEY=VALUE (repeatable): restitution=0.3, "
                     "body.2.mass=3, view.theme=dark, digits=6 (a preset parameter)");
  const char* group = "Two-body shortcuts";
  command.add_option("--m1", m1, "Mass of body 1, kg (= --set body.1.mass=...)")->group(group);
  command.add_option("--m2", m2, "Mass of body 2, kg")->group(group);
  command.add_option("--v1", v1, "Speed of body 1, m/s (1D: signed velocity)")->group(group);
  command.add_option("--v2", v2, "Speed of body 2, m/s (1D: signed velocity)")->group(group);
  command.add_option("--e", e, "Coefficient of restitution, 0 to 1 (= --set restitution=...)")
      ->group(group);
  command.add_option("--theta1", theta1, "2D: direction of body 1, degrees from +x")->group(group);
  command.add_option("--theta2", theta2, "2D: direction of body 2, degrees from +x")->group(group);
}

std::vector<scene::Override> OverrideOptions::overrides() const {
  using Kind = scene::Override::Kind;
  std::vector<scene::Override> result;
  for (const std::string& text : sets) result.push_back(scene::parseSetExpression(text));
  const auto shortcut = [&](const std::string& value, const char* option, const char* key,
                            Kind kind) {
    if (!value.empty()) result.push_back({key, value, std::string(option) + " " + value, kind});
  };
  shortcut(m1, "--m1", "body.1.mass", Kind::kValue);
  shortcut(m2, "--m2", "body.2.mass", Kind::kValue);
  shortcut(e, "--e", "restitution", Kind::kValue);
  shortcut(v1, "--v1", "body.1", Kind::kSpeed);
  shortcut(theta1, "--theta1", "body.1", Kind::kDirection);
  shortcut(v2, "--v2", "body.2", Kind::kSpeed);
  shortcut(theta2, "--theta2", "body.2", Kind::kDirection);
  return result;
}

void SceneOptions::addTo(CLI::App& command) {
  addSceneArgument(command);
  addChanges(command);
}

void SceneOptions::addSceneArgument(CLI::App& command) {
  command
      .add_option("SCENE", scene,
                  "Preset name (see 'collide presets') or scene file (.toml, see "
                  "docs/scene-format.md)")
      ->required();
}

void SceneOptions::addChanges(CLI::App& command) {
  duration_option = command.add_option("--duration", duration_s,
                                       "Simulated seconds (default: the scene's duration)");
  if (words) {
    addLanguageOption(command, lang);
  } else {
    // Taken as the picture commands take it, so one command line serves both; it changes
    // nothing but must name a shipped language.
    command.add_option("--lang", lang,
                       "Accepted as on the picture commands and checked; changes nothing here: "
                       "the numbers are the same in every language");
  }
  changes.addTo(command);
}

void addLanguageOption(CLI::App& command, std::string& tag) {
  command.add_option("--lang", tag,
                     "Language of the words on pictures, captions and alt text, a BCP 47 tag: " +
                         text::shippedLanguageList() + " (default: the scene's lang, else en)");
}

scene::SceneDesc SceneOptions::load() const {
  const text::Language* chosen = lang.empty() ? nullptr : &text::findLanguage(lang, "--lang");
  if (!words) chosen = nullptr;  // checked, and no more
  text::setActiveLanguage(chosen != nullptr ? *chosen : text::shippedLanguages().front());
  scene::SceneDesc loaded = scene::loadScene(scene, changes.overrides());
  if (words && chosen == nullptr && !loaded.lang.empty()) {
    // The scene picks its language: read it again in it, so a preset's words come in it.
    text::setActiveLanguage(text::findLanguage(loaded.lang, "lang"));
    loaded = scene::loadScene(scene, changes.overrides());
  }
  if (chosen != nullptr) loaded.lang = chosen->tag;
  if (duration_option->count() > 0) {
    checkDuration(duration_s, "--duration", duration_option->results().back());
    loaded.duration_s = duration_s;
  }
  return loaded;
}

void SizeOption::addTo(CLI::App& command) {
  command.add_option("--size", text, "Frame size WIDTHxHEIGHT, 16x16 to 7680x4320")
      ->capture_default_str();
}

}  // namespace collide::app
