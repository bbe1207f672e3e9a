// The preset library: names, one-line summaries, parameters and the function that builds each.
#include <cmath>
#include <functional>
#include <numbers>

#include "scene/preset_builders.hpp"
#include "scene/scene_desc.hpp"
#include "scene/suggest.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"

namespace collide::scene {
namespace {

struct PresetEntry {
  PresetInfo info;
  std::function<SceneDesc(const detail::Parameters&)> make;
};

// The presets up to the strings', in the order `collide presets` lists them; presetTable adds
// the rest.
std::vector<PresetEntry> firstPresets() {
  using namespace detail;
  return {
      {{"worked-example",
        text::N_("1 kg at +2 m/s meets 1 kg at -1 m/s, e = 0.5 (the default)"),
        {}},
       workedExample},
      {{"elastic", text::N_("elastic (e = 1): 1 kg at 3 m/s hits 2 kg at rest, bounces back"), {}},
       elastic},
      {{"perfectly-inelastic",
        text::N_("e = 0: 2 kg at 3 m/s hits 1 kg at rest; they move on together"),
        {}},
       perfectlyInelastic},
      {{"compare-restitution",
        text::N_("the same collision side by side with e = 1, 0.5 and 0"),
        {}},
       compareRestitution},
      {{"heavy-light", text::N_("mass ratio 100: a 10 kg cart hits a 0.1 kg cart at rest"), {}},
       heavyLight},
      {{"car-crash",
        text::N_("head-on crash of two cars; e falls with impact speed (about 0.1 here)"),
        {}},
       carCrash},
      {{"accident-reconstruction",
        text::N_("two cars lock (e = 0) and skid to rest: the skid length gives their speed"),
        {}},
       accidentReconstruction},
      {{"air-drag",
        text::N_("a glider with a sail slows in the air (F = -c v^2) before it hits one at rest"),
        {}},
       airDrag},
      {{"clay", text::N_("two lumps of clay meet head-on and stick (e = 0)"), {}}, clay},
      {{"bullet-block",
        text::N_("a 10 g bullet embeds in a 1 kg block: momentum kept, 99% of KE lost"),
        {}},
       bulletBlock},
      {{"spring-carts",
        text::N_("a spring released between carts at rest pushes them apart with 3 J"),
        {}},
       springCarts},
      {{"recoil", text::N_("a 4 kg rifle fires a 10 g bullet at 400 m/s and recoils at 1 m/s"), {}},
       recoil},
  };
}

// From the strings' on.
std::vector<PresetEntry> laterPresets() {
  using namespace detail;
  return {
      {{"ballistic-pendulum",
        text::N_("2D: a bullet into a hanging block; the block's rise gives the bullet's speed"),
        {}},
       ballisticPendulum},
      {{"air-track",
        text::N_("two gliders with spring bumpers on an air track with end stops"),
        {}},
       airTrack},
      {{"bouncing-ball",
        text::N_("2D: a ball bounces on the floor under gravity, e = 0.8; see it in a strobe"),
        {}},
       bouncingBall},
      {{"air-drag-throw",
        text::N_("2D: the same throw to each side, one ball with air drag: it lands short"),
        {}},
       airDragThrow},
      {{"newtons-cradle",
        text::N_("2D: five touching equal balls on strings, e = 1: n swing in, n swing out"),
        {{"moving", text::N_("balls swung in from the left"), 1, 1, 4, true}}},
       newtonsCradle},
      {{"billiards-glancing",
        text::N_("2D: equal balls, off-centre elastic hit: they leave at 90 degrees"),
        {}},
       billiardsGlancing},
      {{"billiards-break",
        text::N_("2D: a cue ball breaks a rack of 15 balls on a cushioned table"),
        {{"rows", text::N_("rows of balls in the triangular rack"), 5, 1, 5, true}}},
       billiardsBreak},
      {{"billiards-follow",
        text::N_("2D: a rolling cue ball hits head-on, stops, then follows at 2/7 of its speed"),
        {}},
       billiardsFollow},
      {{"billiards-draw",
        text::N_("2D: a cue ball with backspin hits head-on, stops, then comes back"),
        {}},
       billiardsDraw},
      {{"stick-2d", text::N_("2D: two disks hit off-centre and stick into one rotating body"), {}},
       stick2d},
      {{"ideal-gas",
        text::N_("2D: disks in a box, e = 1; speeds relax to Maxwell-Boltzmann (histogram)"),
        {{"disks", text::N_("disks in the box"), 300, 2, 1000, true}}},
       idealGas},
      {{"granular-chain",
        text::N_("a striker runs into a row of blocks; e varies from pair to pair"),
        {}},
       granularChain},
      {{"soft-contact",
        text::N_("spring-damper contact lasting 0.2 s, with the force over time"),
        {}},
       softContact},
      {{"pi-blocks",
        text::N_("Galperin's blocks: the collision count spells the digits of pi"),
        {{"digits", text::N_("digits of pi to count (mass ratio 100^(digits-1))"), 3, 1, 9, true}}},
       piBlocks},
  };
}

std::vector<PresetEntry> allPresets() {
  std::vector<PresetEntry> entries = firstPresets();
  std::vector<PresetEntry> later = laterPresets();
  entries.insert(entries.end(), later.begin(), later.end());
  return entries;
}

const std::vector<PresetEntry>& presetTable() {
  static const std::vector<PresetEntry> table = allPresets();
  return table;
}

const PresetEntry* findEntry(const std::string& name) {
  for (const PresetEntry& entry : presetTable()) {
    if (entry.info.name == name) return &entry;
  }
  return nullptr;
}

}  // namespace

const std::vector<PresetInfo>& presetList() {
  static const std::vector<PresetInfo> list = [] {
    std::vector<PresetInfo> infos;
    for (const PresetEntry& entry : presetTable()) infos.push_back(entry.info);
    return infos;
  }();
  return list;
}

const PresetInfo* findPreset(const std::string& name) {
  for (const PresetInfo& info : presetList()) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

SceneDesc makePreset(const std::string& name, const std::map<std::string, double>& parameters) {
  const PresetEntry* entry = findEntry(name);
  if (entry == nullptr) throwUnknownPreset(name);
  detail::Parameters values;
  for (const PresetParameter& p : entry->info.parameters) {
    const auto given = parameters.find(p.name);
    values[p.name] = given != parameters.end() ? given->second : p.default_value;
    COLLIDE_ASSERT(values[p.name] >= p.min && values[p.name] <= p.max,
                   "parameter " + p.name + " outside its range");
  }
  SceneDesc scene = entry->make(values);
  scene.parameters = values;
  // The numbers its translator typed into its words, in the language's digits.
  scene.title = text::typedNumbersIn(scene.title);
  scene.title_template = text::typedNumbersIn(scene.title_template);
  for (BodyDesc& body : scene.bodies) body.name = text::typedNumbersIn(body.name);
  return scene;
}

void throwUnknownPreset(const std::string& name) {
  std::vector<std::string> names;
  for (const PresetEntry& entry : presetTable()) names.push_back(entry.info.name);
  throw SceneError("scene: '" + name + "': no such preset or file" + didYouMean(name, names) +
                   " (run 'collide presets' for the list)");
}

core::Vec2 hangingOffset(double length_m, double angle_deg) {
  const double a = angle_deg * std::numbers::pi / 180.0;
  return length_m * core::Vec2(std::sin(a), -std::cos(a));
}

std::vector<WallDesc> allWalls(const SceneDesc& scene) {
  std::vector<WallDesc> walls = scene.walls;
  if (!scene.box) return walls;
  const BoxDesc& box = *scene.box;
  walls.push_back({"box left", box.min_m, {1.0, 0.0}, box.restitution});
  walls.push_back({"box right", box.max_m, {-1.0, 0.0}, box.restitution});
  if (scene.dimensions == 2) {
    walls.push_back({"box bottom", box.min_m, {0.0, 1.0}, box.restitution});
    walls.push_back({"box top", box.max_m, {0.0, -1.0}, box.restitution});
  }
  return walls;
}

}  // namespace collide::scene
