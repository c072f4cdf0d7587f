#pragma once
// One seeded source of randomness per run (planner, synthetic glove, pair sampling). std::mt19937_64's output sequence
// is fixed by the standard, but std:: distributions are not, so the uniform numbers are made here from raw bits: the
// same seed gives the same numbers on every platform and standard library.
#include <cstdint>
#include <random>

namespace pmdplan {

class RandomSource {
 public:
  explicit RandomSource(std::uint64_t seed = 1) : engine_(seed) {}

  void reseed(std::uint64_t seed) { engine_.seed(seed); }

  /// Uniform in [0, 1): the top 53 bits of one 64-bit draw, so every value is exactly representable.
  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  /// Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform01(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace pmdplan
