#pragma once
// The robot's and the task's collision geometry as convex parts for the fast checker, equal to what
// the exact checker tests: a URDF cylinder with a sphere of its radius on each cap centre
// (how URDF spells a capsule) is that capsule, a sphere inside such a capsule adds nothing and is
// dropped, other spheres are point capsules, boxes and cylinders stay as they are. A mesh (of a
// link or an obstacle) is stood in for by its enclosure (mesh_enclosure.hpp: the smallest box,
// cylinder or capsule around its vertices), which only ever proves "apart". Every link gets a
// bounding sphere around its parts for the broad phase. Obstacles are parts in the world.
#include <vector>

#include "pmdplan/collision/convex_part.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct LinkParts {
  std::vector<ConvexPart> parts;  ///< in the link frame; their union is the link's geometry
  double boundCentre[3] = {0, 0, 0};
  double boundRadius = 0.0;  ///< the sphere contains every part
  bool empty() const { return parts.empty(); }
};

/// Indexed like RobotModel::links(); empty for links without geometry. Throws InputError naming
/// the mesh file if a mesh whose triangles were not read cannot be read.
std::vector<LinkParts> linkParts(const RobotModel& model);

struct ObstaclePart {
  ConvexPart part;    ///< in the world
  bool exact = true;  ///< false: a mesh's enclosure (the mesh lies inside it)
};

/// Throws InputError naming the mesh file if a mesh cannot be read.
std::vector<ObstaclePart> obstacleParts(const std::vector<Obstacle>& obstacles);

}  // namespace pmdplan
