// The portable elementary functions agree with the C library to about an ulp over the ranges the
// project uses them on (joint angles, Box-Muller's log of (0, 1], the synthetic operator's decay).
#include "pmdplan/core/portable_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace pmdplan {
namespace {

double relativeError(double got, double expected) {
  return expected == 0.0 ? std::abs(got) : std::abs(got - expected) / std::abs(expected);
}

TEST(PortableMath, SinAndCosMatchTheLibraryOverJointAngles) {
  std::mt19937_64 engine(3);
  std::uniform_real_distribution<double> angle(-20.0, 20.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = angle(engine);
    double s, c;
    portable::sinCos(x, s, c);
    // Absolute error: near a zero the relative error of any rounding of x is large.
    worst = std::max({worst, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
  }
  EXPECT_LT(worst, 4e-16);
  EXPECT_EQ(portable::sin(0.0), 0.0);
  EXPECT_EQ(portable::cos(0.0), 1.0);
}

TEST(PortableMath, ExpAndLogMatchTheLibrary) {
  std::mt19937_64 engine(5);
  std::uniform_real_distribution<double> exponent(-50.0, 50.0);
  double worstExp = 0.0, worstLog = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = exponent(engine);
    worstExp = std::max(worstExp, relativeError(portable::exp(x), std::exp(x)));
    const double u = std::ldexp(static_cast<double>(engine() >> 11) + 1.0, -53);  // (0, 1]
    worstLog = std::max(worstLog, std::abs(portable::log(u) - std::log(u)) / std::max(1.0, std::abs(std::log(u))));
    const double big = std::exp(x);
    worstLog = std::max(worstLog, std::abs(portable::log(big) - x) / std::max(1.0, std::abs(x)));
  }
  EXPECT_LT(worstExp, 1e-15);
  EXPECT_LT(worstLog, 1e-15);
  EXPECT_EQ(portable::log(1.0), 0.0);
  EXPECT_EQ(portable::exp(0.0), 1.0);
}

}  // namespace
}  // namespace pmdplan
