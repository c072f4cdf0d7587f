#include "pmdplan/planning/van_der_corput.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace pmdplan {

std::size_t segmentIntervals(double length, double spacing) {
  if (!(spacing > 0.0) || !std::isfinite(spacing) || !(length >= 0.0) || !std::isfinite(length))
    throw std::invalid_argument("segmentIntervals: need a finite length >= 0 and spacing > 0 (got length " +
                                std::to_string(length) + ", spacing " + std::to_string(spacing) + ")");
  constexpr std::size_t largest = std::size_t{1} << 40;
  std::size_t intervals = 1;
  // Dividing by a power of two is exact, so the test is exactly the one the paper states.
  while (length / static_cast<double>(intervals) > spacing) {
    if (intervals == largest)
      throw std::invalid_argument("segmentIntervals: spacing " + std::to_string(spacing) +
                                  " is too small for a segment of length " + std::to_string(length));
    intervals *= 2;
  }
  return intervals;
}

double vanDerCorput(std::size_t index, std::size_t intervals) {
  if (intervals == 0 || (intervals & (intervals - 1)) != 0)
    throw std::invalid_argument("vanDerCorput: intervals must be a power of two, got " + std::to_string(intervals));
  if (index > intervals)
    throw std::invalid_argument("vanDerCorput: index " + std::to_string(index) + " beyond " +
                                std::to_string(intervals) + " intervals");
  if (index == 0) return 0.0;
  if (index == 1) return 1.0;
  // The radical inverse in base 2 of index-1 = 1, 2, 3, ...: 1/2, 1/4, 3/4, 1/8, ...
  return radicalInverse(index - 1);
}

double radicalInverse(std::size_t n) {
  double value = 0.0;
  for (double digit = 0.5; n != 0; n >>= 1, digit *= 0.5)
    if ((n & 1u) != 0) value += digit;
  return value;
}

}  // namespace pmdplan
