#pragma once
// The convex solids the checkers reason about, in plain numbers (no Eigen in the inner loops;
// Eigen types built with other vector flags would misalign against Debian's FCL): capsules (a
// sphere is a capsule with both ends equal), boxes and cylinders, and the triangles of meshes
// (the exact checker's own route for a mesh against a primitive, primitive_contact.hpp; the fast
// checker never holds one). A capsule is its core segment swept by a ball; boxes, cylinders and
// triangles are their own core (radius 0). Distances between parts come from the cores (fast/convex_distance.hpp)
// minus the radii.
#include <cstdint>

namespace pmdplan {

struct ConvexPart {
  enum class Kind : std::uint8_t { Capsule, Box, Cylinder, Triangle };
  Kind kind = Kind::Capsule;
  /// Capsule: its core segment a-b. Box and cylinder: the centre in `a` (b unused). Triangle: its
  /// corners a, b, c.
  double a[3] = {0, 0, 0};
  double b[3] = {0, 0, 0};
  double c[3] = {0, 0, 0};
  /// Box and cylinder: rotation, row-major, local -> frame (its columns are the local axes; a
  /// cylinder's axis is local z).
  double axes[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  /// Box: half extents. Cylinder: radius, half length, 0. Capsule: unused.
  double half[3] = {0, 0, 0};
  /// Capsule: the ball radius. Box, cylinder: 0.
  double radius = 0.0;
  /// A sphere that contains the whole part.
  double boundCentre[3] = {0, 0, 0};
  double boundRadius = 0.0;
  /// A capsule that contains the whole part (the part itself for a capsule; around a cylinder's
  /// axis, or a box's longest axis): two of them apart is the cheapest proof after the spheres.
  double outerA[3] = {0, 0, 0};
  double outerB[3] = {0, 0, 0};
  double outerRadius = 0.0;
  /// True for a part that only encloses a mesh (mesh_enclosure.hpp): apart from it is apart from
  /// the mesh, an overlap with it proves nothing.
  bool enclosure = false;
};

ConvexPart capsulePart(const double* a, const double* b, double radius);
/// `pose`: row-major rotation (9) then translation (3), as BatchedForwardKinematics writes poses.
ConvexPart boxPart(const double* pose, const double* halfExtents);
ConvexPart cylinderPart(const double* pose, double radius, double halfLength);
ConvexPart trianglePart(const double* a, const double* b, const double* c);

/// `local` moved by `pose` (12 values as above) into `world`.
void placePart(const ConvexPart& local, const double* pose, ConvexPart& world);

/// The point of the core farthest along `direction` (need not be unit length).
void coreSupport(const ConvexPart& part, const double* direction, double* point);

/// The part made smaller by `amount` on every side (its core shrunk, or its radius reduced), so
/// that the shrunk part grown by a ball of that radius lies in the original. False if the part is
/// too thin to shrink that much (a triangle always is).
bool shrinkPart(const ConvexPart& part, double amount, ConvexPart& shrunk);

}  // namespace pmdplan
