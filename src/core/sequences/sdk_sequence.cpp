#include "pmdplan/core/sequences/sdk_sequence.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pmdplan {
namespace {

using Rows = std::vector<std::uint64_t>;

/// Kronecker product of two binary matrices held as bit rows (a is na × na, b is nb × nb).
Rows kronecker(const Rows& a, const Rows& b) {
  const std::size_t na = a.size(), nb = b.size();
  Rows product(na * nb, 0);
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < na; ++j) {
      if (!((a[i] >> j) & 1U)) continue;
      for (std::size_t k = 0; k < nb; ++k) product[i * nb + k] |= b[k] << (j * nb);
    }
  return product;
}

Rows truncated(Rows rows, std::size_t size) {
  rows.resize(size);
  const std::uint64_t mask = size >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << size) - 1;
  for (auto& row : rows) row &= mask;
  return rows;
}

std::vector<int> primeFactors(int n) {
  std::vector<int> factors;
  for (int p = 2; p * p <= n; ++p)
    while (n % p == 0) {
      factors.push_back(p);
      n /= p;
    }
  if (n > 1) factors.push_back(n);
  return factors;
}

Rows primeMatrix(int p) {
  if (p == 2) return {0b01, 0b11};
  if (p == 3) return {0b001, 0b010, 0b111};
  return truncated(sdkMatrix(p + 1), static_cast<std::size_t>(p));
}

}  // namespace

std::vector<std::uint64_t> sdkMatrix(int dimension) {
  if (dimension < 1 || dimension > 63)
    throw std::invalid_argument("sdkMatrix: dimension " + std::to_string(dimension) + " outside 1..63");
  Rows matrix = {1};
  for (const int p : primeFactors(dimension)) matrix = kronecker(matrix, primeMatrix(p));
  return matrix;
}

std::vector<std::uint64_t> sdkCell(std::uint64_t n, int dimension, int levels) {
  const Rows matrix = sdkMatrix(dimension);
  if (levels < 1 || dimension * levels > 63)
    throw std::invalid_argument("sdkCell: " + std::to_string(levels) + " levels in " + std::to_string(dimension) +
                                " dimensions need more than 63 bits");
  const std::uint64_t groupMask = (std::uint64_t{1} << dimension) - 1;
  std::vector<std::uint64_t> cell(static_cast<std::size_t>(dimension), 0);
  for (int level = 0; level < levels; ++level) {
    const std::uint64_t group = (n >> (level * dimension)) & groupMask;
    for (int axis = 0; axis < dimension; ++axis) {
      const auto bit = static_cast<std::uint64_t>(std::popcount(matrix[static_cast<std::size_t>(axis)] & group) & 1);
      cell[static_cast<std::size_t>(axis)] |= bit << (levels - 1 - level);
    }
  }
  return cell;
}

int SdkSequence::levelsFor(int dimension) { return std::min(20, 63 / dimension); }

SdkSequence::SdkSequence(int maxDimension, RandomSource& random) : maxDimension_(maxDimension), random_(random) {
  if (maxDimension < 1 || maxDimension > 63)
    throw std::invalid_argument("SdkSequence: dimension " + std::to_string(maxDimension) + " outside 1..63");
}

void SdkSequence::next(int dimension, double* point) {
  if (dimension < 1 || dimension > maxDimension_)
    throw std::invalid_argument("SdkSequence::next: dimension " + std::to_string(dimension) + " outside 1.." +
                                std::to_string(maxDimension_));
  const int levels = levelsFor(dimension);
  auto [entry, isNew] = streams_.try_emplace(dimension);
  Stream& stream = entry->second;
  if (isNew) {
    // The start: 64 random bits (two draws of 32), cut to the tree's d·levels bits.
    const auto high = static_cast<std::uint64_t>(random_.uniform01() * 0x1.0p32);
    const auto low = static_cast<std::uint64_t>(random_.uniform01() * 0x1.0p32);
    stream.index = ((high << 32) | low) & ((std::uint64_t{1} << (dimension * levels)) - 1);
  }
  const std::vector<std::uint64_t> cell = sdkCell(stream.index++, dimension, levels);
  const double cellSize = std::ldexp(1.0, -levels);
  for (int axis = 0; axis < dimension; ++axis) {
    const double value = (static_cast<double>(cell[static_cast<std::size_t>(axis)]) + random_.uniform01()) * cellSize;
    point[axis] = std::min(value, 0x1.fffffffffffffp-1);
  }
}

}  // namespace pmdplan
