#pragma once
// The SDK sequence (Rosell, Roa, Pérez and García 2007): the unit cube is cut into a tree of
// cells, each split in 2^d halves along every axis, and the sequence visits the cells of every
// level in an order that keeps consecutive samples apart. Sample n's cell, in words: the d-bit
// groups of n, lowest first, pick the sub-cell at level 1, 2, ...; each group goes through the
// binary matrix T_d (mod 2) first, which sends consecutive groups to sub-cells far apart. So the
// first 2^d samples fill the 2^d cells of level 1 once each, the first 2^2d those of level 2,
// and so on. The point is drawn uniformly inside its finest cell, and a run's seed picks where in
// the sequence it starts, as the authors' toolkit does; runs of different seeds then differ.
//
// T_d: T_2 = [1 0; 1 1], T_3 = [1 0 0; 0 1 0; 1 1 1]; a composite d = p·q·... takes the Kronecker
// product of its prime factors' matrices (ascending); a prime p > 3 takes T_{p+1} cut to p × p.
// Every T_d is lower triangular with a unit diagonal, hence invertible mod 2: each level's cells
// are each visited once per 2^(d·level) samples.
#include <cstdint>
#include <map>
#include <vector>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/core/sequences/sample_sequence.hpp"

namespace pmdplan {

/// T_d as rows of bits: bit j of row i is T_d[i][j]. d in 1..63 (std::invalid_argument otherwise).
std::vector<std::uint64_t> sdkMatrix(int dimension);

/// The finest cell of sample `n` in d dimensions with `levels` levels (d · levels <= 63): per axis,
/// the integer index of the cell in 0 .. 2^levels - 1.
std::vector<std::uint64_t> sdkCell(std::uint64_t n, int dimension, int levels);

class SdkSequence final : public UnitSequence {
 public:
  /// Points of up to `maxDimension` coordinates; each dimension asked for is its own sequence
  /// (the hand's grows as a run goes on). Offsets and in-cell positions come from `random`.
  SdkSequence(int maxDimension, RandomSource& random);

  void next(int dimension, double* point) override;

  /// Levels of the tree in d dimensions: as many as 63 bits hold, at most 20 (cells of 2^-20).
  static int levelsFor(int dimension);

 private:
  struct Stream {
    std::vector<std::uint64_t> matrix;
    std::uint64_t index = 0;
  };
  int maxDimension_;
  RandomSource& random_;
  std::map<int, Stream> streams_;
};

}  // namespace pmdplan
