// SPDX-License-Identifier: MIT
#pragma once
// Internal to collide_scene: every key of a scene file, per table, with its form, the kind of
// quantity a number measures and its limits. The reader takes its allowed keys (and the limits of
// the keys it reads through fieldRange) from here, and docs/scene.schema.json is generated from
// it (scene_schema.cpp), so the editor's schema and the reader cannot drift apart.
#include <string>
#include <vector>

#include "scene/fields.hpp"

namespace collide::scene::detail {

enum class FieldForm {
  kNumber,            // a number or a quoted quantity
  kInteger,           // a whole number
  kVector,            // 1D: a number or [x, 0]; 2D: [x, y]; components numbers or quantities
  kText,              // a string
  kChoice,            // one of `choices`
  kFlag,              // true or false
  kColor,             // "#rrggbb" or [r, g, b]
  kHeading,           // a number, an angle or compass words
  kBodyRef,           // a body's number from 1 or its name
  kBodyPair,          // [a, b], each a body's number or name
  kChart,             // true, false or a chart's name
  kPanels,            // {parameter = "KEY", values = [...]}
  kLawTable,          // [[speed, e], ...]
  kLengthOrFraction,  // a fraction (number) or a quoted length
};

struct FieldSpec {
  std::string key;
  FieldForm form = FieldForm::kNumber;
  std::string description;  // one line, for editors
  Range range;              // kNumber, kVector (max as +-max), kInteger (min, max)
  std::vector<std::string> choices;
  std::size_t max_length = 0;  // kText
  std::string needs;           // a key this one is only read with ("length" needs "pivot")
};

// The tables of a scene file: "" (top level), "body", "wall", "box", "pair", "restitution_law",
// "contact", "view"; "body", "wall" and "pair" are arrays of tables.
struct SectionSpec {
  std::string name;
  bool array_of_tables = false;
  std::vector<FieldSpec> fields;
};

const std::vector<SectionSpec>& sceneSections();

// The keys of one section, in order (sub-tables of the top level included).
std::vector<std::string> sectionKeys(const std::string& section);

// The range of a number key, from the table; throws std::logic_error for a key not in it.
const Range& fieldRange(const std::string& section, const std::string& key);

// e of a pair or wall: 0 to 1, or to kMaxSuperElasticRestitution where the scene opted in with
// super_elastic = true (the range without it says how to opt in).
Range restitutionRange(bool super_elastic);

}  // namespace collide::scene::detail
