#include "pmdplan/model/forward_kinematics.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

namespace pmdplan {

ForwardKinematics::ForwardKinematics(const RobotModel& model, const Eigen::Isometry3d& base)
    : model_(model), base_(base) {}

std::vector<double> ForwardKinematics::jointValues(const Configuration& q) const {
  if (q.size() != model_.dof())
    throw std::invalid_argument("configuration has " + std::to_string(q.size()) + " values, the robot " +
                                std::to_string(model_.dof()) + " active joints");
  const auto& joints = model_.joints();
  std::vector<double> values(joints.size(), 0.0);
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].activeIndex >= 0) values[i] = q[joints[i].activeIndex];
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].mimicSource >= 0)
      values[i] =
          joints[i].mimicMultiplier * values[static_cast<std::size_t>(joints[i].mimicSource)] + joints[i].mimicOffset;
  return values;
}

LinkPoses ForwardKinematics::linkPoses(const Configuration& q) const {
  LinkPoses poses;
  linkPoses(q, poses);
  return poses;
}

void ForwardKinematics::linkPoses(const Configuration& q, LinkPoses& out) const {
  const auto values = jointValues(q);
  const auto& joints = model_.joints();
  out.resize(model_.links().size());
  out[static_cast<std::size_t>(model_.rootLink())] = base_;
  for (int j : model_.jointOrder()) {
    const Joint& joint = joints[static_cast<std::size_t>(j)];
    Eigen::Isometry3d t = out[static_cast<std::size_t>(joint.parentLink)] * joint.origin;
    const double v = values[static_cast<std::size_t>(j)];
    switch (joint.type) {
      case JointType::Fixed:
        break;
      case JointType::Revolute:
      case JointType::Continuous:
        t.rotate(Eigen::AngleAxisd(v, joint.axis));
        break;
      case JointType::Prismatic:
        t.translate(v * joint.axis);
        break;
    }
    out[static_cast<std::size_t>(joint.childLink)] = t;
  }
}

}  // namespace pmdplan
