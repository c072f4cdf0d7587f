#pragma once
// The exact checker, the independent certifier (validate, check, view): self-collision over the
// enabled link pairs and collision of every link with the task's static obstacles. Two primitives
// (box, cylinder, sphere, a URDF capsule) take our own route, closed forms or GJK with proven
// bounds, that calls them touching unless it proves them apart (primitive_contact.hpp: FCL 0.7
// calls some box-cylinder and box-capsule penetrations free). A mesh against a primitive is its
// triangles, each tested the same way (mesh_part_contact.hpp); two meshes go to FCL, triangle
// against triangle (GST_INDEP; the libccd default gives wrong answers in FCL 0.7). Where no
// triangle touches, geometry wholly inside a closed mesh collides with it too (a winding-number
// test), so that meshes are solids like the primitives.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/collision/collision_report.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/model/forward_kinematics.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// How far the robot is from an obstacle: the smallest distance, or when they overlap minus the
/// deepest penetration (a lower bound on it, primitive_contact.hpp; FCL's for meshes), with the
/// link and obstacle it was found for.
struct Clearance {
  double metres = 0.0;
  CollisionPair pair;
};

class ExactCollisionChecker : public StateValidator {
 public:
  /// The robot, its base pose and the obstacles of `task` (kept by reference: outlive the checker).
  explicit ExactCollisionChecker(const Task& task);
  ~ExactCollisionChecker() override;
  ExactCollisionChecker(const ExactCollisionChecker&) = delete;
  ExactCollisionChecker& operator=(const ExactCollisionChecker&) = delete;

  bool isValid(const Configuration& q) override;
  bool isArmValid(const Configuration& q) override;
  std::size_t checkCount() const override { return checks_; }

  /// Every colliding pair (self and environment), not just the first.
  CollisionReport check(const Configuration& q);
  /// Smallest distance between any of `links` and the obstacle `obstacleName` (negative or zero
  /// when they touch). Throws std::invalid_argument for unknown names.
  double distanceToObstacle(const Configuration& q, const std::vector<int>& links, const std::string& obstacleName);
  /// The robot's clearance from the obstacles (or only from `obstacleName`); nullopt when the
  /// task has no (such) obstacle or no link has geometry.
  std::optional<Clearance> clearance(const Configuration& q, const std::optional<std::string>& obstacleName = {});

  const RobotModel& model() const { return model_; }
  /// The task it was built on.
  const Task& task() const { return task_; }
  const ForwardKinematics& kinematics() const { return kinematics_; }

  // Pair-level access for checkers that confirm only some pairs (the fast checker): the exact
  // tests isValid runs, one pair at a time, on poses from kinematics().linkPoses(q).
  /// Enabled self-collision pairs (both links with geometry, not disabled), in the order checked.
  const std::vector<std::pair<int, int>>& selfPairs() const;
  /// Links whose pose depends on arm joints only (the pairs isArmValid checks have both).
  bool isArmLink(int link) const { return armLink_[static_cast<std::size_t>(link)] != 0; }
  bool linkPairCollides(const LinkPoses& poses, int linkA, int linkB) const;
  bool linkObstacleCollides(const LinkPoses& poses, int link, std::size_t obstacle) const;

 private:
  struct Geometry;
  bool selfCollides(const LinkPoses& poses, bool armOnly, CollisionReport* report) const;
  /// Signed distance of the link (posed in poses_) from obstacle `o`.
  double linkObstacleDistance(int link, std::size_t o) const;
  bool environmentCollides(const LinkPoses& poses, CollisionReport* report) const;

  const Task& task_;
  const RobotModel& model_;
  ForwardKinematics kinematics_;
  std::unique_ptr<Geometry> geometry_;
  std::vector<char> armLink_;
  LinkPoses poses_;
  std::size_t checks_ = 0;
};

}  // namespace pmdplan
