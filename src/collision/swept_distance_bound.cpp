#include "pmdplan/collision/swept_distance_bound.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

/// Distance from joint `j`'s origin to the farthest point of any geometry below it, for any
/// configuration: offsets along the chain add up (triangle inequality), plus each shape's extent.
double reachBelow(const RobotModel& model, int j, const std::vector<double>& shapeReach) {
  const auto& joints = model.joints();
  double best = 0.0;
  // Depth-first over the subtree of the joint's child link, carrying the chain length so far.
  std::vector<std::pair<int, double>> stack{{joints[static_cast<std::size_t>(j)].childLink, 0.0}};
  while (!stack.empty()) {
    auto [link, chain] = stack.back();
    stack.pop_back();
    best = std::max(best, chain + shapeReach[static_cast<std::size_t>(link)]);
    for (const auto& child : joints)
      if (child.parentLink == link) stack.emplace_back(child.childLink, chain + child.origin.translation().norm());
  }
  return best;
}

}  // namespace

SweptDistanceBound::SweptDistanceBound(const RobotModel& model)
    : leverArms_(static_cast<std::size_t>(model.dof()), 0.0) {
  std::vector<double> shapeReach(model.links().size(), 0.0);
  for (std::size_t l = 0; l < model.links().size(); ++l)
    for (const auto& placed : model.links()[l].collisionShapes) {
      const double r = boundingRadius(placed.shape);
      if (!std::isfinite(r))
        throw std::invalid_argument("link '" + model.links()[l].name +
                                    "': a mesh whose triangles were not read (loadMeshShape)");
      shapeReach[l] = std::max(shapeReach[l], placed.pose.translation().norm() + r);
    }
  const auto& joints = model.joints();
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const Joint& joint = joints[j];
    if (joint.type == JointType::Fixed) continue;
    // A prismatic joint moves everything below it by exactly its displacement.
    const double perUnit =
        joint.type == JointType::Prismatic ? 1.0 : reachBelow(model, static_cast<int>(j), shapeReach);
    if (joint.activeIndex >= 0)
      leverArms_[static_cast<std::size_t>(joint.activeIndex)] += perUnit;
    else if (joint.mimicSource >= 0) {
      const int source = joints[static_cast<std::size_t>(joint.mimicSource)].activeIndex;
      if (source >= 0) leverArms_[static_cast<std::size_t>(source)] += std::abs(joint.mimicMultiplier) * perUnit;
    }
  }
}

double SweptDistanceBound::bound(const Configuration& from, const Configuration& to) const {
  if (from.size() != to.size() || static_cast<std::size_t>(from.size()) != leverArms_.size())
    throw std::invalid_argument("segment endpoints do not match the robot's active joints");
  double total = 0.0;
  for (std::size_t i = 0; i < leverArms_.size(); ++i)
    total += leverArms_[i] * std::abs(to[static_cast<Eigen::Index>(i)] - from[static_cast<Eigen::Index>(i)]);
  return total;
}

long SweptDistanceBound::intervals(const Configuration& from, const Configuration& to, double tolerance) const {
  if (!(tolerance > 0.0)) throw std::invalid_argument("the motion tolerance must be positive");
  const double needed = std::ceil(bound(from, to) / tolerance - 1e-12);
  if (!(needed <= static_cast<double>(kMaxSegmentIntervals))) {
    std::ostringstream text;
    text << "a segment would need " << needed << " states at " << tolerance * 1000.0 << " mm, more than the limit of "
         << kMaxSegmentIntervals
         << " (a larger tolerance, or the robot's joint ranges or mimic multipliers are too large)";
    throw InputError("", "--tolerance-mm", text.str());
  }
  return std::max(1L, static_cast<long>(needed));
}

void checkMotionToleranceMm(double mm) {
  if (!(mm >= kMinToleranceMm && mm <= kMaxToleranceMm)) {
    std::ostringstream text;
    text << "expected a tolerance from " << kMinToleranceMm << " to " << kMaxToleranceMm << " millimetres, got " << mm;
    throw InputError("", "--tolerance-mm", text.str());
  }
}

}  // namespace pmdplan
