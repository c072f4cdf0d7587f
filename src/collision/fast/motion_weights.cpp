#include "motion_weights.hpp"

#include <algorithm>
#include <cmath>

#include "pmdplan/model/collision_shape.hpp"

namespace pmdplan::fast {
namespace {

/// Joints from the root to `link` (indices into joints()), root first.
std::vector<int> weightedJointChain(const RobotModel& model, int link) {
  std::vector<int> chain;
  for (int l = link; model.links()[static_cast<std::size_t>(l)].parentJoint >= 0;) {
    const int j = model.links()[static_cast<std::size_t>(l)].parentJoint;
    chain.insert(chain.begin(), j);
    l = model.joints()[static_cast<std::size_t>(j)].parentLink;
  }
  return chain;
}

}  // namespace

// How far a point of a link can move per unit of each active joint: for every moving joint on its
// chain, the distance from the joint origin to the farthest point of the link's geometry in any
// configuration (the joint offsets down the chain plus the shapes' reach: triangle inequality),
// as SweptDistanceBound does for the whole robot. Mimic joints are charged to their source. For a
// pair of links only the joints below their common ancestor count: the joints above move both
// links rigidly together and do not change their distance.
MotionWeights::MotionWeights(const RobotModel& model, const std::vector<std::pair<int, int>>& selfPairs,
                             const std::vector<int>& geometricLinks, const std::vector<char>& moving)
    : dof_(static_cast<std::size_t>(model.dof())), linkCount_(geometricLinks.size()) {
  const std::size_t dof = dof_;
  const auto weightsOf = [&](int link, const std::vector<int>& exclude) {
    std::vector<double> w(dof, 0.0);
    double shapeReach = 0.0;
    for (const auto& placed : model.links()[static_cast<std::size_t>(link)].collisionShapes)
      shapeReach = std::max(shapeReach, placed.pose.translation().norm() + boundingRadius(placed.shape));
    const auto chain = weightedJointChain(model, link);
    for (std::size_t k = 0; k < chain.size(); ++k) {
      const Joint& joint = model.joints()[static_cast<std::size_t>(chain[k])];
      if (joint.type == JointType::Fixed || std::find(exclude.begin(), exclude.end(), chain[k]) != exclude.end())
        continue;
      double reach = shapeReach;
      for (std::size_t below = k + 1; below < chain.size(); ++below)
        reach += model.joints()[static_cast<std::size_t>(chain[below])].origin.translation().norm();
      if (joint.type == JointType::Prismatic) reach = 1.0;
      if (joint.activeIndex >= 0)
        w[static_cast<std::size_t>(joint.activeIndex)] += reach;
      else if (joint.mimicSource >= 0) {
        const int source = model.joints()[static_cast<std::size_t>(joint.mimicSource)].activeIndex;
        if (source >= 0) w[static_cast<std::size_t>(source)] += std::abs(joint.mimicMultiplier) * reach;
      }
    }
    return w;
  };
  for (int l : geometricLinks) {
    const auto w = weightsOf(l, {});
    linkWeights_.insert(linkWeights_.end(), w.begin(), w.end());
  }
  for (const auto& [a, b] : selfPairs) {
    const auto chainA = weightedJointChain(model, a), chainB = weightedJointChain(model, b);
    std::vector<int> common;
    for (std::size_t k = 0; k < chainA.size() && k < chainB.size() && chainA[k] == chainB[k]; ++k)
      common.push_back(chainA[k]);
    const auto wa = weightsOf(a, common), wb = weightsOf(b, common);
    for (std::size_t i = 0; i < dof; ++i) pairWeights_.push_back(wa[i] + wb[i]);
    defaultPairShare_.push_back(1.0 / (moving[static_cast<std::size_t>(a)] + moving[static_cast<std::size_t>(b)]));
  }
}

void MotionWeights::defaultShares(std::vector<double>& pairShare, std::vector<double>& linkShare) const {
  pairShare = defaultPairShare_;
  linkShare.assign(linkCount_, 1.0);
}

void MotionWeights::motionShares(const Configuration& from, const Configuration& to, std::vector<double>& pairShare,
                                 std::vector<double>& linkShare) const {
  const std::size_t dof = dof_;
  std::vector<double> delta(dof);
  for (std::size_t i = 0; i < dof; ++i)
    delta[i] = std::abs(to[static_cast<Eigen::Index>(i)] - from[static_cast<Eigen::Index>(i)]);
  const auto share = [&](const double* w) {
    double rate = 0.0;
    for (std::size_t i = 0; i < dof; ++i) rate += w[i] * delta[i];
    return 1.0 / (rate * (1.0 + 1e-9));
  };
  for (std::size_t p = 0; p < pairShare.size(); ++p) pairShare[p] = share(pairWeights_.data() + p * dof);
  for (std::size_t i = 0; i < linkShare.size(); ++i) linkShare[i] = share(linkWeights_.data() + i * dof);
}

}  // namespace pmdplan::fast
