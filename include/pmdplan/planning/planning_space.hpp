#pragma once
// What the planner knows about the robot: the active joints in configuration order and which of
// them form the arm and the hand. A plain value, so the planner is testable with hand-built spaces;
// robot_planning_space.hpp builds one from a RobotModel.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

struct PlanningSpace {
  /// Active joints, configuration order (arm first then hand, as the model defines it).
  JointLimits joints;
  /// Configuration indices of the arm joints and of the hand joints (together: every joint once).
  /// A hand alone has no arm joints: the planner then samples hands only (Algorithm 4 without its
  /// arm part).
  std::vector<int> armIndices;
  std::vector<int> handIndices;

  int dof() const { return static_cast<int>(joints.size()); }
  std::vector<std::string> jointNames() const;
  /// Configuration index of a joint, or -1.
  int indexOf(const std::string& jointName) const;

  /// Throws std::invalid_argument if a range is not positive and finite, an index is out of range,
  /// or the arm and hand indices do not split the joints into two disjoint groups, the hand's
  /// non-empty.
  void check() const;

  /// Joint values to [0, 1] by their limits and back (the paper's planning metric).
  Eigen::VectorXd normalise(const Configuration& q) const;
  Configuration denormalise(const Eigen::VectorXd& unit) const;
  /// Euclidean distance in normalised joint space (all joints).
  double distance(const Configuration& a, const Configuration& b) const;
  /// Euclidean distance in normalised joint space over the arm joints only.
  double armDistance(const Configuration& a, const Configuration& b) const;
  bool withinLimits(const Configuration& q, double tolerance = 1e-9) const;
};

}  // namespace pmdplan
