#pragma once
// The order in which Algorithm 4 visits the arm hypercubes along the start-goal segment, and how
// many there are (the paper's VANDERCORPUT and STEPS).
#include <cstddef>

namespace pmdplan {

/// STEPS: the smallest power of two n such that `length / n <= spacing`, i.e. the number of equal
/// intervals the segment is cut into. The hypercube centres are the n + 1 interval ends (0 and 1
/// included). Throws std::invalid_argument unless spacing > 0 and length >= 0 are finite.
std::size_t segmentIntervals(double length, double spacing);

/// VANDERCORPUT: the position (fraction of the segment from its start) of the `index`-th centre,
/// index = 0 .. intervals, in the order 0, 1, 1/2, 1/4, 3/4, 1/8, 5/8, 3/8, 7/8, ...; `intervals`
/// must be a power of two. Each multiple of 1/intervals appears exactly once.
double vanDerCorput(std::size_t index, std::size_t intervals);

/// The base-2 radical inverse of n: 0 for 0, then 1/2, 1/4, 3/4, 1/8, 5/8, ... (vanDerCorput's
/// inner centres; also the lazy planner's segment points and edge probes).
double radicalInverse(std::size_t n);

}  // namespace pmdplan
