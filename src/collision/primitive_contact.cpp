#include "primitive_contact.hpp"

#include <algorithm>

#include "pmdplan/collision/fast/convex_distance.hpp"

namespace pmdplan {
namespace {

bool isPoint(const ConvexPart& p) {
  return p.kind == ConvexPart::Kind::Capsule && p.a[0] == p.b[0] && p.a[1] == p.b[1] && p.a[2] == p.b[2];
}

/// Closed forms: two capsules (a sphere is a capsule), or a sphere against a box or cylinder.
bool closedForm(const ConvexPart& a, const ConvexPart& b, double& signedDistance) {
  if (a.kind == ConvexPart::Kind::Capsule && b.kind == ConvexPart::Kind::Capsule) {
    signedDistance = segmentDistance(a.a, a.b, b.a, b.b) - a.radius - b.radius;
    return true;
  }
  const bool triangle = a.kind == ConvexPart::Kind::Triangle || b.kind == ConvexPart::Kind::Triangle;
  if (!triangle && (isPoint(a) || isPoint(b))) {
    const ConvexPart& ball = isPoint(a) ? a : b;
    // sphereGap is 0 inside a box or cylinder: the depth below is then a lower bound.
    signedDistance = sphereGap(isPoint(a) ? b : a, ball.a, ball.radius);
    return true;
  }
  return false;
}

constexpr double kRelativePrecision = 1e-6;

}  // namespace

bool primitivesTouch(const ConvexPart& a, const ConvexPart& b) {
  const double outer = segmentDistance(a.outerA, a.outerB, b.outerA, b.outerB) - a.outerRadius - b.outerRadius;
  if (outer > 0.0) return false;
  double closed;
  if (closedForm(a, b, closed)) return closed <= 0.0;
  const CoreDistance d = coreDistance(a, b, a.radius + b.radius, 0.0, kRelativePrecision);
  return !(d.lower - (a.radius + b.radius) > 0.0);
}

bool primitiveContainsPoint(const ConvexPart& part, const double* point) {
  return part.kind != ConvexPart::Kind::Triangle && sphereGap(part, point, 0.0) <= 0.0;
}

double primitiveSignedDistance(const ConvexPart& a, const ConvexPart& b) {
  double closed;
  if (closedForm(a, b, closed)) return closed;
  const double radii = a.radius + b.radius;
  const CoreDistance d = coreDistance(a, b, radii, 0.0, kRelativePrecision);
  if (d.lower - radii > 0.0) return d.lower - radii;
  if (!d.intersecting && d.upper - radii < 0.0) return d.upper - radii;
  // The cores meet: bisect the largest amount both can shrink by on every side and still meet (a
  // ball of that radius lies in both, so no translation shorter than twice it separates them).
  double inside = 0.0, outside = 1.0;
  ConvexPart sa, sb;
  for (int i = 0; i < 40 && outside - inside > 1e-6; ++i) {
    const double middle = 0.5 * (inside + outside);
    const bool meet =
        shrinkPart(a, middle, sa) && shrinkPart(b, middle, sb) &&
        !(coreDistance(sa, sb, sa.radius + sb.radius, 0.0, kRelativePrecision).lower - (sa.radius + sb.radius) > 0.0);
    (meet ? inside : outside) = middle;
  }
  return -2.0 * inside;
}

}  // namespace pmdplan
