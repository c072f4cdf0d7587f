#pragma once
// Seeded random numbers that are the same on every platform: std::mt19937_64 is specified exactly,
// the std:: distributions and the C library's log, sin and cos are not, so uniform and normal draws
// are made here with portable_math.hpp.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "pmdplan/core/portable_math.hpp"

namespace pmdplan {

class DeterministicRandom {
 public:
  explicit DeterministicRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  /// Standard normal (Box-Muller; the second value of each pair is kept for the next call).
  double normal() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log stays finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * portable::log(u1));
    spare_ = radius * portable::sin(2.0 * std::numbers::pi * u2);
    hasSpare_ = true;
    return radius * portable::cos(2.0 * std::numbers::pi * u2);
  }

  /// Uniform integer in [0, n).
  int below(int n) { return static_cast<int>(uniform() * n); }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool hasSpare_ = false;
};

}  // namespace pmdplan
