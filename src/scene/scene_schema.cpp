// SPDX-License-Identifier: MIT
// docs/scene.schema.json, made from the field table the reader uses (field_table.hpp), so that an
// editor with a JSON Schema for TOML (Taplo, Even Better TOML) completes keys, shows what each
// means and marks a value the reader would refuse where a schema can tell.
#include <sstream>

#include "scene/field_table.hpp"
#include "scene/scene_io.hpp"
#include "scene/units.hpp"

namespace collide::scene {
namespace detail {
namespace {

// A JSON value under construction: an object's members keep their order.
struct Json {
  enum class Type { kObject, kArray, kRaw } type = Type::kRaw;
  // An object's keys and values, in order (two vectors: std::vector, unlike std::pair, may hold
  // the type being defined).
  std::vector<std::string> keys;
  std::vector<Json> values;
  std::vector<Json> items;
  std::string raw;  // the JSON text of a string, number or boolean

  Json& set(const std::string& key, Json value) {
    keys.push_back(key);
    values.push_back(std::move(value));
    return *this;
  }
};

Json object() {
  return Json{Json::Type::kObject, {}, {}, {}, ""};
}

Json array(std::vector<Json> items) {
  return Json{Json::Type::kArray, {}, {}, std::move(items), ""};
}

Json string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return Json{Json::Type::kRaw, {}, {}, {}, quoted + "\""};
}

Json number(double value) {
  return Json{Json::Type::kRaw, {}, {}, {}, plainNumber(value)};
}

Json boolean(bool value) {
  return Json{Json::Type::kRaw, {}, {}, {}, value ? "true" : "false"};
}

Json typed(const std::string& type) {
  return object().set("type", string(type));
}

Json anyOf(std::vector<Json> options) {
  return object().set("anyOf", array(std::move(options)));
}

Json strings(const std::vector<std::string>& words) {
  std::vector<Json> items;
  for (const std::string& word : words) items.push_back(string(word));
  return array(std::move(items));
}

void write(std::ostream& out, const Json& value, int indent) {
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  if (value.type == Json::Type::kRaw) {
    out << value.raw;
  } else if (value.type == Json::Type::kArray) {
    out << "[";
    for (std::size_t i = 0; i < value.items.size(); ++i) {
      out << (i > 0 ? ", " : "");
      write(out, value.items[i], indent);
    }
    out << "]";
  } else {
    out << "{\n";
    for (std::size_t i = 0; i < value.keys.size(); ++i) {
      out << pad << "\"" << value.keys[i] << "\": ";
      write(out, value.values[i], indent + 2);
      out << (i + 1 < value.keys.size() ? ",\n" : "\n");
    }
    out << std::string(static_cast<std::size_t>(indent), ' ') << "}";
  }
}

// A regular expression's literal text.
std::string escaped(const std::string& text) {
  std::string result;
  for (const char c : text) {
    if (std::string("\\^$.|?*+()[]{}/-").find(c) != std::string::npos) result += '\\';
    result += c;
  }
  return result;
}

// What readQuantity takes for `kind`, as far as a pattern can tell: arithmetic made of numbers,
// operators and muParser's names, then one of the kind's units (the spellings docs list).
std::string quantityPattern(Quantity kind) {
  std::string pattern =
      "^\\s*(?:[0-9.eE+\\-*/^(),\\s]|pi|sqrt|sinh|cosh|tanh|asin|acos|atan|sin|cos|tan|exp|"
      "log10|log2|ln|log|abs|sign|rint|min|max)+";
  std::vector<std::string> units = allowedUnits(kind);
  if (kind == Quantity::kAngle) {
    for (const char* alias : {"degrees", "degree", "\u00B0"}) units.emplace_back(alias);
  }
  if (!units.empty()) {
    pattern += "(?:\\s*(?:";
    for (std::size_t i = 0; i < units.size(); ++i) {
      if (i > 0) pattern += '|';
      pattern += escaped(units[i]);
    }
    pattern += "))?";
  }
  return pattern + "\\s*$";
}

std::string describe(const FieldSpec& field) {
  std::string text = field.description;
  const std::string unit = quantityBaseUnit(field.range.kind);
  if (!unit.empty()) {
    text += (text.empty() ? "" : "; ") + std::string("a number in ") + unit + " or a quoted " +
            "value with a unit: " + quantityUnits(field.range.kind);
  }
  return text;
}

Json numberSchema(const Range& range) {
  Json plain = typed("number");
  plain.set(range.min_open ? "exclusiveMinimum" : "minimum", number(range.min));
  plain.set("maximum", number(range.max));
  Json quoted = typed("string");
  quoted.set("pattern", string(quantityPattern(range.kind)));
  return anyOf({plain, quoted});
}

Json vectorSchema(const Range& range) {
  const Json component = numberSchema(range);
  Json pair = typed("array");
  pair.set("items", component).set("minItems", number(2)).set("maxItems", number(2));
  return anyOf({component, pair});
}

Json bodyRef() {
  Json index = typed("integer");
  index.set("minimum", number(1));
  Json name = typed("string");
  name.set("minLength", number(1));
  return anyOf({index, name});
}

Json panels() {
  Json parameter = typed("string");
  parameter.set("minLength", number(1));
  Json values = typed("array");
  values.set("items", typed("number")).set("minItems", number(1)).set("maxItems", number(6));
  Json result = typed("object");
  result.set("properties", object().set("parameter", parameter).set("values", values));
  result.set("required", strings({"parameter", "values"}));
  return result.set("additionalProperties", boolean(false));
}

Json lawTable() {
  Json point = typed("array");
  point.set("items", typed("number")).set("minItems", number(2)).set("maxItems", number(2));
  Json table = typed("array");
  return table.set("items", point).set("minItems", number(1)).set("maxItems", number(100));
}

Json colorSchema() {
  Json hex = typed("string");
  hex.set("pattern", string("^#[0-9a-fA-F]{6}$"));
  Json channel = typed("integer");
  channel.set("minimum", number(0)).set("maximum", number(255));
  Json rgb = typed("array");
  rgb.set("items", channel).set("minItems", number(3)).set("maxItems", number(3));
  return anyOf({hex, rgb});
}

Json fractionOrLength() {
  Json fraction = typed("number");
  fraction.set("minimum", number(-1)).set("maximum", number(1));
  Json length = typed("string");
  length.set("pattern", string(quantityPattern(Quantity::kLength)));
  return anyOf({fraction, length});
}

Json choiceOrFlag(const FieldSpec& field) {
  return anyOf({typed("boolean"), object().set("enum", strings(field.choices))});
}

Json fieldSchema(const FieldSpec& field) {
  switch (field.form) {
    case FieldForm::kNumber:
      return numberSchema(field.range);
    case FieldForm::kInteger:
      return typed("integer")
          .set("minimum", number(field.range.min))
          .set("maximum", number(field.range.max));
    case FieldForm::kVector:
      return vectorSchema(field.range);
    case FieldForm::kText:
      return typed("string").set("maxLength", number(static_cast<double>(field.max_length)));
    case FieldForm::kChoice:
      return object().set("enum", strings(field.choices));
    case FieldForm::kFlag:
      return typed("boolean");
    case FieldForm::kColor:
      return colorSchema();
    case FieldForm::kHeading:
      return anyOf({typed("number"), typed("string")});
    case FieldForm::kBodyRef:
      return bodyRef();
    case FieldForm::kBodyPair:
      return typed("array")
          .set("items", bodyRef())
          .set("minItems", number(2))
          .set("maxItems", number(2));
    case FieldForm::kChart:
      return choiceOrFlag(field);
    case FieldForm::kPanels:
      return panels();
    case FieldForm::kLawTable:
      return lawTable();
    case FieldForm::kLengthOrFraction:
      return fractionOrLength();
  }
  return object();
}

const SectionSpec& section(const std::string& name) {
  for (const SectionSpec& spec : sceneSections()) {
    if (spec.name == name) return spec;
  }
  return sceneSections().front();
}

bool isSection(const std::string& key) {
  for (const SectionSpec& spec : sceneSections()) {
    if (!spec.name.empty() && spec.name == key) return true;
  }
  return false;
}

// One table's keys: each key's schema with its description; no other keys.
Json tableSchema(const SectionSpec& spec, const std::vector<std::string>& required) {
  Json properties = object();
  for (const FieldSpec& field : spec.fields) {
    if (spec.name.empty() && isSection(field.key)) continue;
    Json schema = fieldSchema(field);
    if (const std::string text = describe(field); !text.empty()) {
      schema.set("description", string(text));
    }
    properties.set(field.key, schema);
  }
  Json table = typed("object");
  table.set("properties", properties);
  if (!required.empty()) table.set("required", strings(required));
  Json needs = object();
  for (const FieldSpec& field : spec.fields) {
    if (!field.needs.empty()) needs.set(field.key, strings({field.needs}));
  }
  if (!needs.keys.empty()) table.set("dependencies", needs);
  return table.set("additionalProperties", boolean(false));
}

Json sectionSchema(const std::string& name, int max_items) {
  const SectionSpec& spec = section(name);
  Json table = tableSchema(spec, name == "body"              ? std::vector<std::string>{"mass"}
                                 : name == "restitution_law" ? std::vector<std::string>{"kind"}
                                                             : std::vector<std::string>{});
  if (!spec.array_of_tables) return table;
  Json list = typed("array");
  list.set("items", table);
  if (max_items > 0) list.set("maxItems", number(max_items));
  if (name == "body") list.set("minItems", number(1));
  return list;
}

// The preset a file starts from, and the parameters presets take.
void addPresetKeys(Json& properties) {
  std::vector<std::string> names;
  for (const PresetInfo& info : presetList()) names.push_back(info.name);
  properties.set("preset", object()
                               .set("enum", strings(names))
                               .set("description", string("start from this preset; the file then "
                                                          "changes it")));
  for (const PresetInfo& info : presetList()) {
    for (const PresetParameter& p : info.parameters) {
      Json parameter = typed(p.integer ? "integer" : "number");
      parameter.set("minimum", number(p.min)).set("maximum", number(p.max));
      parameter.set("description", string("with preset = \"" + info.name + "\": " + p.description));
      properties.set(p.name, parameter);
    }
  }
}

Json required(const std::vector<std::string>& keys) {
  return object().set("required", strings(keys));
}

// Rules across keys that a schema can state: a string hangs only in a 2D scene, and only with
// gravity pulling down (a file that starts from a preset may take both from it); e above 1 needs
// super_elastic = true.
Json crossKeyRules() {
  Json two_d = object();
  two_d.set("properties", object().set("dimensions", object().set("const", number(2))));
  two_d.set("required", strings({"dimensions"}));
  Json no_pivot = object().set("not", required({"pivot"}));
  Json planar = object();
  planar.set("if", object().set("not", anyOf({required({"preset"}), two_d})));
  planar.set("then",
             object().set("properties", object().set("body", object().set("items", no_pivot))));
  Json downwards = anyOf({typed("number").set("exclusiveMaximum", number(0)), typed("string")});
  Json gravity = typed("array").set("items", array({object(), downwards}));
  Json hanging = object();
  hanging.set("if", object()
                        .set("properties",
                             object().set("body", object().set("contains", required({"pivot"}))))
                        .set("required", strings({"body"})));
  hanging.set("then",
              anyOf({required({"preset"}),
                     required({"gravity"}).set("properties", object().set("gravity", gravity))}));
  // e above 1 (the scene's, as a number) only with super_elastic = true; a wall's or a pair's
  // e is collide check's.
  Json above_one = typed("number").set("exclusiveMinimum", number(1));
  Json super_elastic = object();
  super_elastic.set("if", object()
                              .set("properties", object().set("restitution", above_one))
                              .set("required", strings({"restitution"})));
  super_elastic.set(
      "then",
      required({"super_elastic"})
          .set("properties", object().set("super_elastic", object().set("const", boolean(true)))));
  return array({planar, hanging, super_elastic});
}

}  // namespace
}  // namespace detail

std::string sceneJsonSchema() {
  using namespace detail;
  Json root = tableSchema(section(""), {});
  Json& properties = root.values[1];  // after "type"
  properties.set("body", sectionSchema("body", kMaxBodies));
  properties.set("wall", sectionSchema("wall", kMaxWalls));
  properties.set("box", sectionSchema("box", 0));
  properties.set("pair", sectionSchema("pair", 0));
  properties.set("release", sectionSchema("release", 0));
  properties.set("restitution_law", sectionSchema("restitution_law", 0));
  properties.set("contact", sectionSchema("contact", 0));
  properties.set("view", sectionSchema("view", 0));
  addPresetKeys(properties);
  Json schema = object();
  schema.set("$schema", string("http://json-schema.org/draft-07/schema#"));
  schema.set("title", string("collide scene file (docs/scene-format.md)"));
  schema.set("description",
             string("Generated from src/scene/field_table.cpp by collide_scene_schema; do not "
                    "edit by hand."));
  for (std::size_t i = 0; i < root.keys.size(); ++i) schema.set(root.keys[i], root.values[i]);
  schema.set("anyOf", array({required({"body"}), required({"preset"})}));
  schema.set("allOf", crossKeyRules());
  std::ostringstream out;
  write(out, schema, 0);
  out << "\n";
  return out.str();
}

}  // namespace collide::scene
