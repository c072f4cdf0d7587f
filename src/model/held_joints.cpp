// RobotModel::withHeldJoints: joints a task keeps still (the other arm of a bimanual robot, a
// humanoid's head) become fixed joints at their held values.
#include <Eigen/Geometry>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "urdf_reader.hpp"

namespace pmdplan {
namespace {

/// Folds a joint's motion at `value` into its origin and makes it fixed.
void freeze(Joint& joint, double value) {
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      joint.origin.rotate(Eigen::AngleAxisd(value, joint.axis));
      break;
    case JointType::Prismatic:
      joint.origin.translate(value * joint.axis);
      break;
    case JointType::Fixed:
      break;
  }
  joint.type = JointType::Fixed;
  joint.mimicSource = -1;
  joint.activeIndex = -1;
  joint.lower = joint.upper = value;
}

}  // namespace

std::optional<double> RobotModel::heldJointValue(const std::string& jointName) const {
  for (const auto& [name, value] : heldJoints_)
    if (name == jointName) return value;
  return std::nullopt;
}

RobotModel RobotModel::withHeldJoints(const std::vector<std::pair<std::string, double>>& held,
                                      const std::string& field) const {
  RobotModel model = *this;
  for (const auto& [name, value] : held) {
    const int index = jointIndex(name);
    if (index < 0 || joints_[static_cast<std::size_t>(index)].activeIndex < 0)
      throw InputError(urdfPath_.string(), field, "'" + name + "' is not an active joint of robot " + name_);
    for (std::size_t j = 0; j < model.joints_.size(); ++j) {
      Joint& follower = model.joints_[j];
      if (follower.mimicSource == index) freeze(follower, follower.mimicMultiplier * value + follower.mimicOffset);
    }
    freeze(model.joints_[static_cast<std::size_t>(index)], value);
    model.heldJoints_.emplace_back(name, value);
  }
  RobotModelBuilder::reassignActiveOrder(model);
  return model;
}

}  // namespace pmdplan
