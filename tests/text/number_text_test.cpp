#include "pmdplan/text/number_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace pmdplan {
namespace {

TEST(NumberText, ShortestFormReadsBackExactly) {
  for (const double value : {0.1 + 0.2, std::numbers::pi, -1e-300, 1.0 / 3.0, 123456789.0, 5e-324,
                             std::numeric_limits<double>::max(), -0.30000000000000004}) {
    const std::string text = exactNumberText(value);
    const auto back = parseFiniteNumber(text);
    ASSERT_TRUE(back) << text;
    EXPECT_EQ(*back, value) << text;
  }
  EXPECT_EQ(exactNumberText(0.1), "0.1");
  EXPECT_EQ(exactNumberText(42.0), "42");
  EXPECT_EQ(exactNumberText(-0.0), "0");
}

TEST(NumberText, RejectsWhatIsNotAPlainFiniteNumber) {
  for (const char* text : {"", " ", "abc", "inf", "-inf", "nan", "0x1p3", "1.5x", "1,5", "--1", "1e999"})
    EXPECT_FALSE(parseFiniteNumber(text)) << text;
  EXPECT_EQ(*parseFiniteNumber(" +2.5e1 "), 25.0);
  EXPECT_EQ(*parseFiniteNumber("-.5"), -0.5);
  EXPECT_THROW(exactNumberText(std::nan("")), std::invalid_argument);
}

TEST(NumberText, WholeNumbersHaveNoSignPointOrExponent) {
  EXPECT_EQ(*parseWholeNumber(" 255 "), 255);
  EXPECT_EQ(*parseWholeNumber("0"), 0);
  for (const char* text : {"-1", "+1", "1.0", "1e2", "", "12a"}) EXPECT_FALSE(parseWholeNumber(text)) << text;
}

}  // namespace
}  // namespace pmdplan
