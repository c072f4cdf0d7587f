#include "checker_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lane_geometry.hpp"
#include "lane_parts.hpp"

namespace pmdplan::fast {
namespace {

constexpr int kValues = BatchedForwardKinematics::kPoseValues;

/// Links that no joint moves: reached from the root through fixed joints only.
std::vector<char> movingLinks(const RobotModel& model) {
  std::vector<char> moving(model.links().size(), 0);
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    moving[static_cast<std::size_t>(joint.childLink)] =
        moving[static_cast<std::size_t>(joint.parentLink)] || joint.type != JointType::Fixed;
  }
  return moving;
}

/// Joints from the root to `link` (indices into joints()), root first.
std::vector<int> jointChain(const RobotModel& model, int link) {
  std::vector<int> chain;
  for (int l = link; model.links()[static_cast<std::size_t>(l)].parentJoint >= 0;) {
    const int j = model.links()[static_cast<std::size_t>(l)].parentJoint;
    chain.insert(chain.begin(), j);
    l = model.joints()[static_cast<std::size_t>(j)].parentLink;
  }
  return chain;
}

}  // namespace

CheckerState::CheckerState(const Task& task, ExactCollisionChecker& exact, double band)
    : exact_(exact),
      band_(band),
      links_(linkParts(*task.robot)),
      obstacles_(obstacleParts(task.obstacles)),
      kinematics_(*task.robot, task.base),
      moving_(movingLinks(*task.robot)) {
  if (&exact.model() != task.robot.get()) throw std::invalid_argument("the exact checker belongs to another task");
  if (!(band > 0.0)) throw std::invalid_argument("the fast checker's band must be positive");
  const std::size_t n = links_.size();
  for (std::size_t l = 0; l < n; ++l) {
    partOffset_.push_back(static_cast<int>(worldParts_.size()));
    worldParts_.resize(worldParts_.size() + links_[l].parts.size());
    if (!links_[l].empty()) boundLinks_.push_back(static_cast<int>(l));
  }
  orderGeometricLinks(*task.robot);
  placed_.assign(n, 0);
  boundPlaced_.assign(n, 0);
  partPlaced_.assign(worldParts_.size(), 0);
  linkPoses_.assign(n * kValues, 0.0);
  boundX_.assign(n, 0.0), boundY_ = boundZ_ = boundX_;
  geometricX_.assign(geometricLinks_.size(), 0.0), geometricY_ = geometricZ_ = geometricX_;
  obstacleGaps_.assign(geometricLinks_.size() * obstacles_.size(), 0.0);
  poseScratch_.resize(kinematics_.batchPoseSize());

  // Pairs no joint moves are decided once, by the exact checker itself (their poses never change).
  exact.kinematics().linkPoses(Configuration::Zero(task.robot->dof()), exactPoses_);
  for (const auto& [a, b] : exact.selfPairs()) {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if (moving_[ua] || moving_[ub]) {
      selfPairs_.emplace_back(a, b);
      pairIsArm_.push_back(exact.isArmLink(a) && exact.isArmLink(b));
      pairA_.push_back(a);
      pairB_.push_back(b);
      pairRadiusSum_.push_back(links_[ua].boundRadius + links_[ub].boundRadius);
      pairShare_.push_back(1.0 / (moving_[ua] + moving_[ub]));
    } else if (exact.linkPairCollides(exactPoses_, a, b)) {
      staticSelfCollisions_.emplace_back(a, b);
      if (exact.isArmLink(a) && exact.isArmLink(b)) staticArmSelfCollisions_.emplace_back(a, b);
    }
  }
  pairGaps_.assign(selfPairs_.size(), 0.0);
  pairDx_ = pairDy_ = pairDz_ = pairGaps_;
  linkShare_.assign(geometricLinks_.size(), 1.0);
  computeMotionWeights(*task.robot);
  for (std::size_t p = 0; p < pairCount(); ++p) {
    auto links = kinematics_.emptyLinkSet();
    if (p < selfPairs_.size()) {
      const auto [a, b] = selfPairs_[p];
      kinematics_.addWithAncestors(links, a);
      kinematics_.addWithAncestors(links, b);
      const int frame = kinematics_.commonAncestor(a, b);
      auto above = kinematics_.emptyLinkSet(), relative = links;
      kinematics_.addWithAncestors(above, frame);
      for (std::size_t w = 0; w < relative.size(); ++w) relative[w] &= ~above[w];
      pairFrame_.push_back(frame);
      pairRelativeLinks_.push_back(std::move(relative));
    } else {
      kinematics_.addWithAncestors(links, geometricLinks_[(p - selfPairs_.size()) % geometricLinks_.size()]);
    }
    pairLinks_.push_back(std::move(links));
  }
  posedLinks_ = kinematics_.emptyLinkSet();
  prepareLanes();

  for (std::size_t l = 0; l < n; ++l)
    if (!moving_[l] && !links_[l].empty())
      for (std::size_t o = 0; o < obstacles_.size(); ++o)
        if (exact.linkObstacleCollides(exactPoses_, static_cast<int>(l), o))
          staticEnvironmentCollisions_.emplace_back(static_cast<int>(l), o);
}

// The moving links with geometry in depth-first order, so that every link's geometric
// descendants follow it in one run (the batch screen tests a whole subtree against an obstacle
// first).
void CheckerState::orderGeometricLinks(const RobotModel& model) {
  std::vector<std::vector<int>> children(model.links().size());
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    children[static_cast<std::size_t>(joint.parentLink)].push_back(joint.childLink);
  }
  const auto visit = [&](const auto& self, int link, int parent) -> void {
    const auto l = static_cast<std::size_t>(link);
    const bool geometric = moving_[l] && !links_[l].empty();
    const int position = static_cast<int>(geometricLinks_.size());
    if (geometric) {
      geometricLinks_.push_back(link);
      geometricBoundR_.push_back(links_[l].boundRadius);
      geometricParent_.push_back(parent);
      geometricSubtreeEnd_.push_back(0);
    }
    for (int child : children[l]) self(self, child, geometric ? position : parent);
    if (geometric) geometricSubtreeEnd_[static_cast<std::size_t>(position)] = static_cast<int>(geometricLinks_.size());
  };
  visit(visit, model.rootLink(), -1);
}

// How far a point of a link can move per unit of each active joint: for every moving joint on its
// chain, the distance from the joint origin to the farthest point of the link's geometry in any
// configuration (the joint offsets down the chain plus the shapes' reach: triangle inequality),
// as SweptDistanceBound does for the whole robot. Mimic joints are charged to their source. For a
// pair of links only the joints below their common ancestor count: the joints above move both
// links rigidly together and do not change their distance.
void CheckerState::computeMotionWeights(const RobotModel& model) {
  const auto dof = static_cast<std::size_t>(model.dof());
  const auto weightsOf = [&](int link, const std::vector<int>& exclude) {
    std::vector<double> w(dof, 0.0);
    double shapeReach = 0.0;
    for (const auto& placed : model.links()[static_cast<std::size_t>(link)].collisionShapes)
      shapeReach = std::max(shapeReach, placed.pose.translation().norm() + boundingRadius(placed.shape));
    const auto chain = jointChain(model, link);
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
  linkWeights_.clear();
  for (int l : geometricLinks_) {
    const auto w = weightsOf(l, {});
    linkWeights_.insert(linkWeights_.end(), w.begin(), w.end());
  }
  pairWeights_.clear();
  for (const auto& [a, b] : selfPairs_) {
    const auto chainA = jointChain(model, a), chainB = jointChain(model, b);
    std::vector<int> common;
    for (std::size_t k = 0; k < chainA.size() && k < chainB.size() && chainA[k] == chainB[k]; ++k)
      common.push_back(chainA[k]);
    const auto wa = weightsOf(a, common), wb = weightsOf(b, common);
    for (std::size_t i = 0; i < dof; ++i) pairWeights_.push_back(wa[i] + wb[i]);
  }
}

void CheckerState::setMotion(const Configuration& from, const Configuration& to) {
  const auto dof = static_cast<std::size_t>(kinematics_.dof());
  std::vector<double> delta(dof);
  for (std::size_t i = 0; i < dof; ++i)
    delta[i] = std::abs(to[static_cast<Eigen::Index>(i)] - from[static_cast<Eigen::Index>(i)]);
  // Shares are 1 / (distance moved over the whole segment), rounded up by a relative 1e-9 so
  // rounding never makes a gap look safer than it is.
  const auto share = [&](const double* w) {
    double rate = 0.0;
    for (std::size_t i = 0; i < dof; ++i) rate += w[i] * delta[i];
    return 1.0 / (rate * (1.0 + 1e-9));
  };
  for (std::size_t p = 0; p < selfPairs_.size(); ++p) pairShare_[p] = share(pairWeights_.data() + p * dof);
  for (std::size_t i = 0; i < geometricLinks_.size(); ++i) linkShare_[i] = share(linkWeights_.data() + i * dof);
}

void CheckerState::prepareLanes() {
  const std::size_t obstacleBase = worldParts_.size();
  boundLanes_.assign(links_.size() * 3 * L, 0.0);
  partLanes_.assign((obstacleBase + obstacles_.size()) * kPartValues * L, 0.0);
  partLanesPlaced_.assign(links_.size(), 0);
  pairLaneGaps_.assign(pairCount() * L, 0.0);
  pairNear_.assign(pairCount(), 0);
  subtreeLanes_.assign(geometricLinks_.size() * L, 0.0);
  for (std::size_t o = 0; o < obstacles_.size(); ++o) {
    const ConvexPart& part = obstacles_[o].part;
    double* out = partLanes_.data() + (obstacleBase + o) * kPartValues * L;
    const auto spread = [&](int at, const double* values, int count) {
      for (int v = 0; v < count; ++v)
        for (int l = 0; l < L; ++l) out[(at + v) * L + l] = values[v];
    };
    spread(0, part.a, 3);
    spread(3, part.b, 3);
    spread(kPartAxes, part.axes, 9);
    spread(kPartBound, part.boundCentre, 3);
    spread(kPartOuter, part.outerA, 3);
    spread(kPartOuter + 3, part.outerB, 3);
  }
  // Every part, then every pair's part pairs in pair order.
  partShapes_.clear();
  for (const auto& link : links_) partShapes_.insert(partShapes_.end(), link.parts.begin(), link.parts.end());
  for (const auto& obstacle : obstacles_) partShapes_.push_back(obstacle.part);
  // Each part pair with its kernel (checker_state.hpp, PartPairKind), counted by kind.
  std::uint32_t kindCounts[kPartPairKinds] = {};
  const auto add = [&](std::uint32_t a, std::uint32_t b) {
    using Kind = ConvexPart::Kind;
    const Kind first = partShapes_[a].kind, second = partShapes_[b].kind;
    PartPairKind kind;
    if (first == second) {
      kind = first == Kind::Capsule ? PartPairKind::CapsuleCapsule
             : first == Kind::Box   ? PartPairKind::BoxBox
                                    : PartPairKind::CylinderCylinder;
    } else if (first == Kind::Capsule || second == Kind::Capsule) {
      kind = first == Kind::Box || second == Kind::Box ? PartPairKind::CapsuleBox : PartPairKind::CapsuleCylinder;
      if (second == Kind::Capsule) std::swap(a, b);
    } else {
      kind = first == Kind::Box ? PartPairKind::BoxCylinder : PartPairKind::CylinderBox;
      if (first == Kind::Cylinder) std::swap(a, b);
    }
    ++kindCounts[static_cast<int>(kind)];
    partPairs_.push_back({a, b, kind, lanes::inverseSquaredLength(partShapes_[a].a, partShapes_[a].b),
                          lanes::inverseSquaredLength(partShapes_[b].a, partShapes_[b].b)});
  };
  const auto partsOf = [&](int link) {
    const auto first = static_cast<std::uint32_t>(partOffset_[static_cast<std::size_t>(link)]);
    return std::pair{first, first + static_cast<std::uint32_t>(links_[static_cast<std::size_t>(link)].parts.size())};
  };
  partPairs_.clear();
  pairPartsBegin_.assign(1, 0);
  for (std::size_t p = 0; p < selfPairs_.size(); ++p) {
    const auto [beginA, endA] = partsOf(pairA_[p]);
    const auto [beginB, endB] = partsOf(pairB_[p]);
    for (std::uint32_t i = beginA; i < endA; ++i)
      for (std::uint32_t j = beginB; j < endB; ++j) add(i, j);
    pairPartsBegin_.push_back(static_cast<std::uint32_t>(partPairs_.size()));
  }
  for (std::size_t o = 0; o < obstacles_.size(); ++o)
    for (const int link : geometricLinks_) {
      const auto [begin, end] = partsOf(link);
      for (std::uint32_t k = begin; k < end; ++k) add(k, static_cast<std::uint32_t>(obstacleBase + o));
      pairPartsBegin_.push_back(static_cast<std::uint32_t>(partPairs_.size()));
    }
  partPairGaps_.assign(partPairs_.size() * L, 0.0);
  partWork_.assign(partPairs_.size(), 0);
  for (int k = 1; k < kPartPairKinds; ++k) partWorkBegin_[k] = partWorkBegin_[k - 1] + kindCounts[k - 1];
}

}  // namespace pmdplan::fast
