#include "pmdplan/core/sequences/halton_sequence.hpp"

#include <stdexcept>
#include <string>

namespace pmdplan {

std::vector<unsigned> firstPrimes(int count) {
  std::vector<unsigned> primes;
  for (unsigned candidate = 2; static_cast<int>(primes.size()) < count; ++candidate) {
    bool prime = true;
    for (const unsigned p : primes) {
      if (p * p > candidate) break;
      if (candidate % p == 0) {
        prime = false;
        break;
      }
    }
    if (prime) primes.push_back(candidate);
  }
  return primes;
}

double radicalInverseInBase(std::uint64_t n, unsigned base) {
  const double inverseBase = 1.0 / base;
  double value = 0.0;
  double digitWeight = inverseBase;
  while (n > 0) {
    value += static_cast<double>(n % base) * digitWeight;
    n /= base;
    digitWeight *= inverseBase;
  }
  return value;
}

HaltonSequence::HaltonSequence(int firstBase, int dimension, RandomSource& random) {
  if (firstBase < 0 || dimension < 1)
    throw std::invalid_argument("HaltonSequence: needs firstBase >= 0 and dimension >= 1, got " +
                                std::to_string(firstBase) + " and " + std::to_string(dimension));
  const std::vector<unsigned> primes = firstPrimes(firstBase + dimension);
  bases_.assign(primes.begin() + firstBase, primes.end());
  for (int i = 0; i < dimension; ++i) offsets_.push_back(random.uniform01());
}

void HaltonSequence::next(int dimension, double* point) {
  if (dimension < 1 || dimension > static_cast<int>(bases_.size()))
    throw std::invalid_argument("HaltonSequence::next: dimension " + std::to_string(dimension) + " outside 1.." +
                                std::to_string(bases_.size()));
  for (int i = 0; i < dimension; ++i) {
    const double shifted =
        radicalInverseInBase(index_, bases_[static_cast<std::size_t>(i)]) + offsets_[static_cast<std::size_t>(i)];
    point[i] = shifted >= 1.0 ? shifted - 1.0 : shifted;
  }
  ++index_;
}

}  // namespace pmdplan
