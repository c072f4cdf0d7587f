#pragma once
// Internal: the exact checker's own route for two convex primitives (boxes, cylinders, spheres,
// capsules as convex_part.hpp holds them), used instead of FCL 0.7, which calls some contacts free:
// box against cylinder (GJK, GST_INDEP) by up to a few millimetres near the paper's cans, box
// against capsule, and cylinder against box by 0.02 mm at a fingertip on the table (the near-contact
// differential test, tests/collision/near_contact_test.cpp, found each). Closed forms where they
// exist (two capsules: their segments' distance; a sphere: its centre's distance), otherwise GJK
// with proven bounds on the cores (fast/convex_distance.hpp). Two primitives collide unless they
// are proven apart, so a penetration is never called free; a pair within a nanometre of touching
// counts as touching.
#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan {

/// True unless `a` and `b` (placed in one frame) are proven apart.
bool primitivesTouch(const ConvexPart& a, const ConvexPart& b);

/// Is `point` inside (or on) the box, cylinder or capsule `part`?
bool primitiveContainsPoint(const ConvexPart& part, const double* point);

/// Their distance (to 1e-6 relative, and never more than the true one) when apart; when they
/// overlap, minus a lower bound on their penetration depth: exact when a sphere or capsule core
/// stays outside the other part, else twice the radius of the largest ball found inside both
/// (bisected to 1 micrometre), 0 when they only touch.
double primitiveSignedDistance(const ConvexPart& a, const ConvexPart& b);

}  // namespace pmdplan
