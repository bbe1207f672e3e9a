// The number formatter: three significant figures, SI prefixes per quantity, grouping, zero never
// signed, one angle convention, parts that add up as displayed.
#include "text/number_format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace collide::text {
namespace {

const std::string kMinus = "\u2212";

TEST(NumberFormatTest, EnergiesGetThePrefixThatGivesThreeFigures) {
  const QuantityFormat milli = quantityFormat(0.05, "J");
  EXPECT_EQ(milli.unit, "mJ");
  EXPECT_EQ(milli.decimals, 1);
  EXPECT_EQ(formatQuantity(0.0123456, milli), "12.3 mJ");
  EXPECT_EQ(formatQuantity(0.00617, milli), "6.2 mJ");  // same unit and decimals in one picture
  const QuantityFormat kilo = quantityFormat(185700.0, "J");
  EXPECT_EQ(kilo.unit, "kJ");
  EXPECT_EQ(formatQuantity(185700.0, kilo), "186 kJ");
  EXPECT_EQ(formatValue(1.375, "J"), "1.38 J");
  EXPECT_EQ(formatValue(2.5e6, "J"), "2.50 MJ");
  EXPECT_EQ(formatValue(3.2e-5, "N"), "32.0 µN");
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

TEST(NumberFormatTest, ZeroIsNeverSignedAndRoundOffReadsZero) {
  const QuantityFormat metres = quantityFormat(4.0, "m");
  EXPECT_EQ(formatQuantity(-0.0, metres), "0 m");
  EXPECT_EQ(formatQuantity(2.22e-16, metres), "0 m");
  EXPECT_EQ(formatQuantity(-1.67e-16, metres), "0 m");
  EXPECT_EQ(formatIn(-0.001, quantityFormat(1.0, "m/s"), defaultStyle(), Sign::kAlways), "0");
  EXPECT_EQ(formatPlain(-0.0), "0");
  EXPECT_EQ(formatPlain(1e-300), "0");
}

TEST(NumberFormatTest, PlainNumbersKeepThreeFiguresWithoutTrailingZeros) {
  EXPECT_EQ(formatPlain(2.0), "2");
  EXPECT_EQ(formatPlain(0.5), "0.5");
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

TEST(NumberFormatTest, PartsAddUpToTheirTotalAsDisplayed) {
  // compare-restitution at e = 0.5: naive rounding shows 0.13 + 1.13 + 0.75 = 2.01 against 2.00.
  const std::vector<long long> parts = roundedParts({0.125, 1.125, 0.75}, 2);
  EXPECT_EQ(parts[0] + parts[1] + parts[2], 200);
  // Random parts: the rounded parts always sum to the rounded sum, and each moves by < 1 step.
  std::mt19937 random(18);
  std::uniform_real_distribution<double> value(0.0, 3.0);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<double> raw(1 + trial % 7);
    double sum = 0.0;
    for (double& part : raw) sum += part = value(random);
    const std::vector<long long> rounded = roundedParts(raw, 2);
    long long shown = 0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      shown += rounded[i];
      EXPECT_LT(std::fabs(rounded[i] - raw[i] * 100.0), 1.0);
    }
    EXPECT_EQ(shown, std::llround(sum * 100.0));
  }
}

TEST(NumberFormatTest, FormattedPartsShareTheTotalsFormat) {
  const QuantityFormat format = quantityFormat(0.05, "J");
  const std::vector<std::string> shown = formatParts({0.01234, 0.02468, 0.01298}, format);
  ASSERT_EQ(shown.size(), 3u);
  EXPECT_EQ(shown[0], "12.3");
  EXPECT_EQ(shown[1], "24.7");
  EXPECT_EQ(shown[2], "13.0");
  EXPECT_EQ(formatIn(0.01234 + 0.02468 + 0.01298, format), "50.0");
}

TEST(NumberFormatTest, ScaledStepsWriteDecimalsAndGroups) {
  EXPECT_EQ(formatScaled(1234, 2), "12.34");
  EXPECT_EQ(formatScaled(5, 3), "0.005");
  EXPECT_EQ(formatScaled(-1234567, 0), kMinus + "1,234,567");
  EXPECT_EQ(formatScaled(0, 2, defaultStyle(), Sign::kAlways), "0");
}

TEST(NumberFormatTest, AStyleChangesSeparatorsAndMinus) {
  const NumberStyle style{",", "\u202f", "-", 5};  // decimal comma, narrow space, hyphen
  EXPECT_EQ(formatValue(-12345.6, "kg·m/s", style), "-12\u202f300 kg·m/s");
  EXPECT_EQ(formatValue(0.5, "m/s", style), "0,500 m/s");
}

}  // namespace
}  // namespace collide::text
