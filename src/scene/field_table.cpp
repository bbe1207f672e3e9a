// SPDX-License-Identifier: MIT
#include "scene/field_table.hpp"

#include <stdexcept>

#include "scene/scene_io.hpp"

namespace collide::scene::detail {
namespace {

using F = FieldForm;
using Q = Quantity;

// A function, not a namespace-scope constant: the readers take their ranges from this table
// while other files' statics are initialised, in an order C++ does not fix.
Range restitution() {
  return restitutionRange(true);
}

FieldSpec flag(std::string key, std::string description) {
  return {std::move(key), F::kFlag, std::move(description), {}, {}, 0, ""};
}

FieldSpec number(std::string key, std::string description, Range range) {
  return {std::move(key), F::kNumber, std::move(description), std::move(range), {}, 0, ""};
}

FieldSpec of(std::string key, FieldForm form, std::string description,
             std::vector<std::string> choices = {}) {
  return {std::move(key), form, std::move(description), {}, std::move(choices), 0, ""};
}

FieldSpec vector(std::string key, std::string description, double max_abs, Quantity kind) {
  return {std::move(key),
          F::kVector,
          std::move(description),
          Range{-max_abs, max_abs, false, "", kind},
          {},
          0,
          ""};
}

FieldSpec needing(FieldSpec field, std::string key) {
  field.needs = std::move(key);
  return field;
}

FieldSpec text(std::string key, std::string description, std::size_t max_length) {
  return {std::move(key), F::kText, std::move(description), {}, {}, max_length, ""};
}

SectionSpec top() {
  FieldSpec dimensions = of("dimensions", F::kInteger, "1: blocks on a line; 2: disks in a plane");
  dimensions.range = Range{1.0, 2.0, false, "1 or 2"};
  FieldSpec internal = of("internal", F::kInteger,
                          "internal degrees of freedom of every disk (2D): 0 (none), 1 or 2");
  internal.range = Range{0.0, 2.0, false, "0, 1 or 2"};
  return {
      "",
      false,
      {text("name", "scene name, used in output file names", 64),
       text("title", "shown on frames; {KEY} takes the scene's value of KEY", 200),
       text("lang", "language of the words on pictures (a BCP 47 tag)", 35),
       dimensions,
       number("duration", "simulated time",
              {0.0, kMaxDurationS, true, "a duration in s", Q::kTime}),
       vector("gravity", "uniform acceleration (1D: along x)", kMaxGravityMps2, Q::kAcceleration),
       number("restitution", "e for every pair of bodies and every wall without its own",
              restitution()),
       number("string_restitution", "e of a slack string snapping taut", restitutionRange(false)),
       number("surface_gravity", "presses the bodies onto the surface: friction's normal force",
              {0.0, kMaxGravityMps2, true, "an acceleration in m/s^2", Q::kAcceleration}),
       flag("super_elastic", "allow e above 1 (to 10): impacts release stored energy"),
       flag("rolling", "2D: the disks are balls on a cloth that slide until they roll"),
       internal,
       of("body", F::kText, "the bodies: [[body]] tables"),
       of("wall", F::kText, "fixed walls: [[wall]] tables"),
       of("box", F::kText, "an enclosing box: [box]"),
       of("pair", F::kText, "per-pair restitution: [[pair]] tables"),
       of("release", F::kText, "stored energy pushing touching bodies apart: [[release]] tables"),
       of("contact", F::kText, "contact model: [contact]"),
       of("restitution_law", F::kText, "how e depends on impact speed: [restitution_law]"),
       of("view", F::kText, "how the scene is drawn: [view]")}};
}

SectionSpec body() {
  return {
      "body",
      true,
      {text("name", "label in pictures and data", 64),
       of("shape", F::kChoice, "block, disk or (1D) glider", {"block", "disk", "glider"}),
       number("mass", "", {0.0, kMaxMassKg, true, "a mass in kg", Q::kMass}),
       number("width", "a block's or glider's full width",
              {0.0, kMaxLengthM, true, "a width in m (the block's full width)", Q::kLength}),
       number("radius", "a disk's radius", {0.0, kMaxLengthM, true, "a radius in m", Q::kLength}),
       number("size", "the older key: a block's full width, a disk's radius",
              {0.0, kMaxLengthM, true, "a size in m (block width or disk radius)", Q::kLength}),
       vector("position", "centre at t = 0", kMaxLengthM, Q::kLength),
       vector("velocity", "at t = 0", kMaxSpeedMps, Q::kSpeed),
       number("speed", "instead of velocity: how fast, along heading",
              {0.0, kMaxSpeedMps, false, "a speed in m/s", Q::kSpeed}),
       needing(of("heading", F::kHeading,
                  "with speed: degrees from +x, or compass words (\"N\", \"60 deg north of "
                  "east\")"),
               "speed"),
       of("color", F::kColor, "fill colour: \"#rrggbb\" or [r, g, b]"),
       number("friction", "kinetic coefficient of sliding friction with the surface",
              {0.0, kMaxFriction, false, "a coefficient of friction"}),
       number("static_friction", "static coefficient: holds the body at rest (default: friction)",
              {0.0, kMaxFriction, false, "a coefficient of friction"}),
       number("drag_linear",
              "air drag F = -k v: k in kg/s (1D; 2D with contact.inelastic = \"slip\")",
              {0.0, kMaxDrag, false, "a linear drag coefficient in kg/s", Q::kLinearDrag}),
       number("drag_quadratic",
              "air drag F = -c |v| v: c in kg/m (1D only, no gravity along the track)",
              {0.0, kMaxDrag, false, "a quadratic drag coefficient in kg/m", Q::kQuadraticDrag}),
       number("rolling_mu", "rolling resistance's coefficient (rolling = true)",
              {0.0, kMaxFriction, false, "a coefficient of rolling resistance"}),
       of("spin", F::kChoice, "how a ball is struck (rolling = true): follow, stop or draw",
          {"follow", "stop", "draw"}),
       vector("pivot", "the body hangs on a string from this point (2D)", kMaxLengthM, Q::kLength),
       needing(number("length", "with pivot, instead of position: the string's length",
                      {0.0, kMaxLengthM, true, "a string length in m", Q::kLength}),
               "pivot"),
       needing(
           number("angle", "with length: the string's angle from straight down, counter-clockwise",
                  {-180.0, 180.0, false, "an angle in degrees from straight down", Q::kAngle}),
           "length"),
       of("struck_by", F::kBodyRef, "instead of position: placed as the target of this body"),
       needing(of("impact_parameter", F::kLengthOrFraction,
                  "with struck_by: offset to the right of the line of approach; a number is a "
                  "fraction of the summed radii, a quoted length a length"),
               "struck_by"),
       needing(number("gap", "with struck_by: how far the striker travels before they touch",
                      {0.0, kMaxLengthM, false, "a gap in m", Q::kLength}),
               "struck_by")}};
}

std::vector<SectionSpec> tables() {
  return {
      {"wall",
       true,
       {text("name", "", 64), vector("position", "any point on the wall", kMaxLengthM, Q::kLength),
        vector("normal", "the direction into the free side (1D: 1 or -1)", 1e6, Q::kNumber),
        number("restitution", "e of impacts on this wall", restitution())}},
      {"box",
       false,
       {vector("min", "lower-left corner (1D: left end)", kMaxLengthM, Q::kLength),
        vector("max", "upper-right corner (1D: right end)", kMaxLengthM, Q::kLength),
        number("restitution", "e of the box's walls", restitution())}},
      {"pair",
       true,
       {of("bodies", F::kBodyPair, "the two bodies, numbers from 1 or names"),
        number("restitution", "their e", restitution())}},
      {"release",
       true,
       {of("bodies", F::kBodyPair, "the two touching bodies, numbers from 1 or names"),
        number("time", "when the energy is released",
               {0.0, kMaxDurationS, false, "a time in s", Q::kTime}),
        number("energy", "the energy released, Q", {0.0, kMaxEnergyJ, true, "an energy in J"}),
        number("speed", "or: the speed at which it pushes them apart",
               {0.0, kMaxSpeedMps, true, "a speed in m/s", Q::kSpeed})}},
      {"restitution_law",
       false,
       {of("kind", F::kChoice, "", {"constant", "speed-threshold", "table"}),
        number("threshold_speed", "speed-threshold: where e starts to fall",
               {0.0, kMaxSpeedMps, true, "a speed in m/s", Q::kSpeed}),
        number("exponent", "speed-threshold: how fast e falls", {0.0, 10.0, false, "an exponent"}),
        of("table", F::kLawTable, "table: [[speed, e], ...]")}},
      {"contact",
       false,
       {of("model", F::kChoice, "", {"impulse", "spring-damper"}),
        number("duration", "spring-damper: how long one contact lasts",
               {0.0, 1.0, true, "a contact duration in s", Q::kTime}),
        of("inelastic", F::kChoice, "2D, e = 0: slide on or stick together", {"slip", "stick"}),
        number("collapse_time", "impacts closer than this become inelastic",
               {0.0, 1e-3, false, "a time in s", Q::kTime})}},
      {"view",
       false,
       {of("theme", F::kChoice, "colours", {"light", "dark", "high-contrast"}),
        of("panels", F::kPanels, "side-by-side panels: {parameter = \"KEY\", values = [...]}"),
        of("chart", F::kChart, "a chart beside the animation",
           {"none", "energy", "momentum", "force", "speed"}),
        of("momentum_diagram", F::kFlag, "2D: momentum vectors tip to tail"),
        of("center_of_mass", F::kFlag, "mark the centre of mass"),
        number("trail", "fading trails this long",
               {0.0, 60.0, false, "a trail length in s", Q::kTime}),
        of("center_of_momentum_frame", F::kFlag, "draw in the zero-momentum frame"),
        number("slow_motion", "playback slowed by this factor around collisions",
               {1.0, 100.0, false, "a slow-down factor"}),
        number("strobe_rate", "images per second in a strobe picture",
               {0.0, 1000.0, true, "a rate in images per second", Q::kFrequency}),
        number("best_still", "the still shown where a strobe cannot teach the scene",
               {0.0, kMaxDurationS, false, "a time in s", Q::kTime}),
        of("arc_trail", F::kFlag, "bodies on strings: the arc swept so far"),
        of("calibration", F::kFlag, "a calibration stick and the origin, for Tracker"),
        of("working", F::kFlag, "the first impact's working beside the scene (collide solve)")}}};
}

}  // namespace

Range restitutionRange(bool super_elastic) {
  Range range{0.0, 1.0, false, "a coefficient of restitution"};
  if (super_elastic) {
    range.max = kMaxSuperElasticRestitution;
  } else {
    range.note = " (above 1, to 10, with super_elastic = true: impacts that release energy)";
  }
  return range;
}

const std::vector<SectionSpec>& sceneSections() {
  static const std::vector<SectionSpec> sections = [] {
    std::vector<SectionSpec> all = {top(), body()};
    for (SectionSpec& section : tables()) all.push_back(std::move(section));
    return all;
  }();
  return sections;
}

std::vector<std::string> sectionKeys(const std::string& section) {
  std::vector<std::string> keys;
  for (const SectionSpec& spec : sceneSections()) {
    if (spec.name != section) continue;
    for (const FieldSpec& field : spec.fields) keys.push_back(field.key);
  }
  return keys;
}

const Range& fieldRange(const std::string& section, const std::string& key) {
  for (const SectionSpec& spec : sceneSections()) {
    if (spec.name != section) continue;
    for (const FieldSpec& field : spec.fields) {
      if (field.key == key) return field.range;
    }
  }
  throw std::logic_error("fieldRange: no key " + section + "." + key);
}

}  // namespace collide::scene::detail
