#pragma once
// The one number formatter for text a person reads: frame readouts, captions, legends, chart ticks
// and alt text. Data files (CSV, JSON) keep full precision and never come here.
//
// Rules (a teacher reads these numbers aloud):
// - three significant figures, never an exponent;
// - an SI prefix chosen once per quantity for a whole picture (a QuantityFormat), so every energy
//   on one frame reads in the same unit: "12.3 mJ", "6.17 mJ", "0.46 mJ";
// - thousands grouped ("12,500 kg·m/s");
// - anything that rounds to zero reads "0": never "-0", never "0.000000000000000167";
// - angles counter-clockwise from +x in (-180°, 180°];
// - parts shown beside their total add up to it as displayed (largest-remainder rounding).
//
// Every function takes a NumberStyle: the decimal sign, group separator and minus sign of a
// language (issue 21 adds one per locale; today there is English only).
#include <string>
#include <string_view>
#include <vector>

namespace collide::text {

struct NumberStyle {
  std::string decimal_separator = ".";
  std::string group_separator = ",";  // between groups of three integer digits
  std::string minus = "\u2212";       // a true minus sign
  int group_from_digits = 5;          // group integers of at least this many digits (12,500, 1250)
};

// The style of the language text is written in; English until issue 21.
const NumberStyle& defaultStyle();

enum class Sign { kNegativeOnly, kAlways };  // kAlways: "+2.00" for positives (not for 0)

// How one quantity is written throughout a picture: the unit with its SI prefix and the decimals.
struct QuantityFormat {
  std::string unit;         // as written after the number, prefix included: "mJ", "kg·m/s", ""
  double unit_value = 1.0;  // the unit in base units: mJ -> 1e-3
  int decimals = 2;         // digits after the decimal sign; negative: rounded to tens (-1),
                            // hundreds (-2)... so 12,345.6 kg·m/s reads 12,300 (three figures)
};

// A format showing `typical` (the largest magnitude the picture holds for this quantity, e.g. the
// initial energy) with `significant` figures. A base unit in `prefixable_units` ("J", "N", "N·s",
// "W") gets the SI prefix (µ, m, k, M, G) that brings `typical` into [1, 1000); other units
// ("kg·m/s", "m/s", "kg", "m", "s", "°") keep their unit and only choose decimals.
QuantityFormat quantityFormat(double typical, std::string_view base_unit, int significant = 3);

// The number alone in a format: 0.0123 J in mJ with 1 decimal -> "12.3". Rounds half away from
// zero; a value that rounds to 0 reads "0" (no decimals, no sign).
std::string formatIn(double value, const QuantityFormat& format,
                     const NumberStyle& style = defaultStyle(), Sign sign = Sign::kNegativeOnly);

// formatIn with the unit: "12.3 mJ" (no space before "°" or "%").
std::string formatQuantity(double value, const QuantityFormat& format,
                           const NumberStyle& style = defaultStyle(),
                           Sign sign = Sign::kNegativeOnly);

// One value with its own format: formatQuantity(value, quantityFormat(|value|, unit)).
std::string formatValue(double value, std::string_view base_unit,
                        const NumberStyle& style = defaultStyle(), Sign sign = Sign::kNegativeOnly);

// A plain number with `significant` figures, no prefix: 2 -> "2", 2.6667 -> "2.67",
// 12345 -> "12,345", 0.000123 -> "0.000123", -0 -> "0". Trailing zeros after the decimal sign are
// dropped (a parameter someone typed: "e = 0.5").
std::string formatPlain(double value, const NumberStyle& style = defaultStyle(),
                        int significant = 3);

// An angle of a direction in degrees, normalised to (-180, 180] and rounded to whole degrees:
// -30 -> "−30°", 330 -> "−30°", -180 -> "180°".
std::string formatAngle(double degrees, const NumberStyle& style = defaultStyle());

// Parts rounded to `decimals` digits so that, as displayed, they add up to their rounded sum
// (largest-remainder method): {0.125, 1.125, 0.75} to 2 decimals sum to 2.00. Returns the rounded
// parts as multiples of 10^-decimals (integers), the same order. Parts are >= 0.
std::vector<long long> roundedParts(const std::vector<double>& parts, int decimals);

// roundedParts in a QuantityFormat, each written like formatIn: the displayed parts add up to
// formatIn(sum of parts).
std::vector<std::string> formatParts(const std::vector<double>& parts, const QuantityFormat& format,
                                     const NumberStyle& style = defaultStyle());

// A whole count of steps of 10^-decimals written as a number: (1234, 2) -> "12.34",
// (123, -2) -> "12,300".
std::string formatScaled(long long steps, int decimals, const NumberStyle& style = defaultStyle(),
                         Sign sign = Sign::kNegativeOnly);

}  // namespace collide::text
