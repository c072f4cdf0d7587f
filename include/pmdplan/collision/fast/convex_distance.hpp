#pragma once
// Distances between convex parts (convex_part.hpp), with proofs in both directions, for the fast
// checker's narrow phase:
//  - coreDistance: GJK (Gilbert, Johnson, Keerthi) on the cores, returning a lower bound (the
//    supporting plane of the last support point) and an upper bound (the closest point of the
//    simplex, a point of the Minkowski difference) on their distance;
//  - partContact: whether two parts are certainly apart (with a lower bound on the gap), certainly
//    overlapping by more than `band`, or too close to call — the only case the caller has to hand
//    to the exact checker, whose own margins are far below `band`.
#include <cstdint>

#include "pmdplan/collision/convex_part.hpp"

namespace pmdplan {

/// Distance between the segments p0-p1 and q0-q1 (either may be a point).
double segmentDistance(const double* p0, const double* p1, const double* q0, const double* q1);

/// segmentDistance for kSegmentLanes segment pairs at once, each point given as x[lane], then
/// y[lane], then z[lane] (12 numbers a point): without branches, in SIMD; equal up to rounding.
constexpr int kSegmentLanes = 8;
void segmentDistances(const double* p0, const double* p1, const double* q0, const double* q1, double* distances);

/// Exact distance from the sphere (centre c, radius r) to the part, minus r; <= 0 when they touch.
double sphereGap(const ConvexPart& part, const double* c, double r);
/// sphereGap of `count` spheres (centres x, y, z; radii r) into gaps[i], in one vectorised pass.
void sphereGaps(const ConvexPart& part, const double* x, const double* y, const double* z, const double* r, int count,
                double* gaps);

struct CoreDistance {
  double lower = 0.0;         ///< the cores are at least this far apart
  double upper = 0.0;         ///< and at most this far
  bool intersecting = false;  ///< the cores share a point (lower = upper = 0)
};

/// GJK on the two cores, for parts whose radii add up to `radii`: it runs until the parts are
/// proven to overlap by more than `band` (upper - radii < -band), or proven apart by more than
/// `band` with the gap (distance - radii) known to `relativePrecision`, or the bounds agree to
/// 1 nm, or a fixed number of iterations has passed. The bounds hold whenever it stops.
CoreDistance coreDistance(const ConvexPart& a, const ConvexPart& b, double radii = 0.0, double band = 0.0,
                          double relativePrecision = 0.05);

enum class Contact : std::uint8_t {
  Apart,        ///< gap > band: the exact checker finds no contact
  Overlapping,  ///< interpenetrating by more than band: the exact checker finds it
  Uncertain,    ///< within band of touching: ask the exact checker
};

struct PartContact {
  Contact contact = Contact::Uncertain;
  double gap = 0.0;  ///< when Apart: a lower bound on the distance between the parts (> band)
};

PartContact partContact(const ConvexPart& a, const ConvexPart& b, double band);

}  // namespace pmdplan
