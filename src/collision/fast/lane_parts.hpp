#pragma once
// A placed part in the batch screen's scratch (BatchScratch::partLanes): its numbers as
// [value][lane], kLanes lanes apart whatever the lane vector's width, and the reads and writes of
// them the pair kernels share. Always inlined.
#include "lane_vector.hpp"
#include "pmdplan/collision/batched_forward_kinematics.hpp"

namespace pmdplan::fast {

using lanes::Point;
constexpr int L = BatchedForwardKinematics::kLanes;
/// A placed part, [value][lane]: its core's a (or centre) and b, its rotation (row-major), its
/// bounding sphere's centre, its outer capsule's ends.
constexpr int kPartAxes = 6, kPartBound = 15, kPartOuter = 18, kPartValues = 24;

template <class V>
[[gnu::always_inline]] inline Point<V> pointAt(const double* p) {
  return lanes::loadPoint<V>(p, L);
}

template <class V>
[[gnu::always_inline]] inline void storePoint(double* out, const Point<V>& p) {
  lanes::store(out, p.x), lanes::store(out + L, p.y), lanes::store(out + 2 * L, p.z);
}

/// Row r of pose * p lane by lane; `m` is a link's pose, [value][lane]. A function always inlined,
/// not a lambda: a lambda's body is a function of its own, built for the baseline instruction set
/// whatever the kernel it sits in, and a vector it returns to an AVX kernel comes back where the
/// baseline ABI puts it, not where the kernel reads it (garbage lanes wherever the compiler does
/// not inline the lambda: clang at -O1, the sanitizer build, so checks called free what collides).
template <class V>
[[gnu::always_inline]] inline V transformedRow(const double* m, const double* p, int r) {
  using lanes::load;
  return load<V>(m + (r * 3) * L) * p[0] + load<V>(m + (r * 3 + 1) * L) * p[1] + load<V>(m + (r * 3 + 2) * L) * p[2] +
         load<V>(m + (9 + r) * L);
}
template <class V>
[[gnu::always_inline]] inline Point<V> transformed(const double* m, const double* p) {
  return {transformedRow<V>(m, p, 0), transformedRow<V>(m, p, 1), transformedRow<V>(m, p, 2)};
}

/// Axis k (a column of the rotation) of a placed part.
template <class V>
[[gnu::always_inline]] inline Point<V> axisOf(const double* part, int k) {
  const double* axes = part + kPartAxes * L;
  return {lanes::load<V>(axes + k * L), lanes::load<V>(axes + (3 + k) * L), lanes::load<V>(axes + (6 + k) * L)};
}

}  // namespace pmdplan::fast
