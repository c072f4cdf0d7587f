#pragma once
// Halton points (Halton 1960): coordinate i of point n is the radical inverse of n in the i-th
// prime base of the sequence. A run's seed shifts each coordinate by its own offset, modulo 1
// (a Cranley-Patterson rotation), so runs of different seeds differ while each keeps the
// sequence's low discrepancy; a point's first k coordinates are the k-dimensional sequence's own.
#include <cstdint>
#include <vector>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/core/sequences/sample_sequence.hpp"

namespace pmdplan {

/// The first `count` primes: 2, 3, 5, 7, ...
std::vector<unsigned> firstPrimes(int count);

/// Radical inverse of `n` in `base` (>= 2): the base-b digits of n mirrored about the point.
double radicalInverseInBase(std::uint64_t n, unsigned base);

class HaltonSequence final : public UnitSequence {
 public:
  /// Coordinate i uses the prime firstPrimes(firstBase + dimension)[firstBase + i], so sequences
  /// given disjoint ranges of bases are a Halton sequence of their joint dimension when drawn in
  /// step. The offsets come from `random` (one number per coordinate). Points start at n = 1.
  HaltonSequence(int firstBase, int dimension, RandomSource& random);

  void next(int dimension, double* point) override;

 private:
  std::vector<unsigned> bases_;
  std::vector<double> offsets_;
  std::uint64_t index_ = 1;
};

}  // namespace pmdplan
