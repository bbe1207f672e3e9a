#include "text/number_format.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace collide::text {
namespace {

constexpr int kMaxDecimals = 9;  // a scale below a nanounit is shown as 0 rather than as a string
                                 // of zeros
constexpr double kMaxSteps = 9.0e18;  // fits a long long
constexpr int kFigures = 3;           // significant figures of an amount
// Of a picture's largest value: below this share a value is round-off of zero (a body at rest
// after a chain of float operations, an elastic scene's "lost" energy).
constexpr double kRoundOffShare = 1e-9;
// Below 10^-kLowestExponent of its unit (a femto-unit) plain figures would need over fifteen
// zeros: a nonzero amount there reads in powers of ten ("1.00 × 10⁻³⁰⁰ kg"), never "0". Only
// where a format has no scale to call anything round-off (a typical of 0) does it read 0.
constexpr int kLowestExponent = 15;
// In a shared unit an amount keeps that unit down to a tenth of it (one zero after the decimal
// sign: "0.680 J"); below, it takes its own prefix ("2.00 J" in a kJ picture).
constexpr int kLowestSharedExponent = -1;

// Within this share of a value of halfway between two steps counts as halfway: round-off of a
// few float operations, and more.
constexpr double kHalfwayShare = 1e-9;

// The one rounding rule of every number a picture shows: to the nearest step, and a value
// halfway between two steps to the even one ("1.125 J" reads "1.12 J", "93.75 %" reads
// "93.8 %"), so parts rounded each on its own still add up to their rounded total. A value
// within round-off of halfway (1.4999999999999998 / 1.6 of a whole, 93.75 % computed) counts as
// halfway: the same quantity reads the same in every picture, however it was computed.
long long roundedSteps(double scaled) {
  const double below = std::floor(scaled);
  if (std::fabs(scaled - below - 0.5) <= kHalfwayShare * std::max(1.0, std::fabs(scaled))) {
    const auto low = static_cast<long long>(below);
    return low % 2 == 0 ? low : low + 1;
  }
  return std::llround(scaled);
}

// Decimal exponent of |value| after rounding to `significant` figures: 999.6 -> 3 (it shows as
// 1000), 0.0123 -> -2.
int roundedExponent(double value, int significant) {
  const double magnitude = std::fabs(value);
  int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
  const double scaled = magnitude / std::pow(10.0, exponent - significant + 1);
  if (static_cast<double>(roundedSteps(scaled)) >= std::pow(10.0, significant)) ++exponent;
  return exponent;
}

bool usable(double value) {
  return std::isfinite(value) && value != 0.0;
}

// Integer digits with the style's group separators: the lowest group of group_size digits, the
// higher ones of secondary_group_size (12,500; Hindi 12,34,567).
std::string grouped(const std::string& digits, const NumberStyle& style) {
  if (static_cast<int>(digits.size()) < style.group_from_digits) return digits;
  const std::size_t lowest = static_cast<std::size_t>(std::max(1, style.group_size));
  const std::size_t higher = static_cast<std::size_t>(std::max(1, style.secondary_group_size));
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    const std::size_t after = digits.size() - i;  // digits from here to the end
    if (i > 0 && after >= lowest && (after - lowest) % higher == 0) out += style.group_separator;
    out += digits[i];
  }
  return out;
}

// Zero as the style writes it, with `decimals` zeros after the decimal sign.
std::string zero(const NumberStyle& style, int decimals = 0) {
  std::string out = "0";
  if (decimals > 0)
    out += style.decimal_separator + std::string(static_cast<std::size_t>(decimals), '0');
  return withLocalDigits(out, style);
}

std::string nonFinite(double value) {
  return std::isnan(value) ? "not a number" : value > 0 ? "infinity" : "−infinity";
}

// SI prefixes by power of 1000, from micro (-2) to giga (3).
constexpr std::array<const char*, 6> kPrefixes = {"µ", "m", "", "k", "M", "G"};
constexpr int kLowestPrefixPower = -2;

bool prefixable(std::string_view unit) {
  return unit == "J" || unit == "N" || unit == "N·s" || unit == "W";
}

// The unit and decimals an amount of `magnitude` (> 0, base units) reads in: the format's unit
// with three figures, or its own prefix when it is far below that unit.
struct AmountFormat {
  std::string unit;
  double unit_value = 1.0;
  int decimals = 0;
  // The step of the last figure is 10^step_exponent base units (units are powers of ten).
  int step_exponent = 0;
};

AmountFormat amountFormat(double magnitude, const QuantityFormat& format) {
  const double in_unit = magnitude / format.unit_value;
  const int exponent = roundedExponent(in_unit, kFigures);
  const int unit_exponent = static_cast<int>(std::lround(std::log10(format.unit_value)));
  if (prefixable(format.base_unit) && exponent < kLowestSharedExponent) {
    const QuantityFormat own = quantityFormat(magnitude, format.base_unit, kFigures);
    const int own_exponent = static_cast<int>(std::lround(std::log10(own.unit_value)));
    const int decimals = kFigures - 1 - roundedExponent(magnitude / own.unit_value, kFigures);
    return {own.unit, own.unit_value, decimals, own_exponent - decimals};
  }
  const int decimals = kFigures - 1 - exponent;
  return {format.unit, format.unit_value, decimals, unit_exponent - decimals};
}

std::string withUnit(const std::string& number, const std::string& unit, const NumberStyle& style) {
  if (unit.empty()) return number;
  if (unit == "%") return style.percent_prefix + number + style.percent_suffix;
  return number + (unit == "°" ? "" : " ") + unit;
}

// Whether `magnitude` (> 0) of a unit needs more zeros after the decimal sign than a person reads.
bool belowPlainFigures(double magnitude) {
  return roundedExponent(magnitude, kFigures) < -kLowestExponent;
}

// "⁻³⁰⁰": an exponent in superscript figures.
std::string superscript(int exponent) {
  static constexpr std::array<const char*, 10> kDigits = {"⁰", "¹", "²", "³", "⁴",
                                                          "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = exponent < 0 ? "⁻" : "";
  for (char c : std::to_string(std::abs(exponent))) {
    out += kDigits[static_cast<std::size_t>(c - '0')];
  }
  return out;
}

// `value` (finite, nonzero) with three figures times a power of ten: "1.00 × 10⁻³⁰⁰".
std::string scientific(double value, const NumberStyle& style, Sign sign) {
  const int exponent = roundedExponent(value, kFigures);
  // Scaled in steps a double holds: 10^-320 itself is below the normal numbers.
  double mantissa = value;
  int left = exponent;
  for (; left < -200; left += 200) mantissa *= 1e200;
  for (; left > 200; left -= 200) mantissa /= 1e200;
  mantissa /= std::pow(10.0, left);
  const long long steps = std::llround(mantissa * std::pow(10.0, kFigures - 1));
  return formatScaled(steps, kFigures - 1, style, sign) + " × " + withLocalDigits("10", style) +
         superscript(exponent);
}

}  // namespace

std::string multiplicationSign(const NumberStyle& style) {
  const bool zero_is_a_dot =
      style.digits.size() == 10 && (style.digits[0] == "\u0660" || style.digits[0] == "\u06F0");
  return zero_is_a_dot ? "\u00D7" : "\u00B7";
}

std::string withLocalDigits(std::string_view ascii, const NumberStyle& style) {
  if (style.digits.size() != 10) return std::string(ascii);
  std::string out;
  for (char c : ascii) {
    if (c >= '0' && c <= '9') {
      out += style.digits[static_cast<std::size_t>(c - '0')];
    } else {
      out += c;
    }
  }
  return out;
}

QuantityFormat quantityFormat(double typical, std::string_view base_unit, int significant) {
  QuantityFormat format;
  format.unit = std::string(base_unit);
  format.base_unit = std::string(base_unit);
  format.zero_below = usable(typical) ? kRoundOffShare * std::fabs(typical) : 0.0;
  const int exponent = usable(typical) ? roundedExponent(typical, significant) : 0;
  int shown_exponent = exponent;
  if (prefixable(base_unit)) {
    const int power = std::clamp(static_cast<int>(std::floor(exponent / 3.0)), kLowestPrefixPower,
                                 kLowestPrefixPower + static_cast<int>(kPrefixes.size()) - 1);
    format.unit = kPrefixes[static_cast<std::size_t>(power - kLowestPrefixPower)] + format.unit;
    format.unit_value = std::pow(1000.0, power);
    shown_exponent = exponent - 3 * power;
  }
  format.decimals = std::min(significant - 1 - shown_exponent, kMaxDecimals);
  return format;
}

std::string formatScaled(long long steps, int decimals, const NumberStyle& style, Sign sign) {
  if (steps == 0) return zero(style);
  const bool negative = steps < 0;
  std::string digits = std::to_string(negative ? -steps : steps);
  if (decimals < 0) {  // steps of tens, hundreds...: 123 steps of 100 -> 12300
    digits.append(static_cast<std::size_t>(-decimals), '0');
    decimals = 0;
  }
  if (static_cast<int>(digits.size()) <= decimals) {
    digits.insert(0, static_cast<std::size_t>(decimals + 1 - static_cast<int>(digits.size())), '0');
  }
  const std::size_t integer_digits = digits.size() - static_cast<std::size_t>(decimals);
  std::string out = grouped(digits.substr(0, integer_digits), style);
  if (decimals > 0) out += style.decimal_separator + digits.substr(integer_digits);
  out = withLocalDigits(out, style);
  if (negative) return style.minus + out;
  return sign == Sign::kAlways ? style.plus + out : out;
}

bool readsZero(double value, const QuantityFormat& format) {
  if (!std::isfinite(value)) return false;
  const double magnitude = std::fabs(value);
  if (magnitude == 0.0 || magnitude < format.zero_below) return true;
  return format.zero_below == 0.0 && belowPlainFigures(magnitude / format.unit_value);
}

std::string formatIn(double value, const QuantityFormat& format, const NumberStyle& style,
                     Sign sign) {
  if (!std::isfinite(value)) return nonFinite(value);
  if (readsZero(value, format)) return zero(style);
  const double in_unit = value / format.unit_value;
  if (belowPlainFigures(std::fabs(in_unit))) return scientific(in_unit, style, sign);
  const int decimals = kFigures - 1 - roundedExponent(in_unit, kFigures);
  return formatScaled(roundedSteps(in_unit * std::pow(10.0, decimals)), decimals, style, sign);
}

std::pair<std::string, std::string> componentsIn(double x, double y, const QuantityFormat& format,
                                                 const NumberStyle& style) {
  // Only the smaller component can fall below the other's last figure; a partner that reads 0
  // or in powers of ten (no last figure on a decimal scale) keeps its partner as it is.
  const double big = std::max(std::fabs(x), std::fabs(y)) / format.unit_value;
  const bool scaled =
      std::isfinite(big) && !readsZero(big * format.unit_value, format) && !belowPlainFigures(big);
  const double half_step =
      scaled ? 0.5 * std::pow(10.0, roundedExponent(big, kFigures) - kFigures + 1) : 0.0;
  const auto component = [&](double value) {
    return std::fabs(value) / format.unit_value < half_step ? zero(style)
                                                            : formatIn(value, format, style);
  };
  return {component(x), component(y)};
}

std::string formatComponentsIn(double x, double y, const QuantityFormat& format,
                               const NumberStyle& style) {
  const auto [shown_x, shown_y] = componentsIn(x, y, format, style);
  return numberPair(shown_x, shown_y, style);
}

std::string formatQuantity(double value, const QuantityFormat& format, const NumberStyle& style,
                           Sign sign) {
  if (!std::isfinite(value)) return withUnit(nonFinite(value), format.unit, style);
  if (readsZero(value, format)) return withUnit(zero(style), format.unit, style);
  if (belowPlainFigures(std::fabs(value))) {  // in the base unit: no prefix reaches so low
    return withUnit(scientific(value, style, sign), format.base_unit, style);
  }
  const AmountFormat shown = amountFormat(std::fabs(value), format);
  const long long steps = roundedSteps(value / shown.unit_value * std::pow(10.0, shown.decimals));
  return withUnit(formatScaled(steps, shown.decimals, style, sign), shown.unit, style);
}

std::string formatReading(double value, const QuantityFormat& format, const NumberStyle& style,
                          Sign sign) {
  if (!std::isfinite(value)) return withUnit(nonFinite(value), format.unit, style);
  const int decimals = format.decimals;
  if (readsZero(value, format)) return withUnit(zero(style, decimals), format.unit, style);
  double scaled = value / format.unit_value * std::pow(10.0, decimals);
  int shown_decimals = decimals;
  // Beyond what a long long holds: coarser steps (such a value has more digits than it needs).
  while (std::fabs(scaled) >= kMaxSteps) {
    --shown_decimals;
    scaled /= 10.0;
  }
  const long long steps = roundedSteps(scaled);
  // Too small for the scale's decimals, yet not zero: three figures of its own, never "0.00".
  if (steps == 0) return formatQuantity(value, format, style, sign);
  return withUnit(formatScaled(steps, shown_decimals, style, sign), format.unit, style);
}

std::string formatValue(double value, std::string_view base_unit, const NumberStyle& style,
                        Sign sign) {
  return formatQuantity(value, quantityFormat(std::fabs(value), base_unit), style, sign);
}

std::string formatPlain(double value, const NumberStyle& style, int significant) {
  if (!std::isfinite(value)) return nonFinite(value);
  if (value == 0.0) return zero(style);
  const int exponent = roundedExponent(value, significant);
  const int decimals = significant - 1 - exponent;
  if (decimals > kMaxDecimals + 6) return scientific(value, style, Sign::kNegativeOnly);
  long long steps = 0;
  int shown_decimals = std::max(decimals, 0);
  if (decimals >= 0) {
    steps = roundedSteps(value * std::pow(10.0, decimals));
  } else {
    // Round to 10^-decimals, then write the integer: 123456 -> 123,000.
    const double unit = std::pow(10.0, -decimals);
    const double rounded = static_cast<double>(roundedSteps(value / unit)) * unit;
    if (std::fabs(rounded) >= kMaxSteps) {
      char text[64];
      std::snprintf(text, sizeof text, "%.0f", std::fabs(rounded));
      return (rounded < 0 ? style.minus : "") + withLocalDigits(grouped(text, style), style);
    }
    steps = roundedSteps(rounded);
  }
  // Drop trailing zeros after the decimal sign where the number is exactly the value (one typed
  // as 0.5 reads "0.5"); a computed value keeps its figures (0.09798 reads "0.0980", not "0.098").
  const double shown = static_cast<double>(steps) / std::pow(10.0, shown_decimals);
  const bool exact = decimals >= 0 && std::fabs(shown - value) <= 1e-9 * std::fabs(value);
  while (exact && shown_decimals > 0 && steps % 10 == 0) {
    steps /= 10;
    --shown_decimals;
  }
  return formatScaled(steps, shown_decimals, style);
}

std::string formatAngle(double degrees, const NumberStyle& style) {
  if (!std::isfinite(degrees)) return nonFinite(degrees);
  double whole = static_cast<double>(roundedSteps(std::fmod(degrees, 360.0)));
  if (whole <= -180.0) whole += 360.0;
  if (whole > 180.0) whole -= 360.0;
  return formatScaled(static_cast<long long>(whole), 0, style) + "°";
}

namespace {

// One part of a sum as formatParts shows it.
struct ShownPart {
  double value = 0.0;        // >= 0, base units
  AmountFormat shown;        // unit and decimals of its own three figures
  long long steps = 0;       // of its last figure, as shown
  double exact_steps = 0.0;  // value in those steps, unrounded
  bool counted = false;      // takes part in the sum (not zero, not below the finest step counted)
  bool steady = false;       // moved last (formatParts' `steady`)
};

// The parts each with three figures of its own; `finest` comes down to the finest last figure
// among the counted parts. A part more than kMaxSpan decades finer than the total's last figure
// cannot move its rounding.
std::vector<ShownPart> shownParts(const std::vector<double>& parts, bool total_zero,
                                  const AmountFormat& total_shown, const QuantityFormat& format,
                                  int& finest) {
  constexpr int kMaxSpan = 14;
  std::vector<ShownPart> shown(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    ShownPart& part = shown[i];
    part.value = std::isfinite(parts[i]) ? std::max(0.0, parts[i]) : 0.0;
    if (total_zero || readsZero(part.value, format)) continue;
    part.shown = amountFormat(part.value, format);
    part.exact_steps = part.value / part.shown.unit_value * std::pow(10.0, part.shown.decimals);
    part.steps = roundedSteps(part.exact_steps);
    part.counted = total_shown.step_exponent - part.shown.step_exponent <= kMaxSpan;
    if (part.counted) finest = std::min(finest, part.shown.step_exponent);
  }
  return shown;
}

// One step of 10^exponent in steps of 10^finest.
long long stepsOf(int exponent, int finest) {
  long long w = 1;
  for (int k = finest; k < exponent; ++k) w *= 10;
  return w;
}

// The sum of the parts as shown, in integer steps of the finest last figure, made to read as
// the total (`target` steps of `total_weight` finest steps): parts rounded the other way move
// one step each, those nearest to the other rounding first.
class SumToTotal {
 public:
  SumToTotal(std::vector<ShownPart>& shown, long long target, long long total_weight, int finest)
      : shown_(shown), target_(target), total_weight_(total_weight), finest_(finest) {}

  void adjust() {
    long long sum = 0;
    for (const ShownPart& part : shown_) sum += part.counted ? part.steps * weight(part) : 0;
    if (reads(sum)) return;
    const int direction = roundsTo(sum) < target_ ? 1 : -1;
    for (std::size_t i : roundedTheOtherWay(direction)) {
      const long long moved = sum + direction * weight(shown_[i]);
      const bool beyond = direction > 0 ? roundsTo(moved) > target_ : roundsTo(moved) < target_;
      if (reads(moved) || !beyond) {
        shown_[i].steps += direction;
        sum = moved;
      }
      if (reads(sum)) break;
    }
  }

 private:
  long long weight(const ShownPart& part) const {  // one step of the part, in finest steps
    return stepsOf(part.shown.step_exponent, finest_);
  }
  // The sum `s` (>= 0, in finest steps) in steps of the total's last figure, rounded as every
  // number is (halfway to the even step: roundedSteps), in whole numbers.
  long long roundsTo(long long s) const {
    const long long q = s / total_weight_, twice_rest = 2 * (s - q * total_weight_);
    if (twice_rest != total_weight_) return twice_rest < total_weight_ ? q : q + 1;
    return q % 2 == 0 ? q : q + 1;
  }
  // The sum reads as the total when it rounds to it.
  bool reads(long long s) const { return roundsTo(s) == target_; }
  // The counted parts rounded against `direction`, those nearest to the other rounding first.
  // Not a part exactly halfway (within round-off): it reads as the one rule rounds it in every
  // picture (1.125 J is 1.12 J beside 0.250 J of 1.38 J too), even where the sum then misses.
  std::vector<std::size_t> roundedTheOtherWay(int direction) const {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < shown_.size(); ++i) {
      const ShownPart& part = shown_[i];
      const double off = part.exact_steps - static_cast<double>(part.steps);
      if (std::fabs(std::fabs(off) - 0.5) <= kHalfwayShare * std::max(1.0, part.exact_steps))
        continue;
      if (part.counted && (direction > 0 ? off > 0.0 : off < 0.0)) order.push_back(i);
    }
    const auto gap = [&](std::size_t i) {
      return 1.0 - std::fabs(shown_[i].exact_steps - static_cast<double>(shown_[i].steps));
    };
    // Steady parts last; among the others, and among those, nearest the other rounding first.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (shown_[a].steady != shown_[b].steady) return shown_[b].steady;
      return gap(a) < gap(b);
    });
    return order;
  }

  std::vector<ShownPart>& shown_;
  const long long target_, total_weight_;
  const int finest_;
};

// A part as shown: its own figures, or powers of ten below a femto-unit.
std::string partText(const ShownPart& part, const QuantityFormat& format,
                     const NumberStyle& style) {
  if (part.steps == 0) return withUnit(zero(style), format.unit, style);
  if (belowPlainFigures(part.value)) {
    return withUnit(scientific(part.value, style, Sign::kNegativeOnly), format.base_unit, style);
  }
  return withUnit(formatScaled(part.steps, part.shown.decimals, style), part.shown.unit, style);
}

}  // namespace

std::vector<std::string> formatParts(const std::vector<double>& parts, double total,
                                     const QuantityFormat& format, const NumberStyle& style,
                                     const std::vector<bool>& steady) {
  const bool total_zero = !std::isfinite(total) || readsZero(total, format);
  const AmountFormat total_shown =
      total_zero ? AmountFormat{format.unit, format.unit_value, 0, 0} : amountFormat(total, format);
  // The sum is kept in integer steps of the finest last figure among the counted parts.
  int finest = total_shown.step_exponent;
  std::vector<ShownPart> shown = shownParts(parts, total_zero, total_shown, format, finest);
  for (std::size_t i = 0; i < shown.size() && i < steady.size(); ++i) shown[i].steady = steady[i];
  if (!total_zero) {
    const long long target =
        roundedSteps(total / total_shown.unit_value * std::pow(10.0, total_shown.decimals));
    SumToTotal(shown, target, stepsOf(total_shown.step_exponent, finest), finest).adjust();
  }
  std::vector<std::string> out;
  for (const ShownPart& part : shown) out.push_back(partText(part, format, style));
  return out;
}

}  // namespace collide::text
