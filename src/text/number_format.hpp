#pragma once
// The one number formatter for text a person reads: frame readouts, captions, legends, chart ticks
// and alt text. Data files (CSV, JSON) keep full precision and never come here.
//
// Rules (a teacher reads these numbers aloud and checks them with a calculator):
// - An amount (an energy, a speed, a momentum, a force, a percentage) reads with three significant
//   figures, each value on its own: "+1.00 m/s" beside "+0.170 m/s", "8.00 mJ", "49.6 kJ". A
//   nonzero amount never reads 0 and never loses its leading figures to a shared number of
//   decimals; only round-off of zero (below 1e-9 of the picture's largest value) reads "0".
// - Amounts compared side by side share a unit: the SI prefix is chosen once per quantity for a
//   whole picture (a QuantityFormat, from its largest value), so energies read "0.680 J of
//   1.38 J", not "680 mJ of 1.38 J". A value below a tenth of that unit, which would need two or
//   more zeros after the decimal sign, takes its own prefix instead: "KE₁ 2.00 J" beside
//   "KE₂ 5.00 kJ".
// - One rounding rule everywhere: to the nearest step of the last figure, and halfway (within
//   round-off) to the even step, so an exact 1.125 J reads "1.12 J" in every picture and 93.75 %
//   reads "93.8 %".
// - Parts shown beside their total add up to it as displayed: the parts, each rounded to its own
//   last figure, sum to a number that rounds to the total as shown (where plain rounding misses,
//   the parts nearest to their other rounding go that way, by one step of their last figure).
//   A part exactly halfway never moves, so it reads the same everywhere: where only such parts
//   could move, the sum stays one step off ("1.12 J" + "0.250 J" beside a total of "1.38 J").
//   docs/numbers.md.
// - A reading on a scale (a time, a position) keeps the scale's decimals throughout a picture, zero
//   included: "t = 0.00 s" beside "t = 12.00 s", as a stopwatch shows it.
// - Never an exponent, never "-0"; thousands grouped ("12,500 kg·m/s"); angles counter-clockwise
//   from +x in (-180°, 180°]. The one exception: a nonzero amount below a femto-unit (10^-15 of
//   its base unit), which plain figures would bury under zeros, reads "1.00 × 10⁻³⁰⁰ kg" rather
//   than "0 kg".
//
// Every function takes a NumberStyle: the digits, decimal sign, group separator, minus sign and
// percent sign of a language, from CLDR (through ICU) for each shipped language. The default is
// the active language's (text/language.hpp), so "1,25 m/s" in German; data files never come here.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace collide::text {

struct Language;

struct NumberStyle {
  std::string decimal_separator = ".";
  std::string group_separator = ",";  // between groups of integer digits
  std::string minus = "\u2212";       // a true minus sign (with the bidi mark a script needs)
  int group_from_digits = 5;          // group integers of at least this many digits (12,500, 1250)
  std::string plus = "+";
  int group_size = 3;                // digits in the lowest group
  int secondary_group_size = 3;      // digits in each higher group (Hindi: 2, "12,34,567")
  std::vector<std::string> digits;   // the ten digits 0-9 where they are not ASCII (Arabic-Indic)
  std::string percent_prefix;        // "%" before the number (Turkish "%12,5")
  std::string percent_suffix = "%";  // after it ("12,5\u00a0%" in German and French)
  // Between two numbers of a list or vector: "(1.00, 2.00)"; "; " where the decimal sign is a
  // comma, so "(1,00; 2,00)" does not read as four numbers; the Arabic semicolon "؛ " in
  // Arabic, whose decimal sign "٫" is comma-like.
  std::string list_separator = ", ";
};

// The style of the language text is written in now (activeLanguage()).
const NumberStyle& defaultStyle();
// The style of a shipped language (cached) and of any BCP 47 tag (read from CLDR each call).
const NumberStyle& numberStyle(const Language& language);
NumberStyle numberStyleFor(std::string_view bcp47_tag);
// English: what the number formatter wrote before languages (metadata that stays English).
const NumberStyle& englishStyle();

// `ascii` with its digits 0-9 in the style's digits (Arabic-Indic in Arabic), the rest as it is.
std::string withLocalDigits(std::string_view ascii, const NumberStyle& style);

// The sign between two numbers multiplied: "·", or "×" where the style's zero is itself a dot
// (Arabic-Indic "٠", Extended Arabic-Indic "۰"), beside which a middle dot reads as one more zero.
std::string multiplicationSign(const NumberStyle& style = defaultStyle());

// A number written in ASCII as someone typed it ("-0.5", "1250", "2.5e-07") in the style's decimal
// sign, minus and digits, its figures kept ("−0,5" in German): a typed value in a title.
std::string typedNumber(std::string_view ascii, const NumberStyle& style = defaultStyle());

// Every number typed in `text` (ASCII digits, a decimal point between two of them) that is not
// part of a word of ASCII letters ("MP4") nor inside a {placeholder}, as typedNumber writes it,
// where the style's digits are not ASCII ones (Arabic-Indic); elsewhere `text` as it is. For a
// preset's own words: its translated title ("e = 1 و0.5 و0") and its bodies' names ("العربة 1")
// in the digits of every number a frame formats beside them.
std::string typedNumbersIn(std::string_view text, const NumberStyle& style = defaultStyle());

// "(a, b)" with the style's list separator: a vector's two components, already formatted.
std::string numberPair(std::string_view first, std::string_view second,
                       const NumberStyle& style = defaultStyle());

enum class Sign { kNegativeOnly, kAlways };  // kAlways: "+2.00" for positives (not for 0)

// How one quantity is written throughout a picture: its unit with the SI prefix of the picture's
// largest value, the decimals of a reading on its scale, and what counts as round-off of zero.
struct QuantityFormat {
  std::string unit;         // as written after the number, prefix included: "mJ", "kg·m/s", ""
  double unit_value = 1.0;  // the unit in base units: mJ -> 1e-3
  int decimals = 2;         // a reading's digits after the decimal sign; negative: rounded to
                            // tens (-1), hundreds (-2)... so 12,345.6 reads 12,300
  std::string base_unit;    // the unit without prefix: "J", "m/s"
  double zero_below = 0.0;  // magnitudes below this are round-off and read "0", base units
};

// A format for a picture whose largest value of this quantity is `typical` (e.g. the energy at the
// start): `significant` figures for that value. A base unit in `prefixable_units` ("J", "N", "N·s",
// "W") gets the SI prefix (µ, m, k, M, G) that brings `typical` into [1, 1000); other units
// ("kg·m/s", "m/s", "kg", "m", "s", "°", "%") keep their unit.
QuantityFormat quantityFormat(double typical, std::string_view base_unit, int significant = 3);

// An amount in the format's unit with three significant figures, the number alone:
// 0.0123 J in mJ -> "12.3", 0.000170 in m/s -> "0.000170". Rounds half away from zero; round-off
// of zero reads "0" (no decimals, no sign). For a quantity without prefixes (a vector's
// components: "(1.00, −0.500) kg·m/s").
std::string formatIn(double value, const QuantityFormat& format,
                     const NumberStyle& style = defaultStyle(), Sign sign = Sign::kNegativeOnly);

// A vector's two components in the format's unit (formatIn each), "(a, b)" with the style's list
// separator: a component below half a step of its partner's last shown figure reads "0", as it
// rounds at the partner's precision: a momentum along x whose y is a pendulum's sway, beside it
// round-off of zero, reads "(−0.00997, 0)", not "(−0.00997, −0.000000526)".
std::string formatComponentsIn(double x, double y, const QuantityFormat& format,
                               const NumberStyle& style = defaultStyle());
// The two numbers formatComponentsIn writes between its brackets, x then y, for a vector set
// out another way (a fenced pair in the working's mathematics).
std::pair<std::string, std::string> componentsIn(double x, double y, const QuantityFormat& format,
                                                 const NumberStyle& style = defaultStyle());

// An amount with its unit, three significant figures: "12.3 mJ", "0.680 J"; far below the unit
// (under a tenth of it) in its own prefix: 0.002 kJ -> "2.00 J". No space before "°" or "%".
std::string formatQuantity(double value, const QuantityFormat& format,
                           const NumberStyle& style = defaultStyle(),
                           Sign sign = Sign::kNegativeOnly);

// Whether formatQuantity writes this value as zero (round-off or exactly 0).
bool readsZero(double value, const QuantityFormat& format);

// A reading on a scale with the format's decimals and unit: "t = 0.00 s" and "t = 12.00 s" in one
// picture. Round-off of zero reads as zero with the decimals; a nonzero value too small for the
// decimals reads as an amount (three figures) rather than as zero.
std::string formatReading(double value, const QuantityFormat& format,
                          const NumberStyle& style = defaultStyle(),
                          Sign sign = Sign::kNegativeOnly);

// One value with its own format: formatQuantity(value, quantityFormat(|value|, unit)).
std::string formatValue(double value, std::string_view base_unit,
                        const NumberStyle& style = defaultStyle(), Sign sign = Sign::kNegativeOnly);

// A plain number with `significant` figures, no prefix: 2 -> "2", 2.6667 -> "2.67",
// 12345 -> "12,300", 0.000123 -> "0.000123", -0 -> "0". A value that is exactly a shorter decimal
// (a parameter someone typed: "e = 0.5", a chart tick) drops its trailing zeros; a computed one
// keeps them ("e = 0.0980" for 0.09798).
std::string formatPlain(double value, const NumberStyle& style = defaultStyle(),
                        int significant = 3);

// An angle of a direction in degrees, normalised to (-180, 180] and rounded to whole degrees:
// -30 -> "−30°", 330 -> "−30°", -180 -> "180°".
std::string formatAngle(double degrees, const NumberStyle& style = defaultStyle());

// Parts (>= 0; negative ones count as 0) written as formatQuantity writes each, but rounded so
// that, as displayed, they add up to formatQuantity(total, format): converted to the total's unit
// and summed, the shown parts round to the shown total. `total` is their sum as the caller shows
// it (equal to the sum of the parts up to round-off). Same order as `parts`, units included:
// {0.125, 1.125, 0.75} J of 2 J -> "0.125 J", "1.12 J", "0.750 J" of "2.00 J" (1.995 reads
// 2.00). A part exactly halfway between two steps (1.125 J) never moves: {1.125, 0.25} J of
// 1.375 J -> "1.12 J", "0.250 J" of "1.38 J", one step off, as every picture writes 1.125 J.
// A part `steady` names (same order; none where empty) is moved only where the others cannot
// make the sum: a value that holds still between frames (energy lost between two impacts) then
// reads the same in each, the changing ones taking the step.
std::vector<std::string> formatParts(const std::vector<double>& parts, double total,
                                     const QuantityFormat& format,
                                     const NumberStyle& style = defaultStyle(),
                                     const std::vector<bool>& steady = {});

// A whole count of steps of 10^-decimals written as a number: (1234, 2) -> "12.34",
// (123, -2) -> "12,300".
std::string formatScaled(long long steps, int decimals, const NumberStyle& style = defaultStyle(),
                         Sign sign = Sign::kNegativeOnly);

}  // namespace collide::text
