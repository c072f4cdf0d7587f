#pragma once
// Poses of every link for a configuration, in the world frame (the robot's base pose applied).
#include <Eigen/Geometry>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

using LinkPoses = std::vector<Eigen::Isometry3d, Eigen::aligned_allocator<Eigen::Isometry3d>>;

class ForwardKinematics {
 public:
  ForwardKinematics(const RobotModel& model, const Eigen::Isometry3d& base = Eigen::Isometry3d::Identity());

  /// Values of every joint (mimic joints derived), indexed like RobotModel::joints().
  std::vector<double> jointValues(const Configuration& q) const;
  /// World pose of every link, indexed like RobotModel::links().
  LinkPoses linkPoses(const Configuration& q) const;
  void linkPoses(const Configuration& q, LinkPoses& out) const;

  const RobotModel& model() const { return model_; }
  const Eigen::Isometry3d& base() const { return base_; }

 private:
  const RobotModel& model_;
  Eigen::Isometry3d base_;
};

}  // namespace pmdplan
