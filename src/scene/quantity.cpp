// SPDX-License-Identifier: MIT
#include "scene/quantity.hpp"

#include <muParser.h>

#include <cctype>
#include <mutex>
#include <numbers>
#include <vector>

#include "scene/units.hpp"

namespace collide::scene::detail {
namespace {

constexpr std::size_t kMaxQuantityLength = 200;  // characters; a value, not a program

struct Evaluation {
  std::optional<double> value;
  std::string problem;  // muParser's message when it cannot read the text
};

// muParser arithmetic, evaluated once in double precision: numbers, + - * / ^, parentheses, pi,
// sqrt, sin, cos (radians) and the rest of muParser's functions; exactly one value.
Evaluation evaluate(const std::string& text) {
  static std::mutex mutex;  // muParser's parser tables are not documented thread-safe
  const std::lock_guard<std::mutex> hold(mutex);
  try {
    mu::Parser parser;
    parser.DefineConst("pi", std::numbers::pi);
    parser.SetExpr(text);
    int count = 0;
    const double* values = parser.Eval(count);
    if (count != 1) return {std::nullopt, "more than one value"};
    return {values[0], ""};
  } catch (const mu::Parser::exception_type& error) {
    std::string message = error.GetMsg();
    if (!message.empty() && message.back() == '.') message.pop_back();
    return {std::nullopt, message};
  }
}

std::string trimmed(const std::string& text) {
  const std::size_t a = text.find_first_not_of(" \t");
  const std::size_t b = text.find_last_not_of(" \t");
  return a == std::string::npos ? std::string() : text.substr(a, b - a + 1);
}

// Where the leading number ends in "25g" or "30°": the one place a unit may follow without a
// blank; npos when the text does not start with a number or a blank follows it.
std::size_t afterLeadingNumber(const std::string& text) {
  std::size_t i = text.find_first_not_of("+-");
  const std::size_t digits = text.find_first_not_of("0123456789.", i);
  if (i == std::string::npos || digits == i) return std::string::npos;
  i = digits;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    const std::size_t exponent = text.find_first_not_of("0123456789", i + 1 + (text[i + 1] == '-'));
    if (exponent != i + 1) i = exponent;
  }
  if (i == std::string::npos || i >= text.size() || text[i] == ' ' || text[i] == '\t') {
    return std::string::npos;
  }
  return i;
}

// Places the text may split into EXPR and UNIT, the longest EXPR first.
std::vector<std::size_t> splitPoints(const std::string& text) {
  std::vector<std::size_t> points;
  for (std::size_t i = text.size(); i-- > 1;) {
    if ((text[i - 1] == ' ' || text[i - 1] == '\t') && text[i] != ' ' && text[i] != '\t') {
      points.push_back(i);
    }
  }
  if (const std::size_t glued = afterLeadingNumber(text); glued != std::string::npos) {
    points.push_back(glued);
  }
  return points;
}

// A unit starts with a letter (or a degree or micro sign): "3 m" is no unit, so "2 3 m" is not 6 m.
bool startsLikeUnit(const std::string& unit) {
  const unsigned char first = static_cast<unsigned char>(unit.front());
  return std::isalpha(first) != 0 || first >= 0x80;
}

}  // namespace

std::string quantityName(Quantity kind) {
  switch (kind) {
    case Quantity::kMass:
      return "a mass";
    case Quantity::kLength:
      return "a length";
    case Quantity::kTime:
      return "a time";
    case Quantity::kSpeed:
      return "a velocity";
    case Quantity::kAcceleration:
      return "an acceleration";
    case Quantity::kAngle:
      return "an angle";
    case Quantity::kFrequency:
      return "a frequency";
    case Quantity::kLinearDrag:
      return "a linear drag coefficient";
    case Quantity::kQuadraticDrag:
      return "a quadratic drag coefficient";
    case Quantity::kNumber:
      break;
  }
  return "a number without a unit";
}

std::string quantityUnits(Quantity kind) {
  std::string text;
  const std::vector<std::string>& units = allowedUnits(kind);
  for (std::size_t i = 0; i < units.size(); ++i) text += (i > 0 ? ", " : "") + units[i];
  return text;
}

std::string quantityBaseUnit(Quantity kind) {
  if (kind == Quantity::kAngle) return "degrees";
  return allowedUnits(kind).empty() ? "" : allowedUnits(kind).front();
}

QuantityReading readQuantity(const std::string& typed, Quantity kind) {
  const std::string text = trimmed(typed);
  const std::string allowed = kind == Quantity::kNumber
                                  ? "; allowed: a number or arithmetic such as 2/3 or sqrt(3)/2"
                                  : "; allowed: a number in " + quantityBaseUnit(kind) +
                                        ", arithmetic such as 2/3, " +
                                        "either followed by a unit: " + quantityUnits(kind);
  if (text.empty()) return {std::nullopt, "empty" + allowed};
  if (text.size() > kMaxQuantityLength) return {std::nullopt, "too long" + allowed};
  const Evaluation whole = evaluate(text);
  if (whole.value) return {whole.value, ""};
  std::string unit_problem;
  for (const std::size_t at : splitPoints(text)) {
    const std::string unit = trimmed(text.substr(at));
    if (!startsLikeUnit(unit)) continue;
    const Evaluation number = evaluate(trimmed(text.substr(0, at)));
    if (!number.value) continue;
    const UnitConversion converted = convertToBase(*number.value, unit, kind);
    if (converted.value) return {converted.value, ""};
    if (!converted.problem.empty()) return {std::nullopt, converted.problem};
    if (unit_problem.empty()) unit_problem = "'" + unit + "' is not a unit" + allowed;
  }
  if (!unit_problem.empty()) return {std::nullopt, unit_problem};
  return {std::nullopt,
          "not a number, arithmetic or a quantity with a unit (" + whole.problem + ")" + allowed};
}

bool looksLikeQuantity(const std::string& text) {
  for (const Quantity kind :
       {Quantity::kNumber, Quantity::kMass, Quantity::kLength, Quantity::kTime, Quantity::kSpeed,
        Quantity::kAcceleration, Quantity::kAngle, Quantity::kFrequency, Quantity::kLinearDrag,
        Quantity::kQuadraticDrag}) {
    if (readQuantity(text, kind).value) return true;
  }
  return false;
}

}  // namespace collide::scene::detail
