#include "pmdplan/model/robot_model.hpp"

#include <algorithm>

#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/resource_path.hpp"
#include "urdf_reader.hpp"

namespace pmdplan {

RobotModel RobotModel::load(const std::filesystem::path& urdf, const std::optional<std::filesystem::path>& srdf) {
  if (!std::filesystem::exists(urdf)) throw InputError(urdf.string(), "", "URDF file not found");
  if (srdf && !std::filesystem::exists(*srdf)) throw InputError(srdf->string(), "", "SRDF file not found");
  return RobotModelBuilder::build(urdf, srdf);
}

RobotModel RobotModel::loadBuiltIn(const std::string& name) {
  const auto dir = dataDirectory() / "robots" / name;
  const auto urdf = dir / (name + ".urdf");
  if (!std::filesystem::exists(urdf))
    throw InputError("", "robot", "'" + name + "' is not a built-in robot (no " + urdf.string() + ")");
  const auto srdf = dir / (name + ".srdf");
  return load(urdf, std::filesystem::exists(srdf) ? std::optional(srdf) : std::nullopt);
}

RobotModel RobotModel::loadByNameOrPath(const std::string& nameOrUrdf) {
  if (std::filesystem::path(nameOrUrdf).extension() != ".urdf") return loadBuiltIn(nameOrUrdf);
  const std::filesystem::path path = resolveResourcePath(nameOrUrdf, std::filesystem::current_path() / "-", "robot");
  const auto srdf = std::filesystem::path(path).replace_extension(".srdf");
  return load(path, std::filesystem::exists(srdf) ? std::optional(srdf) : std::nullopt);
}

JointLimits RobotModel::groupJoints(const std::string& groupName) const {
  JointLimits joints;
  for (const int index : group(groupName)) joints.push_back(activeJoints_[static_cast<std::size_t>(index)]);
  return joints;
}

std::vector<std::string> RobotModel::activeJointNames() const {
  std::vector<std::string> names;
  for (const auto& j : activeJoints_) names.push_back(j.name);
  return names;
}

int RobotModel::activeIndex(const std::string& jointName) const {
  for (std::size_t i = 0; i < activeJoints_.size(); ++i)
    if (activeJoints_[i].name == jointName) return static_cast<int>(i);
  return -1;
}

int RobotModel::linkIndex(const std::string& linkName) const {
  for (std::size_t i = 0; i < links_.size(); ++i)
    if (links_[i].name == linkName) return static_cast<int>(i);
  return -1;
}

int RobotModel::jointIndex(const std::string& jointName) const {
  for (std::size_t i = 0; i < joints_.size(); ++i)
    if (joints_[i].name == jointName) return static_cast<int>(i);
  return -1;
}

bool RobotModel::hasGroup(const std::string& groupName) const {
  return std::any_of(groups_.begin(), groups_.end(), [&](const auto& g) { return g.first == groupName; });
}

const std::vector<int>& RobotModel::group(const std::string& groupName) const {
  for (const auto& [name, indices] : groups_)
    if (name == groupName) return indices;
  throw InputError(urdfPath_.string(), "group",
                   "robot '" + name_ + "' has no planning group '" + groupName +
                       "' (write the SRDF with `pmdplan robot init " + urdfPath_.string() +
                       " --arm J1,J2,... --palm LINK`)");
}

bool RobotModel::isCollisionPairDisabled(int linkA, int linkB) const {
  const std::size_t n = links_.size();
  return disabledMatrix_[static_cast<std::size_t>(linkA) * n + static_cast<std::size_t>(linkB)] != 0;
}

bool RobotModel::withinLimits(const Configuration& q, double tolerance) const {
  if (q.size() != dof()) return false;
  for (int i = 0; i < dof(); ++i) {
    const auto& j = activeJoints_[static_cast<std::size_t>(i)];
    if (!(q[i] >= j.lower - tolerance && q[i] <= j.upper + tolerance)) return false;
  }
  return true;
}

Configuration RobotModel::normalise(const Configuration& q) const {
  Configuration unit(q.size());
  for (int i = 0; i < q.size(); ++i) unit[i] = activeJoints_[static_cast<std::size_t>(i)].normalise(q[i]);
  return unit;
}

Configuration RobotModel::denormalise(const Configuration& unit) const {
  Configuration q(unit.size());
  for (int i = 0; i < unit.size(); ++i) q[i] = activeJoints_[static_cast<std::size_t>(i)].denormalise(unit[i]);
  return q;
}

}  // namespace pmdplan
