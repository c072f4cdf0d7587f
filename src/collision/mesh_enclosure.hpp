#pragma once
// Internal: the fast checker's stand-in for a mesh. The exact checker tests a mesh's triangles;
// the fast checker bounds them by one convex part that contains every vertex (so the triangles and their convex
// hull): the smallest by volume of boxes, cylinders and capsules along the mesh's own axes and its
// vertices' principal axes. The part is marked as an enclosure: apart from it is apart from the
// mesh, an overlap with it proves nothing (the exact checker decides).
#include <Eigen/Geometry>

#include "pmdplan/collision/convex_part.hpp"
#include "pmdplan/model/collision_shape.hpp"

namespace pmdplan {

/// The enclosure of `mesh` placed by `pose` (mesh frame -> the part's frame). Reads the file if
/// the shape's triangles were not read (InputError naming it if that fails).
ConvexPart meshEnclosure(const MeshShape& mesh, const Eigen::Isometry3d& pose);

}  // namespace pmdplan
