// The number formatter: three significant figures, SI prefixes per quantity, grouping, zero never
// signed, one angle convention, parts that add up as displayed.
#include "text/number_format.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "text/language.hpp"

namespace collide::text {
namespace {

const std::string kMinus = "\u2212";

TEST(NumberFormatTest, EnergiesGetThePrefixThatGivesThreeFigures) {
  const QuantityFormat milli = quantityFormat(0.05, "J");
  EXPECT_EQ(milli.unit, "mJ");
  EXPECT_EQ(formatQuantity(0.0123456, milli), "12.3 mJ");
  const QuantityFormat kilo = quantityFormat(185700.0, "J");
  EXPECT_EQ(kilo.unit, "kJ");
  EXPECT_EQ(formatQuantity(185700.0, kilo), "186 kJ");
  EXPECT_EQ(formatValue(1.375, "J"), "1.38 J");
  EXPECT_EQ(formatValue(2.5e6, "J"), "2.50 MJ");
  EXPECT_EQ(formatValue(3.2e-5, "N"), "32.0 µN");
}

// Every amount keeps three figures of its own in the picture's unit: a value ten times smaller
// than the largest does not lose a figure ("6.17 mJ", never "6.2 mJ"), one a hundred times
// smaller not two ("0.170 m/s" where the fastest body moves at 100 m/s, never "0 m/s").
TEST(NumberFormatTest, EveryAmountKeepsThreeFiguresInThePicturesUnit) {
  const QuantityFormat milli = quantityFormat(0.05, "J");
  EXPECT_EQ(formatQuantity(0.00617, milli), "6.17 mJ");
  EXPECT_EQ(formatQuantity(0.008, milli), "8.00 mJ");
  const QuantityFormat fast = quantityFormat(100.0, "m/s");
  // A block of 1 kg rebounding from one of 10⁴ kg at 1 m/s, e = 1: (m₁ − m₂)·0 + 2·m₂·(−1) over
  // m₁ + m₂ = −2·10⁴/10001 m/s; a third of it as a slower example.
  const double rebound = -2.0e4 / 10001.0;
  EXPECT_EQ(formatQuantity(rebound, fast, defaultStyle(), Sign::kAlways), kMinus + "2.00 m/s");
  EXPECT_EQ(formatQuantity(-rebound / 12.0, fast, defaultStyle(), Sign::kAlways), "+0.167 m/s");
  EXPECT_EQ(formatIn(0.000170, fast), "0.000170");
  // 50 kJ in a picture of 186 kJ: three figures, not "50 kJ".
  EXPECT_EQ(formatQuantity(49600.0, quantityFormat(185700.0, "J")), "49.6 kJ");
}

// Comparable values stay in the picture's unit down to a tenth of it ("0.680 J of 1.38 J");
// smaller ones take their own prefix: ½·1 kg·(2·10⁴/10001 m/s)² is 2.00 J beside 5.00 kJ.
TEST(NumberFormatTest, AValueFarBelowThePicturesUnitTakesItsOwnPrefix) {
  const QuantityFormat joules = quantityFormat(1.375, "J");
  EXPECT_EQ(formatQuantity(0.68, joules), "0.680 J");
  EXPECT_EQ(formatQuantity(0.06, joules), "60.0 mJ");
  const QuantityFormat kilo = quantityFormat(0.5 * 1e4 * 1.0, "J");
  EXPECT_EQ(formatQuantity(0.5e4, kilo), "5.00 kJ");
  const double v = 2.0e4 / 10001.0;
  EXPECT_EQ(formatQuantity(0.5 * v * v, kilo), "2.00 J");
  // ½·(0.17)² = 0.01445 J, halfway between 14.4 and 14.5 mJ: to the even step.
  EXPECT_EQ(formatQuantity(0.5 * 0.17 * 0.17, kilo), "14.4 mJ");
  // Units without prefixes keep their unit and add decimals instead.
  EXPECT_EQ(formatQuantity(0.17, quantityFormat(100.0, "m/s")), "0.170 m/s");
}

TEST(NumberFormatTest, RoundingUpToTheNextDecadeChangesThePrefix) {
  // 999.6 J shows as 1000 J with three figures: it reads 1.00 kJ instead.
  EXPECT_EQ(formatValue(999.6, "J"), "1.00 kJ");
  EXPECT_EQ(formatValue(0.09996, "J"), "100 mJ");
}

TEST(NumberFormatTest, UnitsWithoutPrefixesGroupThousands) {
  EXPECT_EQ(formatValue(12500.0, "kg·m/s", defaultStyle(), Sign::kAlways), "+12,500 kg·m/s");
  EXPECT_EQ(formatValue(1250.0, "kg"), "1250 kg");  // four digits stay together
  EXPECT_EQ(formatValue(-2.0, "m/s"), kMinus + "2.00 m/s");
  EXPECT_EQ(formatValue(2.0, "m/s", defaultStyle(), Sign::kAlways), "+2.00 m/s");
}

// Only round-off of zero reads 0: below a billionth of the picture's largest value.
TEST(NumberFormatTest, ZeroIsNeverSignedAndRoundOffReadsZero) {
  const QuantityFormat metres = quantityFormat(4.0, "m");
  EXPECT_EQ(formatQuantity(-0.0, metres), "0 m");
  EXPECT_EQ(formatQuantity(2.22e-16, metres), "0 m");
  EXPECT_EQ(formatQuantity(-1.67e-16, metres), "0 m");
  EXPECT_TRUE(readsZero(-1.67e-16, metres));
  EXPECT_FALSE(readsZero(-1e-6, metres));
  EXPECT_EQ(formatIn(-1e-12, quantityFormat(1.0, "m/s"), defaultStyle(), Sign::kAlways), "0");
  EXPECT_EQ(formatIn(-0.001, quantityFormat(1.0, "m/s"), defaultStyle(), Sign::kAlways),
            kMinus + "0.00100");
  EXPECT_EQ(formatQuantity(1e-300, QuantityFormat{}), "0");
  EXPECT_EQ(formatPlain(-0.0), "0");
}

// A vector's component below half a step of its partner's last figure rounds to zero at the
// partner's precision: Newton's cradle's Σp (−0.00997, −0.000000526) kg·m/s has its last figure
// in the 10⁻⁵ place, and 5.26e-7 is below half of that (5e-6).
TEST(NumberFormatTest, AComponentBelowItsPartnersLastFigureReadsZero) {
  const QuantityFormat momentum = quantityFormat(0.05, "kg·m/s");
  EXPECT_EQ(formatComponentsIn(-0.00997, -0.000000526, momentum), "(" + kMinus + "0.00997, 0)");
  EXPECT_EQ(formatComponentsIn(-0.000000526, 0.00997, momentum), "(0, 0.00997)");
  // 0.006 is above half of 0.01, 1.00's last step: it keeps its own three figures.
  const QuantityFormat speed = quantityFormat(1.0, "m/s");
  EXPECT_EQ(formatComponentsIn(1.0, 0.004, speed), "(1.00, 0)");
  EXPECT_EQ(formatComponentsIn(1.0, 0.006, speed), "(1.00, 0.00600)");
  EXPECT_EQ(formatComponentsIn(0.5, -0.25, speed), "(0.500, " + kMinus + "0.250)");
  EXPECT_EQ(formatComponentsIn(0.0, 0.0, speed), "(0, 0)");
}

// Below a femto-unit plain figures would need sixteen zeros or more: a nonzero amount reads in
// powers of ten there, never "0" (1e-300 kg is 1.00 × 10⁻³⁰⁰ kg). Round-off of a picture's
// scale still reads 0, and so does anything where a format has no scale at all.
TEST(NumberFormatTest, TinyAmountsReadInPowersOfTenNeverZero) {
  const std::string times_ten = " \u00d7 10";  // " × 10"
  EXPECT_EQ(formatValue(1e-300, "kg"), "1.00" + times_ten + "⁻³⁰⁰ kg");
  EXPECT_EQ(formatValue(-2.5e-20, "m/s", defaultStyle(), Sign::kAlways),
            kMinus + "2.50" + times_ten + "⁻²⁰ m/s");
  EXPECT_EQ(formatValue(2.5e-20, "m/s", defaultStyle(), Sign::kAlways),
            "+2.50" + times_ten + "⁻²⁰ m/s");
  // No SI prefix reaches 1e-302 J: the base unit.
  EXPECT_EQ(formatValue(3.125e-302, "J"), "3.13" + times_ten + "⁻³⁰² J");
  EXPECT_EQ(formatPlain(1e-300), "1.00" + times_ten + "⁻³⁰⁰");
  EXPECT_EQ(formatIn(4e-17, quantityFormat(4e-17, "m/s")), "4.00" + times_ten + "⁻¹⁷");
  // A femto-unit itself still has plain figures: 1e-15 is 0.00000000000000100.
  EXPECT_EQ(formatValue(1e-15, "kg"), "0.00000000000000100 kg");
  // In German: a decimal comma in the figures.
  EXPECT_EQ(formatValue(1e-300, "kg", numberStyleFor("de")), "1,00" + times_ten + "⁻³⁰⁰ kg");
  // Round-off of the picture's scale, and a value with no scale beside it, read 0 as before.
  EXPECT_EQ(formatQuantity(1e-300, quantityFormat(2.0, "m/s")), "0 m/s");
  EXPECT_EQ(formatQuantity(1e-300, QuantityFormat{}), "0");
}

// Times are read like a stopwatch: one number of decimals in a picture, zero included.
TEST(NumberFormatTest, ReadingsKeepTheScalesDecimals) {
  const QuantityFormat time = quantityFormat(12.0, "s", 4);
  EXPECT_EQ(formatReading(0.0, time), "0.00 s");
  EXPECT_EQ(formatReading(-0.0, time), "0.00 s");
  EXPECT_EQ(formatReading(1.4, time), "1.40 s");
  EXPECT_EQ(formatReading(12.0, time), "12.00 s");
  EXPECT_EQ(formatReading(0.8, quantityFormat(4.0, "s", 4)), "0.800 s");
  // Not zero, yet below the scale's last digit: three figures rather than "0.00 s".
  EXPECT_EQ(formatReading(0.001, time), "0.00100 s");
}

TEST(NumberFormatTest, PlainNumbersKeepThreeFiguresWithoutTrailingZeros) {
  EXPECT_EQ(formatPlain(2.0), "2");
  EXPECT_EQ(formatPlain(0.5), "0.5");
  // car-crash's e at 25 m/s: 0.4·(1.5/25)^½ = 0.09798; computed, so three figures, not "0.098".
  EXPECT_EQ(formatPlain(0.4 * std::sqrt(1.5 / 25.0)), "0.0980");
  EXPECT_EQ(formatPlain(0.1 + 0.2), "0.3");  // round-off of a short decimal is still that decimal
  EXPECT_EQ(formatPlain(2.0 / 3.0 * 4.0), "2.67");
  EXPECT_EQ(formatPlain(0.000123), "0.000123");
  EXPECT_EQ(formatPlain(123456.0), "123,000");
  EXPECT_EQ(formatPlain(-1234.5), kMinus + "1230");
  EXPECT_EQ(formatPlain(1e30).substr(0, 6), "1,000,");
}

TEST(NumberFormatTest, AnglesReadCounterClockwiseFromPlusXWithinHalfATurn) {
  EXPECT_EQ(formatAngle(330.0), kMinus + "30°");
  EXPECT_EQ(formatAngle(-30.0), kMinus + "30°");
  EXPECT_EQ(formatAngle(-180.0), "180°");
  EXPECT_EQ(formatAngle(540.0), "180°");
  EXPECT_EQ(formatAngle(-0.2), "0°");
  EXPECT_EQ(formatAngle(45.4), "45°");
}

// A displayed quantity back in base units: "1.12 J" -> 1.12, "14.4 mJ" -> 0.0144.
double parsed(const std::string& shown, int* last_decimal_exponent = nullptr) {
  const std::size_t space = shown.find(' ');
  std::string number = shown.substr(0, space);
  number.erase(std::remove(number.begin(), number.end(), ','), number.end());
  const std::string unit = space == std::string::npos ? "" : shown.substr(space + 1);
  double unit_value = 1.0;
  if (unit.rfind("µ", 0) == 0) unit_value = 1e-6;
  if (unit.rfind("m", 0) == 0 && unit != "m") unit_value = 1e-3;
  if (unit.rfind("k", 0) == 0 && unit != "kg") unit_value = 1e3;
  if (unit.rfind("M", 0) == 0) unit_value = 1e6;
  if (last_decimal_exponent) {
    const std::size_t dot = number.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(number.size() - dot - 1);
    *last_decimal_exponent = static_cast<int>(std::lround(std::log10(unit_value))) - decimals;
  }
  return std::stod(number) * unit_value;
}

TEST(NumberFormatTest, PartsAddUpToTheirTotalAsDisplayed) {
  // compare-restitution at e = 0.5: 1 kg at 2 m/s meets 1 kg at rest. v₁′ = 0.5 m/s,
  // v₂′ = 1.5 m/s: KE₁ = 0.125 J, KE₂ = 1.125 J, lost ½·½·(1 − ¼)·4 = 0.75 J, of 2 J.
  const std::vector<std::string> shown =
      formatParts({0.125, 1.125, 0.75}, 2.0, quantityFormat(2.0, "J"));
  ASSERT_EQ(shown.size(), 3u);
  EXPECT_EQ(shown[0], "0.125 J");
  // 1.125 J is halfway: it reads 1.12 J (to the even step), here and everywhere; the parts as
  // shown sum to 1.995 J, which by the same rule reads 2.00 J.
  EXPECT_EQ(shown[1], "1.12 J");
  EXPECT_EQ(shown[2], "0.750 J");
  // pi-blocks after the first hit: 2.00 J beside the rest of 5 kJ, in their own units.
  const double v = 2.0e4 / 10001.0, ke1 = 0.5 * v * v;
  const std::vector<std::string> pi =
      formatParts({ke1, 5000.0 - ke1, 0.0}, 5000.0, quantityFormat(5000.0, "J"));
  EXPECT_EQ(pi[0], "2.00 J");
  EXPECT_EQ(pi[1], "5.00 kJ");
  EXPECT_EQ(pi[2], "0 kJ");
  // Three parts of 1.004 J (251/250) each, of 3.012 J: each alone reads 1.00 J, and three of
  // those make 3.00 J, which does not read 3.01 J: one part goes the other way, one step of its
  // last figure (docs/numbers.md's example).
  const std::vector<std::string> three =
      formatParts({1.004, 1.004, 1.004}, 3.012, quantityFormat(3.012, "J"));
  EXPECT_EQ(formatQuantity(3.012, quantityFormat(3.012, "J")), "3.01 J");
  EXPECT_EQ(std::count(three.begin(), three.end(), "1.01 J"), 1);
  EXPECT_EQ(std::count(three.begin(), three.end(), "1.00 J"), 2);
  // soft-contact at the start: ½·1 kg·(1.5 m/s)² = 1.125 J and ½·2 kg·(0.5 m/s)² = 0.25 J of
  // 1.375 J. 1.125 is exactly halfway and reads 1.12 J as everywhere; 0.25 is exact; neither may
  // move, so the parts read 1.37 J beside a total of 1.38 J (1.375, halfway, to the even 8).
  const QuantityFormat soft = quantityFormat(1.375, "J");
  EXPECT_EQ(formatQuantity(1.375, soft), "1.38 J");
  EXPECT_EQ(formatParts({1.125, 0.25}, 1.375, soft),
            (std::vector<std::string>{"1.12 J", "0.250 J"}));
}

// The energy lost in the impacts holds still between them while the kinetic and potential
// energies change: where the parts need a step to add up, a changing part takes it, so that the
// lost energy reads the same in every frame (bouncing-ball's "lost 2.92 J" read 2.93 J for a
// frame where its remainder was the largest). Three parts of 1.004 J (251/250) of 3.012 J need one
// step up (each reads 1.00 J; the total 3.01 J): with the first two steady, the third takes it.
TEST(NumberFormatTest, ASteadyPartTakesTheStepOnlyWhereNoOtherCan) {
  const QuantityFormat format = quantityFormat(3.012, "J");
  EXPECT_EQ(formatParts({1.004, 1.004, 1.004}, 3.012, format, defaultStyle(), {true, true, false}),
            (std::vector<std::string>{"1.00 J", "1.00 J", "1.01 J"}));
  EXPECT_EQ(formatParts({1.004, 1.004, 1.004}, 3.012, format, defaultStyle(), {false, true, true}),
            (std::vector<std::string>{"1.01 J", "1.00 J", "1.00 J"}));
  // 1.004 J, 1.004 J (steady) and exactly 1 J of 3.008 J (reads 3.01 J): the exact part cannot
  // move (it reads as it is), so a steady one takes the step.
  const std::vector<std::string> only_steady = formatParts(
      {1.004, 1.004, 1.0}, 3.008, quantityFormat(3.008, "J"), defaultStyle(), {true, true, false});
  EXPECT_EQ(only_steady[2], "1.00 J");
  EXPECT_EQ(std::count(only_steady.begin(), only_steady.end(), "1.01 J"), 1);
}

// One rounding rule for every number a picture shows: the nearest step, and halfway to the even
// step, with a value within round-off of halfway counted as halfway. The expected readings are
// worked by hand: 1.125 lies halfway between 1.12 and 1.13, 93.75 between 93.7 and 93.8.
TEST(NumberFormatTest, HalfwayRoundsToTheEvenStepEverywhere) {
  // soft-contact's KE₁ at the start, 1/2 · 1 kg · (1.5 m/s)²: the same 1.125 J as
  // compare-restitution's KE₂, on its own and as a part.
  EXPECT_EQ(formatValue(0.5 * 1.0 * 1.5 * 1.5, "J"), "1.12 J");
  EXPECT_EQ(formatQuantity(1.125, quantityFormat(1.375, "J")), "1.12 J");
  // 1.135 is stored just below itself, within round-off of halfway: to the even 1.14.
  EXPECT_EQ(formatValue(1.135, "J"), "1.14 J");
  EXPECT_EQ(formatValue(2.5, "m/s"), "2.50 m/s");
  EXPECT_EQ(formatPlain(0.0625, englishStyle(), 2), "0.062");
  EXPECT_EQ(formatPlain(0.0875, englishStyle(), 2), "0.088");
  // clay: 1.5 J of 1.6 J lost is 15/16 = 93.75 %; computed, 1.4999999999999998 J of 1.6 J.
  EXPECT_EQ(formatValue(100.0 * 1.5 / 1.6, "%"), "93.8%");
  EXPECT_EQ(formatValue(100.0 * 1.4999999999999998 / 1.6, "%"), "93.8%");
  EXPECT_EQ(formatValue(100.0 * 0.9125, "%"), "91.2%");
  // Negative values round as their magnitudes do.
  EXPECT_EQ(formatValue(-1.125, "J"), kMinus + "1.12 J");
  EXPECT_EQ(formatReading(0.125, quantityFormat(1.0, "s")), "0.12 s");
  EXPECT_EQ(formatAngle(-142.5), kMinus + "142°");
}

// Random parts over six decades: each part shows three figures (four where the sum needed its
// rounding moved across a decade) and lies within one step of its last figure of the true value,
// and the parts as shown, summed, round to the total as shown.
TEST(NumberFormatTest, RandomPartsAlwaysAddUpAndStayTrue) {
  std::mt19937 random(18);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<int> decade(-4, 2);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<double> raw(1 + trial % 7);
    double sum = 0.0;
    for (double& part : raw) {
      part = trial % 5 == 0 && &part == &raw.front()
                 ? 0.0
                 : mantissa(random) * std::pow(10.0, decade(random));
      sum += part;
    }
    const QuantityFormat format = quantityFormat(sum, "J");
    const std::string total = formatQuantity(sum, format);
    int total_exponent = 0;
    const double shown_total = parsed(total, &total_exponent);
    const std::vector<std::string> shown = formatParts(raw, sum, format);
    double shown_sum = 0.0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      SCOPED_TRACE(shown[i] + " for " + std::to_string(raw[i]));
      int exponent = 0;
      const double value = parsed(shown[i], &exponent);
      shown_sum += value;
      EXPECT_LT(std::fabs(value - raw[i]), std::pow(10.0, exponent) * (1.0 + 1e-9));
      if (raw[i] == 0.0) {
        EXPECT_EQ(value, 0.0);
      } else {
        EXPECT_GT(value, 0.0);
        const double figures = std::floor(std::log10(value)) - exponent + 1;
        EXPECT_GE(figures, 2.99);
        EXPECT_LE(figures, 4.01);
      }
    }
    const double step = std::pow(10.0, total_exponent);
    EXPECT_LE(std::fabs(shown_sum - shown_total), 0.5 * step * (1.0 + 1e-9))
        << total << " from " << sum;
  }
}

TEST(NumberFormatTest, ScaledStepsWriteDecimalsAndGroups) {
  EXPECT_EQ(formatScaled(1234, 2), "12.34");
  EXPECT_EQ(formatScaled(5, 3), "0.005");
  EXPECT_EQ(formatScaled(-1234567, 0), kMinus + "1,234,567");
  EXPECT_EQ(formatScaled(0, 2, defaultStyle(), Sign::kAlways), "0");
}

TEST(NumberFormatTest, AStyleChangesSeparatorsAndMinus) {
  NumberStyle style;  // decimal comma, narrow space, hyphen
  style.decimal_separator = ",";
  style.group_separator = "\u202f";
  style.minus = "-";
  EXPECT_EQ(formatValue(-12345.6, "kg·m/s", style), "-12\u202f300 kg·m/s");
  EXPECT_EQ(formatValue(0.5, "m/s", style), "0,500 m/s");
}

// Each language's conventions, as its readers write numbers (CLDR, the data behind every
// operating system's locale): the decimal comma of German, French, Spanish, Italian, Polish,
// Brazilian Portuguese, Russian and Turkish; their digit groups; where the percent sign goes; SI
// symbols unchanged.
TEST(NumberStyleTest, EachLanguageWritesItsDecimalSignGroupsAndPercent) {
  const std::string nbsp = "\u00a0", narrow = "\u202f";
  // 12,345.6 kg·m/s reads with three figures as 12,300; 0.125 of a whole as 12.5 %.
  const double momentum = 12345.6, share = 12.5;
  struct Expected {
    const char* tag;
    std::string speed, momentum, percent;
  };
  const Expected expected[] = {
      {"en", "1.25 m/s", "12,300 kg·m/s", "12.5%"},
      {"de", "1,25 m/s", "12.300 kg·m/s", "12,5" + nbsp + "%"},
      {"fr", "1,25 m/s", "12" + narrow + "300 kg·m/s", "12,5" + nbsp + "%"},
      {"es", "1,25 m/s", "12.300 kg·m/s", "12,5" + nbsp + "%"},
      {"it", "1,25 m/s", "12.300 kg·m/s", "12,5%"},
      {"pl", "1,25 m/s", "12" + nbsp + "300 kg·m/s", "12,5%"},
      {"pt-BR", "1,25 m/s", "12.300 kg·m/s", "12,5%"},
      {"ru", "1,25 m/s", "12" + nbsp + "300 kg·m/s", "12,5" + nbsp + "%"},
      {"tr", "1,25 m/s", "12.300 kg·m/s", "%12,5"},
      {"ja", "1.25 m/s", "12,300 kg·m/s", "12.5%"},
      // Arabic-Indic digits, the Arabic decimal and group signs: ١٫٢٥ and ١٢٬٣٠٠.
      {"ar", "\u0661\u066b\u0662\u0665 m/s", "\u0661\u0662\u066c\u0663\u0660\u0660 kg·m/s",
       "\u0661\u0662\u066b\u0665\u066a\u061c"}};
  for (const Expected& language : expected) {
    const NumberStyle style = numberStyleFor(language.tag);
    EXPECT_EQ(formatValue(1.25, "m/s", style), language.speed) << language.tag;
    EXPECT_EQ(formatValue(momentum, "kg·m/s", style), language.momentum) << language.tag;
    EXPECT_EQ(formatValue(share, "%", style), language.percent) << language.tag;
  }
}

TEST(NumberStyleTest, MinusPlusAndListsFollowTheLanguage) {
  const NumberStyle german = numberStyleFor("de");
  EXPECT_EQ(formatValue(-1.25, "m/s", german), kMinus + "1,25 m/s");
  EXPECT_EQ(formatValue(1.25, "m/s", german, Sign::kAlways), "+1,25 m/s");
  // With a decimal comma, a vector's components are kept apart by a semicolon.
  EXPECT_EQ(numberPair(formatPlain(1.5, german), formatPlain(-2, german), german),
            "(1,5; " + kMinus + "2)");
  EXPECT_EQ(numberPair("1.5", "2", numberStyleFor("en")), "(1.5, 2)");
  // Arabic marks its signs for right-to-left text (U+061C, the Arabic letter mark).
  const NumberStyle arabic = numberStyleFor("ar");
  EXPECT_EQ(formatPlain(-2, arabic), "\u061c" + kMinus + "\u0662");
  // Its decimal sign ٫ looks like a small comma: components are kept apart by the Arabic
  // semicolon, so (1.5, −2) never reads as one number's decimals.
  EXPECT_EQ(numberPair(formatPlain(1.5, arabic), formatPlain(-2, arabic), arabic),
            "(\u0661\u066b\u0665\u061b \u061c" + kMinus + "\u0662)");
  EXPECT_EQ(formatReading(0.0, quantityFormat(10.0, "s"), arabic), "\u0660\u066b\u0660 s");
  // A typed value keeps its figures and takes the language's signs: a title's "e = {restitution}".
  EXPECT_EQ(typedNumber("-0.125", german), kMinus + "0,125");
  EXPECT_EQ(typedNumber("0.5", arabic), "\u0660\u066b\u0665");
  // Hindi groups by the lakh: 12,34,567.
  EXPECT_EQ(formatPlain(1234567, numberStyleFor("hi"), 7), "12,34,567");
}

TEST(NumberStyleTest, ANumberTypedInWordsTakesArabicDigitsAndNoOther) {
  const NumberStyle arabic = numberStyleFor("ar");
  // A translator's "e = 1, 0.5 and 0" (و: "and", written onto the next word), its decimal
  // point the Arabic decimal sign.
  EXPECT_EQ(typedNumbersIn("e = 1 \u06480.5 \u06480", arabic),
            "e = \u0661 \u0648\u0660\u066b\u0665 \u0648\u0660");
  // A body's name, a number in a word of ASCII letters, a placeholder and a full stop after a
  // number are left as they are but for the digits.
  EXPECT_EQ(typedNumbersIn("\u0627\u0644\u0639\u0631\u0628\u0629 2", arabic),
            "\u0627\u0644\u0639\u0631\u0628\u0629 \u0662");
  EXPECT_EQ(typedNumbersIn("MP4 x264 {ratio2} 3.", arabic), "MP4 x264 {ratio2} \u0663.");
  // Languages written in ASCII digits keep the text as typed (German's "0.5" is its
  // translator's to write as "0,5").
  EXPECT_EQ(typedNumbersIn("e = 1, 0.5 and 0", numberStyleFor("en")), "e = 1, 0.5 and 0");
  EXPECT_EQ(typedNumbersIn("e = 0.5", numberStyleFor("de")), "e = 0.5");
}

TEST(NumberStyleTest, EnglishIsUnchangedAndTheDefaultFollowsTheActiveLanguage) {
  const NumberStyle english = numberStyleFor("en");
  const NumberStyle& plain = englishStyle();
  EXPECT_EQ(english.decimal_separator, plain.decimal_separator);
  EXPECT_EQ(english.group_separator, plain.group_separator);
  EXPECT_EQ(english.minus, plain.minus);
  EXPECT_EQ(english.percent_suffix, plain.percent_suffix);
  EXPECT_TRUE(english.digits.empty());
  EXPECT_EQ(formatValue(1.25, "m/s"), "1.25 m/s");
  {
    const ScopedLanguage german("de");
    EXPECT_EQ(formatValue(1.25, "m/s"), "1,25 m/s");
    EXPECT_EQ(formatValue(1.25, "m/s", englishStyle()), "1.25 m/s");
  }
  {
    const ScopedLanguage pseudo("en-XA");  // the layout test language writes numbers as English
    EXPECT_EQ(formatValue(1.25, "m/s"), "1.25 m/s");
  }
  EXPECT_EQ(formatValue(1.25, "m/s"), "1.25 m/s");
}

}  // namespace
}  // namespace collide::text
