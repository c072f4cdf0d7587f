#pragma once
// A robot's kinematic tree read from URDF (any robot, through urdfdom), with the planning groups
// and the self-collision pairs that may be skipped from its SRDF-style companion file.
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/model/collision_shape.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

enum class JointType { Fixed, Revolute, Continuous, Prismatic };

struct Joint {
  std::string name;
  JointType type = JointType::Fixed;
  int parentLink = -1;
  int childLink = -1;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  ///< parent link frame -> joint frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();           ///< unit axis in the joint frame
  double lower = 0.0;
  double upper = 0.0;
  double velocity = 0.0;  ///< URDF <limit velocity> (rad/s or m/s); 0 when not given
  int activeIndex = -1;   ///< position in a Configuration; -1 for fixed and mimic joints
  int mimicSource = -1;   ///< index into joints(); value = multiplier * source + offset
  double mimicMultiplier = 1.0;
  double mimicOffset = 0.0;
};

/// A mesh a link's <visual> names: the reference as the URDF writes it and the file it resolves to
/// (empty when it does not resolve: visuals do not stop planning, the viewer then draws collision
/// geometry).
struct VisualMesh {
  std::string reference;
  std::filesystem::path file;
};

struct Link {
  std::string name;
  int parentJoint = -1;                      ///< -1 for the root link
  std::vector<PlacedShape> collisionShapes;  ///< poses in the link frame
  std::vector<VisualMesh> visualMeshes;
};

class RobotModel {
 public:
  /// Loads a URDF and, if given, its SRDF-style companion (groups, disabled collision pairs).
  /// Throws InputError naming the file and the element on malformed input (unknown mimic source,
  /// mimic cycle, missing limits, unsupported geometry, …).
  static RobotModel load(const std::filesystem::path& urdf,
                         const std::optional<std::filesystem::path>& srdf = std::nullopt);
  /// The built-in robot `name` (data/robots/<name>/<name>.urdf and .srdf).
  static RobotModel loadBuiltIn(const std::string& name);
  /// A built-in robot's name, or a path ending in .urdf (with its .srdf beside it, if present).
  static RobotModel loadByNameOrPath(const std::string& nameOrUrdf);

  const std::string& name() const { return name_; }
  const std::filesystem::path& urdfPath() const { return urdfPath_; }
  const std::vector<Link>& links() const { return links_; }
  const std::vector<Joint>& joints() const { return joints_; }
  /// Joint indices in an order where every parent comes before its children.
  const std::vector<int>& jointOrder() const { return jointOrder_; }
  int rootLink() const { return rootLink_; }

  /// Active joints (the configuration layout): limits and names in configuration order.
  const JointLimits& activeJoints() const { return activeJoints_; }
  int dof() const { return static_cast<int>(activeJoints_.size()); }
  std::vector<std::string> activeJointNames() const;
  /// Index of an active joint in a configuration, or -1.
  int activeIndex(const std::string& jointName) const;
  int linkIndex(const std::string& linkName) const;    ///< -1 if absent
  int jointIndex(const std::string& jointName) const;  ///< -1 if absent

  /// Planning groups from the companion file ("arm", "hand"): active-configuration indices.
  const std::vector<int>& group(const std::string& groupName) const;
  bool hasGroup(const std::string& groupName) const;
  /// The limits of a group's active joints, in configuration order.
  JointLimits groupJoints(const std::string& groupName) const;
  using GroupDefinition = std::pair<std::string, std::vector<std::string>>;
  /// The groups as the companion file names them (joint names, mimic joints included).
  const std::vector<GroupDefinition>& groupDefinitions() const { return groupDefinitions_; }
  /// The hand's base link (the palm frame): the companion file's <end_effector parent_link>, else
  /// the parent link of the "hand" group's first joint, else -1.
  int palmLink() const { return palmLink_; }
  /// Link pairs the companion file lets self-collision skip (sorted link indices).
  const std::vector<std::pair<int, int>>& disabledCollisionPairs() const { return disabledPairs_; }
  bool isCollisionPairDisabled(int linkA, int linkB) const;

  /// This robot with the given active joints held at the given values (rad or m): each becomes a
  /// fixed joint at that value, and so do the joints that mimic it; the configuration layout and
  /// the groups lose them. Throws InputError naming `field` for a joint that is not active.
  RobotModel withHeldJoints(const std::vector<std::pair<std::string, double>>& held, const std::string& field) const;
  /// The value a joint is held at by withHeldJoints, if it is held.
  std::optional<double> heldJointValue(const std::string& jointName) const;
  const std::vector<std::pair<std::string, double>>& heldJoints() const { return heldJoints_; }

  bool withinLimits(const Configuration& q, double tolerance = 1e-9) const;
  /// Joint values to [0, 1] by their limits and back (the paper's planning metric).
  Configuration normalise(const Configuration& q) const;
  Configuration denormalise(const Configuration& unit) const;

 private:
  std::string name_;
  std::filesystem::path urdfPath_;
  std::vector<Link> links_;
  std::vector<Joint> joints_;
  std::vector<int> jointOrder_;
  int rootLink_ = -1;
  int palmLink_ = -1;
  JointLimits activeJoints_;
  std::vector<std::pair<std::string, std::vector<int>>> groups_;
  std::vector<GroupDefinition> groupDefinitions_;
  std::vector<std::pair<int, int>> disabledPairs_;
  std::vector<char> disabledMatrix_;
  std::vector<std::pair<std::string, double>> heldJoints_;

  friend class RobotModelBuilder;
};

}  // namespace pmdplan
