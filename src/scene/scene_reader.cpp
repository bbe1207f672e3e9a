// Reads a scene table: top-level keys, [[body]], [[wall]], [box] and [[pair]]; then hands the
// other tables and the checks across the scene to their own files.
#include <cmath>
#include <numbers>
#include <set>

#include "core/error.hpp"
#include "scene/field_table.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"
#include "text/language.hpp"

namespace collide::scene::detail {
namespace {

// Limits from the field table (field_table.cpp), which docs/scene.schema.json is made from.
const Range& kMass = fieldRange("body", "mass");
const Range& kDuration = fieldRange("", "duration");

// Names appear in output file names: keep them to safe characters.
bool isSafeName(const std::string& name) {
  return !name.empty() && name.size() <= 64 && name.front() != '.' &&
         name.find_first_not_of(
             "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.") ==
             std::string::npos;
}

class SceneReader {
 public:
  SceneReader(const toml::table& table, const Origins& origins, Problems& problems)
      : top_(table, "", origins, problems), origins_(origins), problems_(problems) {}

  SceneDesc read(const std::string& default_name) {
    top_.allowOnly(topLevelKeys());
    readTop(default_name);
    readBodies();
    readWalls();
    readBox();
    readPairs();
    if (const toml::array* releases = tableArray("release", "[[release]] tables")) {
      readReleases(*releases, origins_, problems_, scene_);
    }
    if (const toml::table* law = subTable("restitution_law")) {
      Fields fields(*law, "restitution_law", origins_, problems_);
      readRestitutionLaw(fields, scene_.restitution_law);
    }
    if (const toml::table* contact = subTable("contact")) {
      Fields fields(*contact, "contact", origins_, problems_);
      readContact(fields, scene_.contact);
    }
    checkSuperElastic(top_, scene_);
    checkFriction(top_, scene_);
    checkDrag(top_, scene_);
    checkRolling(top_, scene_);
    checkInternal(top_, scene_);
    if (const toml::table* view = subTable("view")) {
      Fields fields(*view, "view", origins_, problems_);
      readView(fields, scene_.view);
    }
    if (problems_.empty()) checkLayout(scene_, nodes_, origins_, problems_);
    return std::move(scene_);
  }

 private:
  void readTop(const std::string& default_name) {
    scene_.name =
        top_.text("name", 64, "a name of letters, digits, '-', '_' and '.'").value_or(default_name);
    if (top_.has("name") && !isSafeName(scene_.name)) {
      top_.problem(top_.node("name"), "name",
                   "allowed: 1 to 64 letters, digits, '-', '_' and '.', not starting with '.'");
    }
    scene_.title =
        top_.text("title", 200, "a string of at most 200 characters").value_or(scene_.name);
    readLanguage();
    scene_.dimensions = top_.integer("dimensions", 1, 2, "1 (a line) or 2 (a plane)").value_or(1);
    scene_.duration_s = top_.number("duration", kDuration).value_or(scene_.duration_s);
    scene_.gravity_mps2 = top_.vector("gravity", scene_.dimensions, kMaxGravityMps2,
                                      "an acceleration in m/s^2", Quantity::kAcceleration)
                              .value_or(scene_.gravity_mps2);
    // Before any e: it sets how far e may go.
    scene_.super_elastic = top_.flag("super_elastic").value_or(false);
    restitution_range_ = restitutionRange(scene_.super_elastic);
    scene_.restitution =
        top_.number("restitution", restitution_range_).value_or(scene_.restitution);
    scene_.string_restitution =
        top_.number("string_restitution", fieldRange("", "string_restitution"))
            .value_or(scene_.string_restitution);
    scene_.surface_gravity_mps2 = top_.number("surface_gravity", fieldRange("", "surface_gravity"))
                                      .value_or(scene_.surface_gravity_mps2);
    scene_.rolling = top_.flag("rolling").value_or(false);
    scene_.internal_dof =
        top_.integer("internal", 0, 2, "internal degrees of freedom per disk").value_or(0);
  }

  // `lang`: one of the shipped languages (text/language.hpp), stored in its canonical form.
  void readLanguage() {
    const std::optional<std::string> tag =
        top_.text("lang", 35, "a BCP 47 language tag such as de, pt-BR or ar");
    if (!tag) return;
    try {
      scene_.lang = text::findLanguage(*tag, "lang").tag;
    } catch (const core::InputError&) {
      top_.problem(top_.node("lang"), "lang",
                   "not a shipped language; allowed: " + text::shippedLanguageList());
    }
  }

  // An array of tables such as [[body]]; reports any other type.
  const toml::array* tableArray(const std::string& key, const std::string& what) {
    const toml::node* at = top_.node(key);
    if (at == nullptr) return nullptr;
    const toml::array* array = at->as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
      top_.problem(at, key, "wrong type; allowed: " + what);
      return nullptr;
    }
    return array;
  }

  const toml::table* subTable(const std::string& key) {
    const toml::node* at = top_.node(key);
    if (at == nullptr) return nullptr;
    if (!at->is_table()) {
      top_.problem(at, key, "wrong type; allowed: a [" + key + "] table");
      return nullptr;
    }
    return at->as_table();
  }

  void readBodies() {
    const toml::array* bodies = tableArray("body", "[[body]] tables, one per body");
    if (bodies == nullptr || bodies->empty()) {
      if (top_.has("body") && bodies != nullptr) top_.missing("body", "at least one [[body]]");
      if (!top_.has("body")) top_.missing("body", "at least one [[body]] table");
      return;
    }
    if (static_cast<int>(bodies->size()) > kMaxBodies) {
      top_.problem(top_.node("body"), "body",
                   std::to_string(bodies->size()) + " bodies; allowed: at most " +
                       std::to_string(kMaxBodies));
      return;
    }
    std::set<std::string> names;
    std::vector<Aim> aims;
    for (std::size_t i = 0; i < bodies->size(); ++i) {
      const toml::table& table = *bodies->get(i)->as_table();
      Fields f(table, "body." + std::to_string(i + 1), origins_, problems_);
      BodyDesc body = readBody(f, i, names);
      if (const std::optional<Aim> aim = readAim(f, i, scene_.dimensions)) aims.push_back(*aim);
      scene_.bodies.push_back(body);
      nodes_.body_table.push_back(&table);
      nodes_.body_position.push_back(f.has("position") ? f.node("position") : &table);
    }
    for (const Aim& aim : aims) placeTarget(aim, aims);
  }

  BodyDesc readBody(Fields& f, std::size_t i, std::set<std::string>& names) {
    f.allowOnly(bodyKeys());
    BodyDesc body;
    body.name = f.text("name", 64, "a string of at most 64 characters")
                    .value_or("body " + std::to_string(i + 1));
    if (!names.insert(body.name).second) {
      f.problem(f.node("name"), "name", "used by another body; allowed: a unique name");
    }
    body.shape = scene_.dimensions == 1 ? "block" : "disk";
    if (f.has("shape")) {
      const std::vector<std::string> shapes =
          scene_.dimensions == 1 ? std::vector<std::string>{"block", "disk", "glider"}
                                 : std::vector<std::string>{"disk"};
      body.shape = f.choice("shape", shapes).value_or(body.shape);
    }
    if (!f.has("mass")) f.missing("mass", kMass.text());
    body.mass_kg = f.number("mass", kMass).value_or(1.0);
    readBodySize(f, body);
    const bool on_string = readString(f, body);
    const bool placed = f.has("struck_by") || (on_string && f.has("length"));
    if (!placed) {
      if (!f.has("position")) f.missing("position", "a position in m");
      body.position_m =
          f.vector("position", scene_.dimensions, kMaxLengthM, "a position in m", Quantity::kLength)
              .value_or(body.position_m);
    }
    readBodyVelocity(f, body, scene_.dimensions);
    readBodyFriction(f, body);
    readBodyDrag(f, body);
    readBodyRolling(f, body);
    body.color = f.color("color");
    return body;
  }

  // A target placed by its striker, named by number or name; a striker that is itself placed so
  // must come first.
  void placeTarget(const Aim& aim, const std::vector<Aim>& aims) {
    Fields f(*aim.table, "body." + std::to_string(aim.body + 1), origins_, problems_);
    const std::optional<int> striker = bodyIndex(*aim.striker);
    bool placed_later = false;
    for (const Aim& other : aims) {
      placed_later = placed_later || (striker && other.body == static_cast<std::size_t>(*striker) &&
                                      other.body > aim.body);
    }
    if (!striker || static_cast<std::size_t>(*striker) == aim.body || placed_later) {
      f.problem(aim.striker, "struck_by",
                "not another body of this scene placed before it; allowed: a body's number from "
                "1 or its name, a body with a position (or one struck_by places earlier)");
      return;
    }
    if (problems_.empty()) placeAimed(scene_, aim, *striker, f);
  }

  // A body on a string: `pivot`, and either `position` or `length` with `angle` (degrees from
  // straight down, counter-clockwise positive), which set the position. True when it hangs.
  bool readString(Fields& f, BodyDesc& body) {
    if (!f.has("pivot")) {
      for (const char* key : {"length", "angle"}) {
        if (f.has(key)) f.problem(f.node(key), key, "needs a pivot; allowed: with pivot = [x, y]");
      }
      return false;
    }
    if (scene_.dimensions != 2) {
      f.problem(f.node("pivot"), "pivot",
                "a string hangs in a plane; allowed: only in 2D scenes (dimensions = 2)");
      return true;  // the pivot is the problem: no second one about its position
    }
    const std::optional<core::Vec2> pivot = f.vector(
        "pivot", 2, kMaxLengthM, "a point [x, y] in m the string hangs from", Quantity::kLength);
    if (!pivot) return false;
    body.pivot_m = *pivot;
    if (f.has("length") && f.has("position")) {
      f.problem(f.node("position"), "position",
                "given with length; allowed: either position or length and angle");
    }
    if (!f.has("length")) {
      if (f.has("angle")) {
        f.problem(f.node("angle"), "angle", "needs a length; allowed: with length = L in m");
      }
      return true;
    }
    const std::optional<double> length = f.number("length", fieldRange("body", "length"));
    const double angle_deg = f.number("angle", fieldRange("body", "angle")).value_or(0.0);
    if (length) {
      body.string_length_m = *length;
      body.string_angle_deg = angle_deg;
      body.position_m = *pivot + hangingOffset(*length, angle_deg);
      f.note(f.path() + ": position [" + plainNumber(body.position_m.x()) + ", " +
             plainNumber(body.position_m.y()) + "] m from pivot, length " + plainNumber(*length) +
             " m and angle " + plainNumber(angle_deg) + " degrees from straight down");
    }
    return true;
  }

  void readWalls() {
    const toml::array* walls = tableArray("wall", "[[wall]] tables, one per wall");
    if (walls == nullptr) return;
    if (static_cast<int>(walls->size()) > kMaxWalls) {
      top_.problem(
          top_.node("wall"), "wall",
          std::to_string(walls->size()) + " walls; allowed: at most " + std::to_string(kMaxWalls));
      return;
    }
    std::set<std::string> names;
    for (std::size_t i = 0; i < walls->size(); ++i) {
      const toml::table& table = *walls->get(i)->as_table();
      Fields f(table, "wall." + std::to_string(i + 1), origins_, problems_);
      f.allowOnly(sectionKeys("wall"));
      WallDesc wall;
      wall.name = f.text("name", 64, "a string of at most 64 characters")
                      .value_or("wall " + std::to_string(i + 1));
      if (!names.insert(wall.name).second) {
        f.problem(f.node("name"), "name", "used by another wall; allowed: a unique name");
      }
      if (!f.has("position")) f.missing("position", "a point on the wall in m");
      wall.position_m = f.vector("position", scene_.dimensions, kMaxLengthM,
                                 "a point on the wall in m", Quantity::kLength)
                            .value_or(wall.position_m);
      bool normal_given = false;
      if (scene_.dimensions == 1) {
        if (const std::optional<int> side = f.integer("normal", -1, 1, "the free side, 1 or -1")) {
          if (*side == 0)
            f.problem(f.node("normal"), "normal", "allowed: 1 (free side to the right) or -1");
          wall.normal = {*side >= 0 ? 1.0 : -1.0, 0.0};
          normal_given = true;
        }
      } else if (!f.has("normal")) {
        f.missing("normal", "[x, y] pointing into the free side");
      } else if (const auto n =
                     f.vector("normal", 2, 1e6, "a direction [x, y] into the free side")) {
        if (n->norm() < 1e-12) {
          f.problem(f.node("normal"), "normal",
                    "zero length; allowed: a non-zero direction [x, y]");
        } else {
          wall.normal = n->normalized();
          normal_given = true;
        }
      }
      wall.restitution = f.number("restitution", restitution_range_);
      scene_.walls.push_back(wall);
      nodes_.wall_table.push_back(&table);
      nodes_.wall_normal_given.push_back(normal_given);
    }
  }

  void readBox() {
    const toml::table* table = subTable("box");
    if (table == nullptr) return;
    Fields f(*table, "box", origins_, problems_);
    f.allowOnly(sectionKeys("box"));
    BoxDesc box;
    const int d = scene_.dimensions;
    const std::string corner = d == 1 ? "an end in m" : "a corner [x, y] in m";
    if (!f.has("min")) f.missing("min", corner);
    if (!f.has("max")) f.missing("max", corner);
    const auto low = f.vector("min", d, kMaxLengthM, corner, Quantity::kLength);
    const auto high = f.vector("max", d, kMaxLengthM, corner, Quantity::kLength);
    box.restitution = f.number("restitution", restitution_range_);
    if (low && high) {
      box.min_m = *low;
      box.max_m = *high;
      const bool empty =
          box.max_m.x() <= box.min_m.x() || (d == 2 && box.max_m.y() <= box.min_m.y());
      if (empty)
        f.problem(f.node("max"), "max", "not above min; allowed: max > min in each component");
    }
    scene_.box = box;
    nodes_.box = table;
  }

  // A body named by its 1-based index or its name.
  std::optional<int> bodyIndex(const toml::node& node) const {
    if (const auto* i = node.as_integer()) {
      if (i->get() >= 1 && i->get() <= static_cast<std::int64_t>(scene_.bodies.size())) {
        return static_cast<int>(i->get() - 1);
      }
    } else if (const auto* s = node.as_string()) {
      for (std::size_t k = 0; k < scene_.bodies.size(); ++k) {
        if (scene_.bodies[k].name == s->get()) return static_cast<int>(k);
      }
    }
    return std::nullopt;
  }

  void readPairs() {
    const toml::array* pairs = tableArray("pair", "[[pair]] tables, one per pair of bodies");
    if (pairs == nullptr) return;
    for (std::size_t i = 0; i < pairs->size(); ++i) {
      Fields f(*pairs->get(i)->as_table(), "pair." + std::to_string(i + 1), origins_, problems_);
      f.allowOnly(sectionKeys("pair"));
      const std::string allowed =
          "allowed: two different bodies, each a 1-based index or a body's name (e.g. [1, 2])";
      PairDesc pair;
      const toml::node* bodies = f.node("bodies");
      const toml::array* list = bodies != nullptr ? bodies->as_array() : nullptr;
      std::optional<int> a, b;
      if (list != nullptr && list->size() == 2) {
        a = bodyIndex(*list->get(0));
        b = bodyIndex(*list->get(1));
      }
      if (bodies == nullptr) {
        f.missing("bodies", allowed);
      } else if (!a || !b || *a == *b) {
        f.problem(bodies, "bodies", "not two different bodies of this scene; " + allowed);
      }
      if (!f.has("restitution")) f.missing("restitution", restitution_range_.text());
      pair.restitution = f.number("restitution", restitution_range_).value_or(1.0);
      if (a && b) {
        pair.body_a = *a;
        pair.body_b = *b;
      }
      scene_.pairs.push_back(pair);
    }
  }

  Fields top_;
  Range restitution_range_;  // e of pairs and walls: to 1, or beyond with super_elastic = true
  const Origins& origins_;
  Problems& problems_;
  SceneDesc scene_;
  LayoutNodes nodes_;
};

}  // namespace

const std::vector<std::string>& bodyKeys() {
  static const std::vector<std::string> keys = sectionKeys("body");
  return keys;
}

const std::vector<std::string>& topLevelKeys() {
  static const std::vector<std::string> keys = sectionKeys("");
  return keys;
}

SceneDesc readScene(const toml::table& table, const Origins& origins, Problems& problems,
                    const std::string& default_name) {
  return SceneReader(table, origins, problems).read(default_name);
}

}  // namespace collide::scene::detail
