// SPDX-License-Identifier: MIT
#include "scene/units.hpp"

#include <udunits2.h>

#include <memory>
#include <mutex>

namespace collide::scene::detail {
namespace {

// Every kind with units, in the order a unit of the wrong kind is looked for.
constexpr Quantity kKinds[] = {
    Quantity::kMass,       Quantity::kLength,        Quantity::kTime,
    Quantity::kSpeed,      Quantity::kAcceleration,  Quantity::kFrequency,
    Quantity::kLinearDrag, Quantity::kQuadraticDrag, Quantity::kAngle};

// How UDUNITS-2 spells the base unit of each kind (angles: a bare number is degrees).
const char* baseSpelling(Quantity kind) {
  switch (kind) {
    case Quantity::kMass:
      return "kg";
    case Quantity::kLength:
      return "m";
    case Quantity::kTime:
      return "s";
    case Quantity::kSpeed:
      return "m/s";
    case Quantity::kAcceleration:
      return "m/s^2";
    case Quantity::kAngle:
      return "degree";
    case Quantity::kFrequency:
      return "Hz";
    case Quantity::kLinearDrag:
      return "kg/s";
    case Quantity::kQuadraticDrag:
      return "kg/m";
    case Quantity::kNumber:
      break;
  }
  return "1";
}

// Spellings UDUNITS-2 lacks or reads as something else ("mph" is a milliphot there).
std::string udunitsSpelling(const std::string& unit) {
  if (unit == "deg" || unit == "degrees" || unit == "\u00B0") return "degree";
  if (unit == "mph") return "mi/h";
  if (unit == "kph") return "km/h";
  return unit;
}

struct UnitFree {
  void operator()(ut_unit* unit) const { ut_free(unit); }
};
using UnitPtr = std::unique_ptr<ut_unit, UnitFree>;

// The UDUNITS-2 database, read once; UDUNITS-2's parser keeps global state, so every use holds
// the lock.
class UnitSystem {
 public:
  static UnitSystem& instance() {
    static UnitSystem system;
    return system;
  }
  std::mutex& lock() { return mutex_; }
  bool ready() const { return system_ != nullptr; }

  UnitPtr parse(const std::string& text) const {
    const std::string spelled = udunitsSpelling(text);
    return UnitPtr(ut_parse(system_, spelled.c_str(), UT_UTF8));
  }

 private:
  UnitSystem() {
    ut_set_error_message_handler(ut_ignore);  // problems are reported as scene problems
    system_ = ut_read_xml(nullptr);
  }
  ut_system* system_ = nullptr;  // held for the life of the program
  std::mutex mutex_;
};

// The allowed unit of `kind` that `unit` is, if any.
bool isAllowed(const UnitSystem& system, const ut_unit* unit, Quantity kind) {
  for (const std::string& name : allowedUnits(kind)) {
    const UnitPtr allowed = system.parse(name);
    if (allowed && ut_compare(allowed.get(), unit) == 0) return true;
  }
  return false;
}

// The kind `unit` measures: an allowed unit of a kind first, then any unit convertible to a
// kind's base (a dimensionless one counts as an angle).
std::optional<Quantity> kindOf(const UnitSystem& system, const ut_unit* unit) {
  for (const Quantity kind : kKinds) {
    if (isAllowed(system, unit, kind)) return kind;
  }
  for (const Quantity kind : kKinds) {
    const UnitPtr base = system.parse(baseSpelling(kind));
    if (base && ut_are_convertible(base.get(), unit) != 0) return kind;
  }
  return std::nullopt;
}

std::string allowedText(Quantity kind) {
  if (kind == Quantity::kNumber) return "; allowed: " + quantityName(kind);
  return "; allowed: " + quantityName(kind) + " in " + quantityUnits(kind);
}

UnitConversion wrongUnit(const UnitSystem& system, const ut_unit* unit, const std::string& text,
                         Quantity kind) {
  UnitConversion result;
  result.is_unit = true;
  const std::optional<Quantity> found = kindOf(system, unit);
  if (!found) {
    result.problem = "'" + text + "' is a unit of no quantity a scene holds" + allowedText(kind);
  } else if (*found == kind) {
    result.problem = "'" + text + "' is not one of the units collide takes" + allowedText(kind);
  } else {
    result.problem = quantityName(*found) + ", not " + quantityName(kind) + allowedText(kind);
  }
  return result;
}

}  // namespace

const std::vector<std::string>& allowedUnits(Quantity kind) {
  static const std::vector<std::string> kNone;
  static const std::vector<std::string> kMass = {"kg", "g", "mg", "t", "lb"};
  static const std::vector<std::string> kLength = {"m", "km", "cm", "mm", "ft", "in", "mi"};
  static const std::vector<std::string> kTime = {"s", "ms", "min", "h"};
  static const std::vector<std::string> kSpeed = {"m/s", "km/h", "cm/s", "mm/s", "ft/s", "mph"};
  static const std::vector<std::string> kAcceleration = {"m/s^2", "cm/s^2", "ft/s^2"};
  static const std::vector<std::string> kAngle = {"deg", "rad"};
  static const std::vector<std::string> kFrequency = {"Hz"};
  static const std::vector<std::string> kLinearDrag = {"kg/s", "g/s"};
  static const std::vector<std::string> kQuadraticDrag = {"kg/m", "g/m"};
  switch (kind) {
    case Quantity::kMass:
      return kMass;
    case Quantity::kLength:
      return kLength;
    case Quantity::kTime:
      return kTime;
    case Quantity::kSpeed:
      return kSpeed;
    case Quantity::kAcceleration:
      return kAcceleration;
    case Quantity::kAngle:
      return kAngle;
    case Quantity::kFrequency:
      return kFrequency;
    case Quantity::kLinearDrag:
      return kLinearDrag;
    case Quantity::kQuadraticDrag:
      return kQuadraticDrag;
    case Quantity::kNumber:
      break;
  }
  return kNone;
}

UnitConversion convertToBase(double value, const std::string& unit, Quantity kind) {
  UnitSystem& system = UnitSystem::instance();
  const std::lock_guard<std::mutex> hold(system.lock());
  UnitConversion result;
  if (!system.ready()) {
    result.problem = "units cannot be read (the UDUNITS-2 database is missing)";
    return result;
  }
  const UnitPtr parsed = system.parse(unit);
  if (!parsed) return result;
  if (kind == Quantity::kNumber || !isAllowed(system, parsed.get(), kind)) {
    return wrongUnit(system, parsed.get(), unit, kind);
  }
  const UnitPtr base = system.parse(baseSpelling(kind));
  cv_converter* converter = ut_get_converter(parsed.get(), base.get());
  result.is_unit = true;
  result.value = cv_convert_double(converter, value);
  cv_free(converter);
  return result;
}

}  // namespace collide::scene::detail
