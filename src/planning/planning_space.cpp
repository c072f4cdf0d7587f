#include "pmdplan/planning/planning_space.hpp"

#include <cmath>
#include <stdexcept>

namespace pmdplan {

std::vector<std::string> PlanningSpace::jointNames() const {
  std::vector<std::string> names;
  names.reserve(joints.size());
  for (const JointLimit& joint : joints) names.push_back(joint.name);
  return names;
}

int PlanningSpace::indexOf(const std::string& jointName) const {
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == jointName) return static_cast<int>(i);
  return -1;
}

void PlanningSpace::check() const {
  if (joints.empty()) throw std::invalid_argument("planning space: no joints");
  for (const JointLimit& joint : joints)
    if (!std::isfinite(joint.lower) || !std::isfinite(joint.upper) || !(joint.range() > 0.0))
      throw std::invalid_argument("planning space: joint '" + joint.name + "' needs finite limits with lower < upper");
  if (handIndices.empty()) throw std::invalid_argument("planning space: the hand group must have a joint");
  std::vector<int> owner(joints.size(), 0);
  auto claim = [&](const std::vector<int>& indices, const char* group) {
    for (const int i : indices) {
      if (i < 0 || i >= dof())
        throw std::invalid_argument(std::string("planning space: ") + group + " index " + std::to_string(i) +
                                    " is not a joint (0.." + std::to_string(dof() - 1) + ")");
      if (owner[static_cast<std::size_t>(i)]++ != 0)
        throw std::invalid_argument("planning space: joint '" + joints[static_cast<std::size_t>(i)].name +
                                    "' is listed twice in the arm and hand groups");
    }
  };
  claim(armIndices, "arm");
  claim(handIndices, "hand");
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (owner[i] == 0)
      throw std::invalid_argument("planning space: joint '" + joints[i].name +
                                  "' is in neither the arm nor the hand group (add it to a group, or hold it "
                                  "still with the task's `fixed: {joints_deg: {" +
                                  joints[i].name + ": VALUE}}`)");
}

Eigen::VectorXd PlanningSpace::normalise(const Configuration& q) const {
  Eigen::VectorXd unit(q.size());
  for (Eigen::Index i = 0; i < q.size(); ++i) unit[i] = joints[static_cast<std::size_t>(i)].normalise(q[i]);
  return unit;
}

Configuration PlanningSpace::denormalise(const Eigen::VectorXd& unit) const {
  Configuration q(unit.size());
  for (Eigen::Index i = 0; i < unit.size(); ++i) q[i] = joints[static_cast<std::size_t>(i)].denormalise(unit[i]);
  return q;
}

double PlanningSpace::distance(const Configuration& a, const Configuration& b) const {
  double sum = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const double d = (a[i] - b[i]) / joints[static_cast<std::size_t>(i)].range();
    sum += d * d;
  }
  return std::sqrt(sum);
}

double PlanningSpace::armDistance(const Configuration& a, const Configuration& b) const {
  double sum = 0.0;
  for (const int i : armIndices) {
    const double d = (a[i] - b[i]) / joints[static_cast<std::size_t>(i)].range();
    sum += d * d;
  }
  return std::sqrt(sum);
}

bool PlanningSpace::withinLimits(const Configuration& q, double tolerance) const {
  if (q.size() != dof()) return false;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const JointLimit& joint = joints[static_cast<std::size_t>(i)];
    if (!(q[i] >= joint.lower - tolerance && q[i] <= joint.upper + tolerance)) return false;
  }
  return true;
}

}  // namespace pmdplan
