#include "pmdplan/collision/fast/convex_distance.hpp"

#include <algorithm>
#include <cmath>

#include "lane_geometry.hpp"

namespace pmdplan {
namespace {

struct Vec {
  double x = 0, y = 0, z = 0;
};
inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec operator*(Vec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

/// Up to four points of the Minkowski difference a - b of the cores.
struct Simplex {
  Vec p[4];
  int size = 0;
};

Vec differenceSupport(const ConvexPart& a, const ConvexPart& b, Vec direction) {
  const double d[3] = {direction.x, direction.y, direction.z};
  const double negated[3] = {-d[0], -d[1], -d[2]};
  double pa[3], pb[3];
  coreSupport(a, d, pa);
  coreSupport(b, negated, pb);
  return {pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]};
}

// The closest point to the origin of the simplex's hull; the simplex keeps only the vertices of
// the feature that point lies on (Ericson, Real-Time Collision Detection, 5.1.5).
Vec closestOnSegment(Simplex& s) {
  const Vec a = s.p[0], b = s.p[1], ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0.0 ? -dot(a, ab) / length2 : 0.0;
  if (t <= 0.0) {
    s.size = 1;
    return a;
  }
  if (t >= 1.0) {
    s.p[0] = b;
    s.size = 1;
    return b;
  }
  return a + ab * t;
}

Vec closestOnTriangle(Simplex& s) {
  const Vec a = s.p[0], b = s.p[1], c = s.p[2];
  const Vec ab = b - a, ac = c - a;
  const double d1 = -dot(ab, a), d2 = -dot(ac, a);
  if (d1 <= 0.0 && d2 <= 0.0) {
    s.size = 1;
    return a;
  }
  const double d3 = -dot(ab, b), d4 = -dot(ac, b);
  if (d3 >= 0.0 && d4 <= d3) {
    s.p[0] = b, s.size = 1;
    return b;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    s.size = 2;
    return a + ab * (d1 / (d1 - d3));
  }
  const double d5 = -dot(ab, c), d6 = -dot(ac, c);
  if (d6 >= 0.0 && d5 <= d6) {
    s.p[0] = c, s.size = 1;
    return c;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    s.p[1] = c, s.size = 2;
    return a + ac * (d2 / (d2 - d6));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    s.p[0] = b, s.p[1] = c, s.size = 2;
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // A degenerate (flat) triangle: the best of its edges.
    Vec best{};
    double bestNorm = INFINITY;
    Simplex bestSimplex;
    for (const auto& [i, j] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
      Simplex edge;
      edge.p[0] = s.p[i], edge.p[1] = s.p[j], edge.size = 2;
      const Vec v = closestOnSegment(edge);
      if (dot(v, v) < bestNorm) bestNorm = dot(v, v), best = v, bestSimplex = edge;
    }
    s = bestSimplex;
    return best;
  }
  return a + ab * (vb / sum) + ac * (vc / sum);
}

/// False when the origin lies inside the tetrahedron (then the cores intersect).
bool closestOnTetrahedron(Simplex& s, Vec& closest) {
  const Vec a = s.p[0], b = s.p[1], c = s.p[2], d = s.p[3];
  const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
  const double volume = dot(b - a, cross(c - a, d - a));
  // Flat relative to its size: the side tests below mean nothing for a sliver (a tetrahedron of
  // near-parallel support points once claimed a box 0.5 mm from another to meet it).
  const double scale = std::max({dot(b - a, b - a), dot(c - a, c - a), dot(d - a, d - a)});
  const bool flat = std::abs(volume) <= 1e-9 * scale * std::sqrt(scale) || std::abs(volume) <= 1e-30;
  double bestNorm = INFINITY;
  Simplex best;
  bool outside = false;
  for (const auto& f : faces) {
    const Vec p = s.p[f[0]], q = s.p[f[1]], r = s.p[f[2]], opposite = s.p[f[3]];
    const Vec normal = cross(q - p, r - p);
    // The origin is beyond this face when it and the opposite vertex lie on different sides.
    const double originSide = -dot(p, normal), oppositeSide = dot(opposite - p, normal);
    if (!flat && originSide * oppositeSide >= 0.0) continue;
    outside = true;
    Simplex face;
    face.p[0] = p, face.p[1] = q, face.p[2] = r, face.size = 3;
    const Vec v = closestOnTriangle(face);
    if (dot(v, v) < bestNorm) bestNorm = dot(v, v), closest = v, best = face;
  }
  if (!outside) return false;
  s = best;
  return true;
}

/// Centre and half width of the part's projection on the unit axis n.
void project(const ConvexPart& p, const double* n, double& centre, double& halfWidth) {
  if (p.kind == ConvexPart::Kind::Capsule) {
    const double pa = p.a[0] * n[0] + p.a[1] * n[1] + p.a[2] * n[2], pb = p.b[0] * n[0] + p.b[1] * n[1] + p.b[2] * n[2];
    centre = 0.5 * (pa + pb), halfWidth = 0.5 * std::abs(pb - pa) + p.radius;
    return;
  }
  const double* m = p.axes;
  centre = p.a[0] * n[0] + p.a[1] * n[1] + p.a[2] * n[2];
  const double u = std::abs(m[0] * n[0] + m[3] * n[1] + m[6] * n[2]),
               v = std::abs(m[1] * n[0] + m[4] * n[1] + m[7] * n[2]),
               w = std::abs(m[2] * n[0] + m[5] * n[1] + m[8] * n[2]);
  if (p.kind == ConvexPart::Kind::Box)
    halfWidth = p.half[0] * u + p.half[1] * v + p.half[2] * w;
  else
    halfWidth = p.half[1] * w + p.half[0] * std::sqrt(std::max(0.0, 1.0 - w * w));
}

/// The largest gap between the two parts' projections on the face normals of their boxes and the
/// axes of their cylinders: a lower bound on their distance (separating axes), tight when the
/// closest features are a face and anything.
double faceSeparation(const ConvexPart& a, const ConvexPart& b) {
  double best = -INFINITY;
  for (const ConvexPart* p : {&a, &b}) {
    if (p->kind == ConvexPart::Kind::Capsule) continue;
    for (int k = p->kind == ConvexPart::Kind::Box ? 0 : 2; k < 3; ++k) {
      const double n[3] = {p->axes[k], p->axes[3 + k], p->axes[6 + k]};
      double ca, wa, cb, wb;
      project(a, n, ca, wa);
      project(b, n, cb, wb);
      best = std::max(best, std::abs(ca - cb) - wa - wb);
    }
  }
  return best;
}

}  // namespace

double segmentDistance(const double* p0, const double* p1, const double* q0, const double* q1) {
  // Minimise |p0 + s d1 - q0 - t d2| over s, t in [0, 1]: the unconstrained optimum of s, clamped,
  // then the best t for it, clamped, then s again for a clamped t (Ericson 5.1.9).
  constexpr double kTiny = 1e-24;  // squared length (m^2) below which a segment is a point
  double d1[3], d2[3], r[3];
  for (int i = 0; i < 3; ++i) d1[i] = p1[i] - p0[i], d2[i] = q1[i] - q0[i], r[i] = p0[i] - q0[i];
  const auto dot3 = [](const double* u, const double* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const auto clamp01 = [](double x) { return std::min(std::max(x, 0.0), 1.0); };
  const double a = dot3(d1, d1), e = dot3(d2, d2), f = dot3(d2, r);
  double s = 0.0, t = 0.0;
  if (a <= kTiny && e <= kTiny) {
    // two points
  } else if (a <= kTiny) {
    t = clamp01(f / e);
  } else {
    const double c = dot3(d1, r);
    if (e <= kTiny) {
      s = clamp01(-c / a);
    } else {
      const double b = dot3(d1, d2);
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
  return std::sqrt(dot3(d, d));
}
// GCC clones these for AVX2; clang (the sanitizer and fuzz build) rejects AVX vectors passed to the
// non-cloned inline helpers, so there they are built for the baseline only (the same results).
#if defined(__clang__)
#define PMDPLAN_AVX2_CLONES
#else
#define PMDPLAN_AVX2_CLONES [[gnu::target_clones("avx2", "default")]]
#endif

// lanes::segmentDistance over plain arrays, four lanes at a time (built for AVX2 and the SSE2
// baseline; the loader picks one for the running CPU).
PMDPLAN_AVX2_CLONES void segmentDistances(const double* p0, const double* p1, const double* q0, const double* q1,
                                          double* distances) {
  using V = lanes::Vec<4>;
  constexpr int L = kSegmentLanes;
  for (int first = 0; first < L; first += 4) {
    const auto point = [&](const double* p) { return lanes::loadPoint<V>(p + first, L); };
    lanes::store(distances + first, lanes::segmentDistance(point(p0), point(p1), point(q0), point(q1)));
  }
}

double sphereGap(const ConvexPart& part, const double* c, double r) {
  if (part.kind == ConvexPart::Kind::Capsule) return segmentDistance(c, c, part.a, part.b) - part.radius - r;
  const double dx = c[0] - part.a[0], dy = c[1] - part.a[1], dz = c[2] - part.a[2];
  const double* m = part.axes;
  const double u = m[0] * dx + m[3] * dy + m[6] * dz;  // local coordinates: rotation transposed
  const double v = m[1] * dx + m[4] * dy + m[7] * dz;
  const double w = m[2] * dx + m[5] * dy + m[8] * dz;
  double outside2;
  if (part.kind == ConvexPart::Kind::Box) {
    const double ou = std::max(std::abs(u) - part.half[0], 0.0), ov = std::max(std::abs(v) - part.half[1], 0.0),
                 ow = std::max(std::abs(w) - part.half[2], 0.0);
    outside2 = ou * ou + ov * ov + ow * ow;
  } else {
    const double radial = std::max(std::sqrt(u * u + v * v) - part.half[0], 0.0),
                 axial = std::max(std::abs(w) - part.half[1], 0.0);
    outside2 = radial * radial + axial * axial;
  }
  return std::sqrt(outside2) - r;
}

namespace {

// One kernel per kind, without branches on the data, so the loop vectorises (this file is built
// with -fno-math-errno -fno-trapping-math, see CMakeLists.txt).
template <ConvexPart::Kind K>
[[gnu::always_inline]] inline void gapsOf(const ConvexPart& p, const double* x, const double* y, const double* z,
                                          const double* r, int count, double* gaps) {
  const double cx = p.a[0], cy = p.a[1], cz = p.a[2];
  const double* m = p.axes;
  const double m0 = m[0], m1 = m[1], m2 = m[2], m3 = m[3], m4 = m[4], m5 = m[5], m6 = m[6], m7 = m[7], m8 = m[8];
  const double h0 = p.half[0], h1 = p.half[1], h2 = p.half[2];
  const double ex = p.b[0] - cx, ey = p.b[1] - cy, ez = p.b[2] - cz;
  const double length2 = ex * ex + ey * ey + ez * ez, inverse = length2 > 0.0 ? 1.0 / length2 : 0.0;
  for (int i = 0; i < count; ++i) {
    const double dx = x[i] - cx, dy = y[i] - cy, dz = z[i] - cz;
    double outside;
    if constexpr (K == ConvexPart::Kind::Capsule) {
      const double t = std::min(std::max((dx * ex + dy * ey + dz * ez) * inverse, 0.0), 1.0);
      const double qx = dx - t * ex, qy = dy - t * ey, qz = dz - t * ez;
      outside = std::sqrt(qx * qx + qy * qy + qz * qz) - p.radius;
    } else {
      const double u = m0 * dx + m3 * dy + m6 * dz, v = m1 * dx + m4 * dy + m7 * dz, w = m2 * dx + m5 * dy + m8 * dz;
      if constexpr (K == ConvexPart::Kind::Box) {
        const double ou = std::max(std::abs(u) - h0, 0.0), ov = std::max(std::abs(v) - h1, 0.0),
                     ow = std::max(std::abs(w) - h2, 0.0);
        outside = std::sqrt(ou * ou + ov * ov + ow * ow);
      } else {
        const double radial = std::max(std::sqrt(u * u + v * v) - h0, 0.0), axial = std::max(std::abs(w) - h1, 0.0);
        outside = std::sqrt(radial * radial + axial * axial);
      }
    }
    gaps[i] = outside - r[i];
  }
}

}  // namespace

// Built for AVX2 and the SSE2 baseline; the loader picks one for the running CPU.
PMDPLAN_AVX2_CLONES void sphereGaps(const ConvexPart& part, const double* x, const double* y, const double* z,
                                    const double* r, int count, double* gaps) {
  switch (part.kind) {
    case ConvexPart::Kind::Capsule:
      return gapsOf<ConvexPart::Kind::Capsule>(part, x, y, z, r, count, gaps);
    case ConvexPart::Kind::Box:
      return gapsOf<ConvexPart::Kind::Box>(part, x, y, z, r, count, gaps);
    case ConvexPart::Kind::Cylinder:
      return gapsOf<ConvexPart::Kind::Cylinder>(part, x, y, z, r, count, gaps);
    case ConvexPart::Kind::Triangle:
      break;  // only the exact checker's mesh route holds triangles
  }
}

CoreDistance coreDistance(const ConvexPart& a, const ConvexPart& b, double radii, double band,
                          double relativePrecision) {
  constexpr int kMaxIterations = 48;
  constexpr double kAbsolutePrecision = 1e-9;  // m
  Simplex simplex;
  const Vec towards = Vec{b.boundCentre[0], b.boundCentre[1], b.boundCentre[2]} -
                      Vec{a.boundCentre[0], a.boundCentre[1], a.boundCentre[2]};
  Vec v = differenceSupport(a, b, towards);
  simplex.p[0] = v, simplex.size = 1;
  CoreDistance result;
  double lower = 0.0;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double vv = dot(v, v);
    if (vv <= 1e-30) break;  // the origin is (numerically) on the hull: the cores touch
    const double upper = std::sqrt(vv);
    // Every point x of a - b has v.x >= v.w: the plane through w normal to v bounds the distance.
    const Vec w = differenceSupport(a, b, v * -1.0);
    const double vw = dot(v, w);
    if (vw > 0.0) lower = std::max(lower, vw / upper);
    const bool overlapping = upper - radii < -band;
    const bool apart = lower - radii > band && upper - lower <= relativePrecision * (lower - radii);
    if (overlapping || apart || upper - lower <= kAbsolutePrecision || vv - vw <= 1e-13 * vv) {
      result.lower = lower, result.upper = upper;
      return result;
    }
    simplex.p[simplex.size++] = w;
    switch (simplex.size) {
      case 2:
        v = closestOnSegment(simplex);
        break;
      case 3:
        v = closestOnTriangle(simplex);
        break;
      default:
        if (!closestOnTetrahedron(simplex, v)) {
          result.intersecting = true;
          return result;
        }
    }
    result.lower = lower, result.upper = std::sqrt(dot(v, v));
  }
  if (dot(v, v) <= 1e-30) result.intersecting = true, result.lower = result.upper = 0.0;
  return result;
}

PartContact partContact(const ConvexPart& a, const ConvexPart& b, double band) {
  // The outer capsules first: exact for two capsules, a cheap proof of "apart" otherwise.
  const double outer = segmentDistance(a.outerA, a.outerB, b.outerA, b.outerB) - a.outerRadius - b.outerRadius;
  if (outer > band) return {Contact::Apart, outer};
  const bool capsuleA = a.kind == ConvexPart::Kind::Capsule, capsuleB = b.kind == ConvexPart::Kind::Capsule;
  const double radii = a.radius + b.radius;
  double lower, upper;
  bool intersecting = false;
  if (capsuleA && capsuleB) {
    lower = upper = outer + radii;
    intersecting = upper <= 0.0;
  } else if ((capsuleA && a.a[0] == a.b[0] && a.a[1] == a.b[1] && a.a[2] == a.b[2]) ||
             (capsuleB && b.a[0] == b.b[0] && b.a[1] == b.b[1] && b.a[2] == b.b[2])) {
    // A sphere against a box or cylinder: the point distance is exact (0 inside).
    const ConvexPart& ball = capsuleA ? a : b;
    lower = upper = sphereGap(capsuleA ? b : a, ball.a, 0.0);
    intersecting = upper <= 0.0;
  } else {
    // A face (or cylinder axis) that separates them is cheaper than GJK and often as tight.
    const double faces = faceSeparation(a, b);
    if (faces > band) return {Contact::Apart, faces};
    const CoreDistance d = coreDistance(a, b, radii, band);
    lower = d.lower, upper = d.upper, intersecting = d.intersecting;
  }
  if (lower - radii > band) return {Contact::Apart, lower - radii};
  if (upper - radii < -band) return {Contact::Overlapping, 0.0};
  if (intersecting) {
    // Cores that meet with (almost) no radius around them: a box or cylinder touching another.
    // If the parts still meet after both shrink by band on every side, a ball of radius band lies
    // in both: FCL finds that contact too.
    ConvexPart sa, sb;
    if (shrinkPart(a, band, sa) && shrinkPart(b, band, sb)) {
      const CoreDistance shrunk = coreDistance(sa, sb, sa.radius + sb.radius);
      if (shrunk.intersecting || shrunk.upper < sa.radius + sb.radius) return {Contact::Overlapping, 0.0};
    }
  }
  return {Contact::Uncertain, 0.0};
}

}  // namespace pmdplan
