#pragma once
// Lane vectors: one double per configuration of a batch as a GCC/Clang vector of W lanes, whose
// arithmetic operators work lane by lane and compile to one SIMD instruction each — W = 8 for
// AVX-512, 4 for AVX2, 2 for SSE2, so every kernel is written once, as a template on the vector
// type, and instantiated at the width of the instruction set it is built for (VAMP's design).
// Private to the collision sources; the files that use it are built with -fno-math-errno (sqrt
// without errno branches) and -Wno-psabi (the helpers are always inlined and the kernels hold no
// lambda that returns or takes a vector by value, lane_parts.hpp's transformedRow: no
// vector crosses a call).
#include <cstring>

namespace pmdplan::lanes {

template <int W>
struct Width;
template <>
struct Width<2> {
  typedef double Vec __attribute__((vector_size(16)));
  typedef float Floats __attribute__((vector_size(8)));
};
template <>
struct Width<4> {  // no Floats: sqrtBelow takes the double root at this width
  typedef double Vec __attribute__((vector_size(32)));
};
template <>
struct Width<8> {
  typedef double Vec __attribute__((vector_size(64)));
  typedef float Floats __attribute__((vector_size(32)));
};
template <int W>
using Vec = typename Width<W>::Vec;
template <class V>
constexpr int widthOf = static_cast<int>(sizeof(V) / sizeof(double));
template <class V>
using MaskOf = decltype(V{} < V{});  ///< all ones where true, lane by lane

template <class V>
[[gnu::always_inline]] inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V>
[[gnu::always_inline]] inline void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
template <class V>
[[gnu::always_inline]] inline V splat(double x) {
  return V{} + x;
}
template <class V>
[[gnu::always_inline]] inline V select(MaskOf<V> m, V yes, V no) {
  return m ? yes : no;
}
template <class V>
[[gnu::always_inline]] inline V min(V a, V b) {
  return a < b ? a : b;
}
template <class V>
[[gnu::always_inline]] inline V max(V a, V b) {
  return a > b ? a : b;
}
template <class V>
[[gnu::always_inline]] inline V clamp01(V x) {
  return min(max(x, splat<V>(0.0)), splat<V>(1.0));
}
template <class V>
[[gnu::always_inline]] inline V abs(V x) {
  return x < 0.0 ? -x : x;
}
template <class V>
[[gnu::always_inline]] inline V sqrt(V x) {
  for (int l = 0; l < widthOf<V>; ++l) x[l] = __builtin_sqrt(x[l]);
  return x;
}
/// A lower bound on sqrt(x) from a single-precision square root (several times the throughput of
/// a double one): rounding x to float, the root and the way back are off by under 2e-7 relative
/// together, so 1e-6 less is below the true root. At four lanes (AVX2) the double root is used:
/// GCC 12 widens four floats back to four doubles through the stack there, which costs more than
/// the single-precision root saves (AVX2 configuration checks 7–16 % faster on four of the five
/// tasks, docs/performance.md).
template <class V>
[[gnu::always_inline]] inline V sqrtBelow(V x) {
  if constexpr (widthOf<V> == 4) {
    return sqrt(x) * (1.0 - 1e-6);
  } else {
    using Floats = typename Width<widthOf<V>>::Floats;
    Floats f = __builtin_convertvector(x, Floats);
    for (int l = 0; l < widthOf<V>; ++l) f[l] = __builtin_sqrtf(f[l]);
    return __builtin_convertvector(f, V) * (1.0 - 1e-6);
  }
}
/// Whether any lane of m is true (a few shuffles and ORs).
template <class M>
[[gnu::always_inline]] inline bool any(M m) {
  long long r = 0;
  for (int l = 0; l < static_cast<int>(sizeof(M) / sizeof(long long)); ++l) r |= m[l];
  return r != 0;
}
/// The smallest lane (a tree of shuffles and minimums): `lowest(x) <= y` is "some lane of x <= y"
/// for one comparison instead of a mask reduction.
template <class V>
[[gnu::always_inline]] inline double lowest(V x) {
  double m = x[0];
  for (int l = 1; l < widthOf<V>; ++l) m = x[l] < m ? x[l] : m;
  return m;
}
/// Bit l set where lane l of m is true (slower than any: one extraction a lane).
template <class M>
[[gnu::always_inline]] inline unsigned bits(M m) {
  unsigned b = 0;
  for (int l = 0; l < static_cast<int>(sizeof(M) / sizeof(long long)); ++l) b |= static_cast<unsigned>(m[l] != 0) << l;
  return b;
}

/// A point (or direction) per lane, read from x[stride], y[stride], z[stride].
template <class V>
struct Point {
  V x, y, z;
};
template <class V>
[[gnu::always_inline]] inline Point<V> loadPoint(const double* p, int stride) {
  return {load<V>(p), load<V>(p + stride), load<V>(p + 2 * stride)};
}
template <class V>
[[gnu::always_inline]] inline V dot(const Point<V>& a, const Point<V>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class V>
[[gnu::always_inline]] inline Point<V> operator-(const Point<V>& a, const Point<V>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

}  // namespace pmdplan::lanes
