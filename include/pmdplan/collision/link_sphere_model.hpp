#pragma once
// Spheres that enclose every collision primitive of every link completely (never a point of a
// primitive outside the union of its spheres), grouped per primitive, with a bounding sphere per
// primitive and per link for early exits. The fast checker's conservative stage runs on them: if
// the spheres are apart, so is the real geometry.
#include <Eigen/Geometry>
#include <vector>

#include "pmdplan/collision/primitive_distance.hpp"
#include "pmdplan/model/collision_shape.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

struct Sphere {
  double centre[3] = {0.0, 0.0, 0.0};
  double radius = 0.0;
};

struct SphereCoverParameters {
  /// Largest distance (m) a sphere may reach beyond the face of the primitive it covers; more
  /// spheres make it smaller (boxes: a finer grid; cylinders: more slices).
  double maxOvershoot = 0.002;
  /// Upper limit on the spheres of one primitive (a huge box then gets a coarser grid).
  int maxSpheresPerShape = 64;
  /// Added to every radius (m): absorbs the rounding difference between the fast kinematics and
  /// the exact checker's, and FCL's contact tolerance, so "apart" stays conservative.
  double safetyMargin = 1e-5;
};

/// Spheres (in the frame the shape is placed in) whose union contains the placed shape. Meshes
/// are not covered (throws std::invalid_argument): robot links here are primitives.
std::vector<Sphere> coverShape(const Shape& shape, const Eigen::Isometry3d& pose, const SphereCoverParameters& parameters = {});

/// A sphere that contains all the given spheres (centre: middle of their bounding box).
Sphere enclosingSphere(const std::vector<Sphere>& spheres);

/// How the fast checker tests a group of primitives: by its covering spheres only, as a capsule
/// (cylinders, and the spheres such a capsule contains, as the SAH phalanges' end caps) or as an
/// exact oriented box. Capsules and boxes keep their spheres for the tests that need them.
enum class GroupKind : char { Spheres, Capsule, Box };

/// Structure of arrays: the spheres of one link (link frame), group by group.
struct LinkSpheres {
  std::vector<double> x, y, z, radius;
  /// Spheres of group g are [groupBegin[g], groupBegin[g + 1]); they contain its primitives.
  std::vector<int> groupBegin{0};
  std::vector<Sphere> groupBounds;  ///< encloses each group's primitives
  std::vector<GroupKind> groupKind;
  /// Per group (meaningful for its kind): the box (half extents grown by the margin) or the
  /// capsule (radius grown by the margin) that contains the group's primitives.
  std::vector<SolidPrimitive> groupBoxes;
  std::vector<Capsule> groupCapsules;
  Sphere bound;  ///< encloses all of the link's primitives
  bool empty() const { return groupKind.empty(); }
  int sphereCount() const { return static_cast<int>(radius.size()); }
  int groupCount() const { return static_cast<int>(groupKind.size()); }
};

class LinkSphereModel {
public:
  explicit LinkSphereModel(const RobotModel& model, const SphereCoverParameters& parameters = {});

  /// Indexed like RobotModel::links(); empty for links without geometry.
  const std::vector<LinkSpheres>& links() const { return links_; }
  int sphereCount() const;
  const SphereCoverParameters& parameters() const { return parameters_; }

private:
  SphereCoverParameters parameters_;
  std::vector<LinkSpheres> links_;
};

}  // namespace pmdplan
