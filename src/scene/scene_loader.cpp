// SCENE argument -> validated SceneDesc: a preset (built with its parameters, written as TOML) or a
// scene file (optionally `preset = "NAME"` plus changes), then the command-line overrides, then
// one reader for all of it.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>

#include "core/bounded_read.hpp"
#include "core/typed_text.hpp"
#include "scene/fields.hpp"
#include "scene/override_apply.hpp"
#include "scene/scene_io.hpp"
#include "scene/suggest.hpp"
#include "scene/title_template.hpp"
#include "scene/toml_guard.hpp"

namespace collide::scene {
namespace fs = std::filesystem;
using detail::Origins;
using detail::Problems;

namespace {

constexpr std::size_t kMaxFileBytes = 4 << 20;  // a scene file is text; 4 MiB is plenty
// Sub-tables a file merges key by key into its preset's; anything else replaces.
const char* const kMergedTables[] = {"view", "contact", "box", "restitution_law"};

bool looksLikeFile(const std::string& arg) {
  std::error_code error;
  return arg.find('/') != std::string::npos ||
         (arg.size() > 5 && arg.compare(arg.size() - 5, 5, ".toml") == 0) ||
         fs::is_regular_file(arg, error);
}

// A file stem made safe for output names ("my scene" -> "my-scene").
std::string nameFromPath(const std::string& path) {
  std::string stem = fs::path(path).stem().string();
  for (char& c : stem) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '-';
  }
  while (!stem.empty() && stem.front() == '.') stem.erase(stem.begin());
  if (stem.size() > 64) stem.resize(64);
  return stem.empty() ? "scene" : stem;
}

// Through the one bounded reader: it stops at the limit whatever the file reports, so /dev/zero,
// a pipe that never ends or a huge file cost at most 4 MiB and a moment.
std::string readFile(const std::string& path) {
  const std::string allowed =
      "; allowed: a preset name (see 'collide presets') or a readable .toml scene file";
  const core::BoundedRead read = core::readBounded(path, kMaxFileBytes);
  switch (read.outcome) {
    case core::ReadOutcome::kRead:
      return read.bytes;
    case core::ReadOutcome::kTooLarge:
      throw SceneError("scene: '" + path + "': more than 4 MiB; allowed: a scene file of at " +
                       "most 4 MiB");
    default:
      throw SceneError("scene: '" + path + "': " + core::describeRefusal(read, kMaxFileBytes) +
                       allowed);
  }
}

// A preset parameter given in a file or an override: a number in the parameter's range.
void readParameter(const PresetParameter& parameter, const toml::node& node,
                   const std::string& where, std::map<std::string, double>& out,
                   Problems& problems) {
  const std::optional<double> value = detail::asNumber(node);
  const bool whole =
      value && std::isfinite(*value) && (!parameter.integer || *value == std::floor(*value));
  if (!whole || *value < parameter.min || *value > parameter.max) {
    problems.add(where + ": " + parameter.name + ": " + detail::valueText(node) +
                 ": allowed: " + parameter.description + ", " +
                 (parameter.integer ? "a whole number " : "") + "from " +
                 detail::plainNumber(parameter.min) + " to " + detail::plainNumber(parameter.max));
    return;
  }
  out[parameter.name] = *value;
}

const PresetParameter* parameterOf(const PresetInfo* preset, const std::string& key) {
  if (preset == nullptr) return nullptr;
  for (const PresetParameter& p : preset->parameters) {
    if (p.name == key) return &p;
  }
  return nullptr;
}

// A preset parameter used on a scene that does not take it: say which presets do.
bool reportForeignParameter(const Override& change, Problems& problems) {
  for (const PresetInfo& info : presetList()) {
    if (parameterOf(&info, change.key) == nullptr) continue;
    problems.add(change.origin + ": " + change.key + ": " + core::echoTyped(change.value) +
                 ": not a parameter of this scene; allowed: with preset '" + info.name +
                 "' (e.g. collide render " + info.name + " --set " + change.key + "=" +
                 core::echoTyped(change.value) + ")");
    return true;
  }
  return false;
}

// The preset's scene as a table: built with its parameters, written as TOML, parsed.
toml::table presetTable(const std::string& name, const std::map<std::string, double>& parameters) {
  return detail::parseToml(sceneToToml(makePreset(name, parameters)), "");
}

// Everything between the SCENE argument and the reader.
class Loader {
 public:
  explicit Loader(const std::vector<Override>& overrides) : overrides_(overrides) {}

  SceneDesc fromPreset(const std::string& name) {
    preset_ = findPreset(name);
    if (preset_ == nullptr) throwUnknownPreset(name);
    origins_.fallback = "preset " + name;
    collectParameters({});
    problems_.throwIfAny();
    return finish(presetTable(name, parameters_), name);
  }

  // `located`: messages give file:line:column (false for text made from a SceneDesc).
  SceneDesc fromText(const std::string& text, const std::string& source, bool located = true) {
    toml::table table = detail::parseToml(text, located ? source : "");
    origins_.fallback = source;
    if (const toml::node* base = table.get("preset")) {
      const auto* base_name = base->as_string();
      preset_ = base_name != nullptr ? findPreset(base_name->get()) : nullptr;
      if (preset_ == nullptr) {
        std::vector<std::string> names;
        for (const PresetInfo& info : presetList()) names.push_back(info.name);
        problems_.add(origins_.where(base) + ": preset: " + detail::valueText(*base) +
                      ": no such preset; allowed: a name from 'collide presets'" +
                      (base_name != nullptr ? didYouMean(base_name->get(), names) : ""));
        problems_.throwIfAny();
      }
      collectParameters(table);
      problems_.throwIfAny();
      toml::table merged = presetTable(preset_->name, parameters_);
      mergeInto(merged, table);
      origins_.fallback = "preset " + preset_->name;
      return finish(std::move(merged), nameFromPath(source));
    }
    return finish(std::move(table), nameFromPath(source));
  }

 private:
  // Parameters from the file's top level, then from overrides (which win); defaults otherwise.
  void collectParameters(const toml::table& file) {
    for (const PresetParameter& p : preset_->parameters) parameters_[p.name] = p.default_value;
    for (const auto& [key, node] : file) {
      if (const PresetParameter* p = parameterOf(preset_, std::string(key.str()))) {
        readParameter(*p, node, origins_.where(&node), parameters_, problems_);
      }
    }
    for (const Override& change : overrides_) {
      const PresetParameter* p = parameterOf(preset_, change.key);
      if (p == nullptr || change.kind != Override::Kind::kValue) continue;
      toml::table parsed;
      std::string text;
      bool parsed_as_toml = false;
      if (detail::tryAsciiForToml("v = " + change.value + "\n", text)) {  // toml++ sees ASCII
        try {
          parsed = toml::parse(text);
          parsed_as_toml = true;
        } catch (const toml::parse_error&) {
        }
      }
      if (!parsed_as_toml) parsed.insert("v", change.value);
      if (const toml::node* v = parsed.get("v")) {
        readParameter(*p, *v, change.origin, parameters_, problems_);
      }
    }
  }

  // The file's keys over the preset's: tables in kMergedTables key by key, the rest replaced.
  // Moving keeps each node's source, so messages still name the file's line.
  void mergeInto(toml::table& base, toml::table& file) {
    for (auto& [key, node] : file) {
      const std::string name(key.str());
      if (name == "preset" || parameterOf(preset_, name) != nullptr) continue;
      const bool merged = std::find(std::begin(kMergedTables), std::end(kMergedTables), name) !=
                          std::end(kMergedTables);
      toml::table* target = base.get_as<toml::table>(name);
      if (merged && target != nullptr && node.is_table()) {
        for (auto& [sub_key, sub_node] : *node.as_table()) {
          // Named copies: clang 14 cannot capture structured bindings in a lambda.
          const toml::key& entry_key = sub_key;
          sub_node.visit([&](auto& v) { target->insert_or_assign(entry_key, std::move(v)); });
        }
      } else {
        const toml::key& entry_key = key;
        node.visit([&](auto& v) { base.insert_or_assign(entry_key, std::move(v)); });
      }
    }
  }

  SceneDesc finish(toml::table table, const std::string& default_name) {
    const std::optional<std::int64_t> dimensions_before = table["dimensions"].value<std::int64_t>();
    for (const Override& change : overrides_) {
      if (change.kind == Override::Kind::kValue && parameterOf(preset_, change.key) != nullptr) {
        continue;  // used when the preset was built
      }
      if (change.kind == Override::Kind::kValue && reportForeignParameter(change, problems_)) {
        continue;
      }
      detail::applyOverride(table, change, origins_, problems_);
    }
    problems_.throwIfAny();
    SceneDesc scene = detail::readScene(table, origins_, problems_, default_name);
    if (!problems_.empty()) blameChangedDimensions(dimensions_before.value_or(1), table);
    problems_.throwIfAny();
    fillTitle(table, scene);
    problems_.throwIfAny();
    scene.parameters = parameters_;
    checkPanels(table, scene);
    problems_.throwIfAny();
    return scene;
  }

  // `--set dimensions=2` on a scene written for a line makes its gravity, positions and
  // velocities wrong: the change is the cause, so it heads the problems instead of the preset's
  // gravity. (Changing them too with --set is allowed; then nothing is wrong.)
  void blameChangedDimensions(std::int64_t before, const toml::table& table) {
    const std::optional<std::int64_t> after = table["dimensions"].value<std::int64_t>();
    if (!after || *after == before || (*after != 1 && *after != 2)) return;
    const auto change = std::find_if(overrides_.rbegin(), overrides_.rend(), [](const Override& c) {
      return c.kind == Override::Kind::kValue && c.key == "dimensions";
    });
    if (change == overrides_.rend()) return;
    const std::string was = std::to_string(before) + "D";
    Problems headed;
    headed.add(change->origin + ": dimensions: " + core::echoTyped(change->value) + ": " +
               origins_.fallback + " is written for " + was +
               (before == 1 ? " (gravity, positions and velocities as single numbers, blocks)"
                            : " (gravity, positions and velocities as [x, y], disks)") +
               "; allowed: " + std::to_string(before) + ", or a scene written for " +
               std::to_string(*after) + "D (see 'collide presets')");
    for (const std::string& line : problems_.lines()) headed.add(line);
    problems_ = std::move(headed);
  }

  // "{restitution}" in the title becomes the scene's value (see title_template.hpp).
  void fillTitle(const toml::table& table, SceneDesc& scene) {
    if (scene.title.find('{') == std::string::npos) return;
    std::string problem;
    const std::string filled = detail::fillTitle(scene.title, scene, problem);
    if (!problem.empty()) {
      const toml::node* title = table.get("title");
      problems_.add(origins_.where(title) + ": title: " +
                    (title != nullptr ? detail::valueText(*title) : scene.title) + ": " + problem);
      return;
    }
    scene.title_template = scene.title;
    scene.title = filled;
  }

  // Each comparison panel must be a valid scene: apply its value to a copy and read it.
  void checkPanels(const toml::table& table, const SceneDesc& scene) {
    if (scene.view.panel_values.empty()) return;
    const toml::node* panels = table.at_path("view.panels").node();
    const std::string where = origins_.where(panels);
    if (parameterOf(preset_, scene.view.panel_parameter) != nullptr) {
      problems_.add(
          where + ": view.panels: " + scene.view.panel_parameter +
          ": a preset parameter; allowed: a scene key such as restitution or body.2.mass");
      return;
    }
    for (const double value : scene.view.panel_values) {
      toml::table copy = table;
      copy["view"].as_table()->erase("panels");
      Problems inner;
      const Override change{scene.view.panel_parameter, detail::numberText(value),
                            where + ": view.panels value " + detail::plainNumber(value),
                            Override::Kind::kValue, value};
      Origins origins = origins_;  // the copy's nodes must not outlive this check
      detail::applyOverride(copy, change, origins, inner);
      if (inner.empty()) detail::readScene(copy, origins, inner, scene.name);
      if (!inner.empty()) {
        problems_.add(inner.lines().front());
        return;
      }
    }
  }

 public:
  const std::vector<std::string>& notes() const { return problems_.notes(); }

 private:
  const std::vector<Override>& overrides_;
  const PresetInfo* preset_ = nullptr;
  std::map<std::string, double> parameters_;
  Origins origins_;
  Problems problems_;
};

}  // namespace

Override parseSetExpression(const std::string& text, const std::string& option) {
  const std::size_t equals = text.find('=');
  // Messages quote the expression as typed, cut at 80 characters with control characters
  // escaped: a megabyte key or a newline in a value stays one short line.
  const std::string origin = option + " " + core::echoTyped(text);
  const auto trim = [](std::string s) {
    const std::size_t a = s.find_first_not_of(" \t");
    const std::size_t b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
  };
  // Both sides must be non-empty once blanks are trimmed (" =1" has no key).
  const std::string key = equals == std::string::npos ? "" : trim(text.substr(0, equals));
  const std::string value = equals == std::string::npos ? "" : trim(text.substr(equals + 1));
  if (key.empty() || value.empty()) {
    throw SceneError(option + ": '" + core::echoTyped(text) +
                     "': not KEY=VALUE; allowed: e.g. restitution=0.3, body.2.mass=3, "
                     "view.theme=dark, digits=6");
  }
  return {key, value, origin, Override::Kind::kValue};
}

SceneDesc loadPreset(const std::string& name) {
  static const std::vector<Override> kNone;
  return Loader(kNone).fromPreset(name);
}

SceneDesc loadScene(const std::string& scene_arg, const std::vector<Override>& overrides,
                    std::vector<std::string>* notes) {
  Loader loader(overrides);
  SceneDesc scene = looksLikeFile(scene_arg) ? loader.fromText(readFile(scene_arg), scene_arg)
                                             : loader.fromPreset(scene_arg);
  if (notes != nullptr) *notes = loader.notes();
  return scene;
}

SceneDesc parseSceneText(const std::string& text, const std::string& source_name,
                         const std::vector<Override>& overrides) {
  return Loader(overrides).fromText(text, source_name);
}

SceneDesc withOverrides(const SceneDesc& scene, const std::vector<Override>& overrides) {
  if (overrides.empty()) return scene;
  SceneDesc changed = Loader(overrides).fromText(sceneToToml(scene), "scene " + scene.name, false);
  changed.parameters = scene.parameters;
  return changed;
}

std::vector<SceneVariant> panelVariants(const SceneDesc& scene) {
  const ViewDesc& view = scene.view;
  if (view.panel_values.empty()) return {SceneVariant{scene, 0.0}};
  // A panel is one picture of the comparison: it has no panels of its own.
  SceneDesc single = scene;
  single.view.panel_values.clear();
  single.view.panel_parameter.clear();
  std::vector<SceneVariant> variants;
  for (const double value : view.panel_values) {
    const Override change{view.panel_parameter, detail::numberText(value),
                          "view.panel_values (" + view.panel_parameter + ")",
                          Override::Kind::kValue, value};
    SceneDesc variant = withOverrides(single, {change});
    variant.view.panel_parameter = view.panel_parameter;
    variant.view.panel_values = view.panel_values;
    variants.push_back({std::move(variant), value});
  }
  return variants;
}

}  // namespace collide::scene
