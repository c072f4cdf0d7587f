#pragma once
// sin, cos, exp and log from +, -, *, / and exact bit operations only, so they give the same bits
// on every x86-64 CPU. The C library picks its own variants at load time by CPU features (FMA or
// not), and those differ in the last bit now and then: enough to change a printed digit of a
// model made from a synthetic recording. Accurate to about 1 ulp on the ranges used here; plain
// loops over these vectorise (no library calls, no branches on the value).
#include <bit>
#include <cmath>
#include <cstdint>

namespace pmdplan::portable {

/// sin and cos of x (|x| < 1e5): x = k pi/2 + r with |r| <= pi/4 (Cody-Waite, three parts of pi/2),
/// Taylor series to r^17 / r^18 (the next terms are below 1e-19), quadrant from the low bits of k.
[[gnu::always_inline]] inline void sinCos(double x, double& s, double& c) {
  constexpr double kTwoOverPi = 0.63661977236758134308;
  constexpr double kShifter = 6755399441055744.0;  // 1.5 * 2^52: adding it rounds to an integer
  constexpr double kPio2a = 1.57079632673412561417e+00, kPio2b = 6.07710050630396597660e-11,
                   kPio2c = 2.02226624879595063154e-21;
  const double shifted = x * kTwoOverPi + kShifter;
  const double k = shifted - kShifter;
  // The low mantissa bits of `shifted` hold k (mod 2^51, two's complement): its quadrant.
  const std::uint64_t quadrant = std::bit_cast<std::uint64_t>(shifted);
  const double r = ((x - k * kPio2a) - k * kPio2b) - k * kPio2c;
  const double r2 = r * r;
  const double sr =
      r + r * r2 *
              (-1.0 / 6 +
               r2 * (1.0 / 120 +
                     r2 * (-1.0 / 5040 + r2 * (1.0 / 362880 + r2 * (-1.0 / 39916800 +
                                                                    r2 * (1.0 / 6227020800.0 +
                                                                          r2 * (-1.0 / 1307674368000.0 +
                                                                                r2 * (1.0 / 355687428096000.0))))))));
  const double cr =
      1.0 +
      r2 * (-0.5 +
            r2 * (1.0 / 24 + r2 * (-1.0 / 720 +
                                   r2 * (1.0 / 40320 + r2 * (-1.0 / 3628800 +
                                                             r2 * (1.0 / 479001600.0 +
                                                                   r2 * (-1.0 / 87178291200.0 +
                                                                         r2 * (1.0 / 20922789888000.0 +
                                                                               r2 * (-1.0 / 6402373705728000.0)))))))));
  const std::uint64_t swap = 0 - (quadrant & 1);  // all ones in odd quadrants: sin <-> cos
  const std::uint64_t sb = std::bit_cast<std::uint64_t>(sr), cb = std::bit_cast<std::uint64_t>(cr);
  const std::uint64_t sinBits = (sb & ~swap) | (cb & swap);
  const std::uint64_t cosBits = (cb & ~swap) | (sb & swap);
  s = std::bit_cast<double>(sinBits ^ ((quadrant & 2) << 62));        // negative in quadrants 2, 3
  c = std::bit_cast<double>(cosBits ^ (((quadrant + 1) & 2) << 62));  // negative in quadrants 1, 2
}

inline double sin(double x) {
  double s, c;
  sinCos(x, s, c);
  return s;
}

inline double cos(double x) {
  double s, c;
  sinCos(x, s, c);
  return c;
}

/// e^x for |x| < 700: x = k ln2 + r with |r| <= ln2 / 2 (Cody-Waite), Taylor series to r^17, then
/// 2^k put into the exponent bits.
inline double exp(double x) {
  constexpr double kLog2e = 1.4426950408889634074, kShifter = 6755399441055744.0;
  constexpr double kLn2a = 6.93147180369123816490e-01, kLn2b = 1.90821492927058770002e-10;
  const double k = (x * kLog2e + kShifter) - kShifter;
  const double r = (x - k * kLn2a) - k * kLn2b;
  double sum = 1.0, term = 1.0;
  for (int n = 1; n <= 17; ++n) {
    term *= r / n;
    sum += term;
  }
  const auto exponent = static_cast<std::int64_t>(k);
  return sum * std::bit_cast<double>(static_cast<std::uint64_t>(1023 + exponent) << 52);
}

/// Natural logarithm of a positive normal x: x = m 2^e with m in [sqrt(1/2), sqrt(2)) (exact, from
/// the bits), log m = 2 atanh(s) with s = (m - 1) / (m + 1), |s| <= 0.172, series to s^23.
inline double log(double x) {
  constexpr double kLn2 = 0.69314718055994530942;
  std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  std::int64_t e = static_cast<std::int64_t>((bits >> 52) & 0x7ff) - 1023;
  bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;  // m in [1, 2)
  double m = std::bit_cast<double>(bits);
  if (m > 1.4142135623730950488) m *= 0.5, ++e;
  const double s = (m - 1.0) / (m + 1.0), s2 = s * s;
  double sum = 0.0;
  for (int n = 23; n >= 3; n -= 2) sum = (sum + 1.0 / n) * s2;
  return 2.0 * s * (1.0 + sum) + static_cast<double>(e) * kLn2;
}

}  // namespace pmdplan::portable
