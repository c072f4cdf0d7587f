#include "pmdplan/collision/primitive_distance.hpp"

namespace pmdplan {
namespace {

// One kernel per kind, without branches, so the loop over spheres vectorises (this file is built
// with -fno-math-errno -fno-trapping-math, see CMakeLists.txt).
template <SolidPrimitive::Kind K>
[[gnu::always_inline]] inline void gapsOf(const SolidPrimitive& p, const double* x, const double* y, const double* z, const double* r, int count, double* gaps) {
  const double cx = p.centre[0], cy = p.centre[1], cz = p.centre[2];
  const double m0 = p.rotation[0], m1 = p.rotation[1], m2 = p.rotation[2], m3 = p.rotation[3], m4 = p.rotation[4],
               m5 = p.rotation[5], m6 = p.rotation[6], m7 = p.rotation[7], m8 = p.rotation[8];
  const double s0 = p.size[0], s1 = p.size[1], s2 = p.size[2];
  for (int i = 0; i < count; ++i) {
    const double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
    const double u = m0 * dx + m3 * dy + m6 * dz, v = m1 * dx + m4 * dy + m7 * dz, w = m2 * dx + m5 * dy + m8 * dz;
    double outside2;
    if constexpr (K == SolidPrimitive::Kind::Box) {
      const double ou = std::max(std::abs(u) - s0, 0.0), ov = std::max(std::abs(v) - s1, 0.0), ow = std::max(std::abs(w) - s2, 0.0);
      outside2 = ou * ou + ov * ov + ow * ow;
    } else if constexpr (K == SolidPrimitive::Kind::Cylinder) {
      const double radial = std::max(std::sqrt(u * u + v * v) - s0, 0.0), axial = std::max(std::abs(w) - s1, 0.0);
      outside2 = radial * radial + axial * axial;
    } else {
      const double d = std::max(std::sqrt(u * u + v * v + w * w) - s0, 0.0);
      outside2 = d * d;
    }
    gaps[i] = std::sqrt(outside2) - r[i];
  }
}

}  // namespace

// Built twice, for AVX2 and for the SSE2 baseline; the loader picks one for the running CPU.
[[gnu::target_clones("avx2", "default")]] void sphereGaps(const SolidPrimitive& p, const double* x, const double* y, const double* z,
                                                          const double* r, int count, double* gaps) {
  switch (p.kind) {
    case SolidPrimitive::Kind::Box: return gapsOf<SolidPrimitive::Kind::Box>(p, x, y, z, r, count, gaps);
    case SolidPrimitive::Kind::Cylinder: return gapsOf<SolidPrimitive::Kind::Cylinder>(p, x, y, z, r, count, gaps);
    default: return gapsOf<SolidPrimitive::Kind::Sphere>(p, x, y, z, r, count, gaps);
  }
}

double smallestSphereGap(const SolidPrimitive& p, const double* x, const double* y, const double* z, const double* r, int count) {
  double gaps[64];
  double smallest = std::numeric_limits<double>::infinity();
  for (int begin = 0; begin < count; begin += 64) {
    const int n = std::min(64, count - begin);
    sphereGaps(p, x + begin, y + begin, z + begin, r + begin, n, gaps);
    for (int i = 0; i < n; ++i) smallest = std::min(smallest, gaps[i]);
  }
  return smallest;
}

double segmentDistance(const double* p0, const double* p1, const double* q0, const double* q1) {
  // Minimise |p0 + s d1 - q0 - t d2| over s, t in [0, 1]: the unconstrained optimum of s, clamped,
  // then the best t for it, clamped, then s again for a clamped t.
  constexpr double kTiny = 1e-24;  // squared length (m^2) below which a segment is a point
  double d1[3], d2[3], r[3];
  for (int i = 0; i < 3; ++i) d1[i] = p1[i] - p0[i], d2[i] = q1[i] - q0[i], r[i] = p0[i] - q0[i];
  const auto dot = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const auto clamp01 = [](double x) { return std::min(std::max(x, 0.0), 1.0); };
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= kTiny && e <= kTiny) {
    // two points
  } else if (a <= kTiny) {
    t = clamp01(f / e);
  } else {
    const double c = dot(d1, r);
    if (e <= kTiny) {
      s = clamp01(-c / a);
    } else {
      const double b = dot(d1, d2);
      const double denominator = a * e - b * b;  // >= 0; 0 for parallel segments (any s will do)
      s = denominator > kTiny * (a + e) ? clamp01((b * f - c * e) / denominator) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = clamp01(-c / a);
      } else if (t > 1.0) {
        t = 1.0;
        s = clamp01((b - c) / a);
      }
    }
  }
  double d[3];
  for (int i = 0; i < 3; ++i) d[i] = r[i] + d1[i] * s - d2[i] * t;
  return std::sqrt(dot(d, d));
}

double capsuleBoxGapLowerBound(const Capsule& capsule, const SolidPrimitive& box) {
  double best = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const double u[3] = {box.rotation[k], box.rotation[3 + k], box.rotation[6 + k]};  // face normal k
    const double pa = (capsule.a[0] - box.centre[0]) * u[0] + (capsule.a[1] - box.centre[1]) * u[1] + (capsule.a[2] - box.centre[2]) * u[2];
    const double pb = (capsule.b[0] - box.centre[0]) * u[0] + (capsule.b[1] - box.centre[1]) * u[1] + (capsule.b[2] - box.centre[2]) * u[2];
    const double low = std::min(pa, pb) - capsule.radius, high = std::max(pa, pb) + capsule.radius;
    best = std::max(best, std::max(low - box.size[k], -box.size[k] - high));
  }
  return best;
}

double boxGapLowerBound(const SolidPrimitive& a, const SolidPrimitive& b) {
  // Axes as world vectors: column k of the row-major rotation.
  double axesA[3][3], axesB[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) {
      axesA[k][i] = a.rotation[i * 3 + k];
      axesB[k][i] = b.rotation[i * 3 + k];
    }
  const double t[3] = {b.centre[0] - a.centre[0], b.centre[1] - a.centre[1], b.centre[2] - a.centre[2]};
  double best = -std::numeric_limits<double>::infinity();
  // Gap along a unit axis: centre distance minus both projected half widths.
  const auto gapAlong = [&](const double* axis) {
    double reach = 0.0;
    for (int k = 0; k < 3; ++k) {
      reach += a.size[k] * std::abs(axesA[k][0] * axis[0] + axesA[k][1] * axis[1] + axesA[k][2] * axis[2]);
      reach += b.size[k] * std::abs(axesB[k][0] * axis[0] + axesB[k][1] * axis[1] + axesB[k][2] * axis[2]);
    }
    return std::abs(t[0] * axis[0] + t[1] * axis[1] + t[2] * axis[2]) - reach;
  };
  // Face normals separate most pairs: a positive gap there is already a valid lower bound.
  for (int k = 0; k < 3; ++k) {
    best = std::max(best, gapAlong(axesA[k]));
    best = std::max(best, gapAlong(axesB[k]));
  }
  if (best > 0.0) return best;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double* u = axesA[i];
      const double* v = axesB[j];
      double axis[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const double length = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      // Parallel edges give no new axis (the face axes already cover that direction).
      if (length < 1e-6) continue;
      for (double& c : axis) c /= length;
      best = std::max(best, gapAlong(axis));
    }
  return best;
}

}  // namespace pmdplan
