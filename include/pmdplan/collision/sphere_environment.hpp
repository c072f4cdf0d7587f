#pragma once
// The task's obstacles as primitives with exact sphere distance tests (boxes as oriented boxes,
// cylinders, spheres). A mesh is replaced by its bounding box in its own frame, which contains the
// mesh, so the tests stay conservative. Plain numbers only, for the fast checker's inner loops.
#include <cstddef>
#include <string>
#include <vector>

#include "pmdplan/collision/primitive_distance.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

class SphereEnvironment {
public:
  /// Throws InputError (naming the mesh file) if a mesh cannot be read.
  explicit SphereEnvironment(const std::vector<Obstacle>& obstacles);

  std::size_t size() const { return primitives_.size(); }
  const SolidPrimitive& primitive(std::size_t o) const { return primitives_[o]; }
  /// A box that contains obstacle o (the obstacle itself if it is a box).
  const SolidPrimitive& boundingBox(std::size_t o) const { return boxes_[o]; }

  /// Distance between the sphere (centre x, y, z, radius r) and obstacle o: exact when positive,
  /// <= 0 when they touch or overlap.
  double gap(std::size_t o, double x, double y, double z, double r) const { return sphereGap(primitives_[o], x, y, z, r); }
  /// Smallest gap of `count` spheres (arrays of centres and radii) to obstacle o.
  double smallestGap(std::size_t o, const double* x, const double* y, const double* z, const double* r, int count) const {
    return smallestSphereGap(primitives_[o], x, y, z, r, count);
  }

private:
  std::vector<SolidPrimitive> primitives_;
  std::vector<SolidPrimitive> boxes_;
};

}  // namespace pmdplan
