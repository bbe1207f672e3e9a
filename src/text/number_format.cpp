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

// Decimal exponent of |value| after rounding to `significant` figures: 999.6 -> 3 (it shows as
// 1000), 0.0123 -> -2.
int roundedExponent(double value, int significant) {
  const double magnitude = std::fabs(value);
  int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
  const double scaled = magnitude / std::pow(10.0, exponent - significant + 1);
  if (std::round(scaled) >= std::pow(10.0, significant)) ++exponent;
  return exponent;
}

bool usable(double value) {
  return std::isfinite(value) && value != 0.0;
}

std::string grouped(const std::string& digits, const NumberStyle& style) {
  if (static_cast<int>(digits.size()) < style.group_from_digits) return digits;
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += style.group_separator;
    out += digits[i];
  }
  return out;
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

}  // namespace

const NumberStyle& defaultStyle() {
  static const NumberStyle english;
  return english;
}

QuantityFormat quantityFormat(double typical, std::string_view base_unit, int significant) {
  QuantityFormat format;
  format.unit = std::string(base_unit);
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
  if (steps == 0) return "0";
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
  if (negative) return style.minus + out;
  return sign == Sign::kAlways ? "+" + out : out;
}

std::string formatIn(double value, const QuantityFormat& format, const NumberStyle& style,
                     Sign sign) {
  if (!std::isfinite(value)) return nonFinite(value);
  int decimals = format.decimals;
  double scaled = value / format.unit_value * std::pow(10.0, decimals);
  // Beyond what a long long holds: coarser steps (such a value has more digits than it needs).
  while (std::fabs(scaled) >= kMaxSteps) {
    --decimals;
    scaled /= 10.0;
  }
  return formatScaled(std::llround(scaled), decimals, style, sign);
}

std::string formatQuantity(double value, const QuantityFormat& format, const NumberStyle& style,
                           Sign sign) {
  const std::string number = formatIn(value, format, style, sign);
  if (format.unit.empty()) return number;
  const bool attached = format.unit == "°" || format.unit == "%";
  return number + (attached ? "" : " ") + format.unit;
}

std::string formatValue(double value, std::string_view base_unit, const NumberStyle& style,
                        Sign sign) {
  return formatQuantity(value, quantityFormat(std::fabs(value), base_unit), style, sign);
}

std::string formatPlain(double value, const NumberStyle& style, int significant) {
  if (!std::isfinite(value)) return nonFinite(value);
  if (value == 0.0) return "0";
  const int exponent = roundedExponent(value, significant);
  const int decimals = significant - 1 - exponent;
  if (decimals > kMaxDecimals + 6) return "0";  // below a femto-unit: nothing to read
  long long steps = 0;
  int shown_decimals = std::max(decimals, 0);
  if (decimals >= 0) {
    steps = std::llround(value * std::pow(10.0, decimals));
  } else {
    // Round to 10^-decimals, then write the integer: 123456 -> 123,000.
    const double unit = std::pow(10.0, -decimals);
    const double rounded = std::round(value / unit) * unit;
    if (std::fabs(rounded) >= kMaxSteps) {
      char text[64];
      std::snprintf(text, sizeof text, "%.0f", std::fabs(rounded));
      return (rounded < 0 ? style.minus : "") + grouped(text, style);
    }
    steps = std::llround(rounded);
  }
  // Drop trailing zeros after the decimal sign: 0.500 -> 0.5.
  while (shown_decimals > 0 && steps % 10 == 0) {
    steps /= 10;
    --shown_decimals;
  }
  return formatScaled(steps, shown_decimals, style);
}

std::string formatAngle(double degrees, const NumberStyle& style) {
  if (!std::isfinite(degrees)) return nonFinite(degrees);
  double whole = std::round(std::fmod(degrees, 360.0));
  if (whole <= -180.0) whole += 360.0;
  if (whole > 180.0) whole -= 360.0;
  return formatScaled(static_cast<long long>(whole), 0, style) + "°";
}

std::vector<long long> roundedParts(const std::vector<double>& parts, int decimals) {
  const double unit = std::pow(10.0, decimals);
  std::vector<long long> rounded(parts.size());
  std::vector<double> remainder(parts.size());
  double sum = 0.0;
  long long floors = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double scaled = std::max(0.0, parts[i]) * unit;
    sum += scaled;
    rounded[i] = static_cast<long long>(std::floor(scaled));
    remainder[i] = scaled - static_cast<double>(rounded[i]);
    floors += rounded[i];
  }
  long long missing = std::llround(sum) - floors;
  std::vector<std::size_t> order(parts.size());
  std::iota(order.begin(), order.end(), 0);
  // Largest remainders first; equal remainders in part order, so the result is deterministic.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; missing > 0 && k < order.size(); ++k, --missing) ++rounded[order[k]];
  return rounded;
}

std::vector<std::string> formatParts(const std::vector<double>& parts, const QuantityFormat& format,
                                     const NumberStyle& style) {
  std::vector<double> scaled;
  for (double part : parts) scaled.push_back(part / format.unit_value);
  std::vector<std::string> out;
  for (long long steps : roundedParts(scaled, format.decimals)) {
    out.push_back(formatScaled(steps, format.decimals, style));
  }
  return out;
}

}  // namespace collide::text
