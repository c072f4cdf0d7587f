#pragma once
// Internal: how URDF spells a capsule — a cylinder with a sphere of its radius on each cap centre.
// Both checkers treat such a triple as one capsule part (link_part_model.hpp): the same solid, and
// a segment core that GJK decides exactly where a cylinder's rim converges slowly.
#include <vector>

#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct UrdfCapsule {
  int cylinder = -1;         ///< index into the link's collision shapes
  int capA = -1, capB = -1;  ///< the spheres on its cap centres (-1: a plain cylinder)
  double radius = 0.0;       ///< the largest of the three radii (they agree to rounding)
};

/// One entry per cylinder of `shapes`, in order.
std::vector<UrdfCapsule> urdfCapsules(const std::vector<PlacedShape>& shapes);

}  // namespace pmdplan
