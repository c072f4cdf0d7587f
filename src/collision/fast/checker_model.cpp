#include "checker_model.hpp"

#include <stdexcept>

namespace pmdplan::fast {
namespace {

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

GeometricLinks orderGeometricLinks(const RobotModel& model, const std::vector<LinkParts>& links,
                                   const std::vector<char>& moving) {
  GeometricLinks geometric;
  std::vector<std::vector<int>> children(model.links().size());
  for (int j : model.jointOrder()) {
    const Joint& joint = model.joints()[static_cast<std::size_t>(j)];
    children[static_cast<std::size_t>(joint.parentLink)].push_back(joint.childLink);
  }
  const auto visit = [&](const auto& self, int link, int parent) -> void {
    const auto l = static_cast<std::size_t>(link);
    const bool isGeometric = moving[l] && !links[l].empty();
    const int position = static_cast<int>(geometric.links.size());
    if (isGeometric) {
      geometric.links.push_back(link);
      geometric.boundRadius.push_back(links[l].boundRadius);
      geometric.parent.push_back(parent);
      geometric.subtreeEnd.push_back(0);
    }
    for (int child : children[l]) self(self, child, isGeometric ? position : parent);
    if (isGeometric)
      geometric.subtreeEnd[static_cast<std::size_t>(position)] = static_cast<int>(geometric.links.size());
  };
  visit(visit, model.rootLink(), -1);
  return geometric;
}

}  // namespace

CheckerModel::CheckerModel(const Task& task, const ExactCollisionChecker& exact, double band)
    : task_(&exact.task()),
      band_(band),
      links_(linkParts(*task.robot)),
      obstacles_(obstacleParts(task.obstacles)),
      kinematics_(*task.robot, task.base),
      moving_(movingLinks(*task.robot)) {
  if (&exact.model() != task.robot.get()) throw std::invalid_argument("the exact checker belongs to another task");
  if (!(band > 0.0)) throw std::invalid_argument("the fast checker's band must be positive");
  const std::size_t n = links_.size();
  for (std::size_t l = 0; l < n; ++l) {
    partOffset_.push_back(static_cast<int>(linkPartCount_));
    linkPartCount_ += links_[l].parts.size();
    if (!links_[l].empty()) boundLinks_.push_back(static_cast<int>(l));
  }
  geometric_ = orderGeometricLinks(*task.robot, links_, moving_);

  // Pairs no joint moves are decided once, by the exact checker itself (their poses never change).
  LinkPoses poses;
  exact.kinematics().linkPoses(Configuration::Zero(task.robot->dof()), poses);
  for (const auto& [a, b] : exact.selfPairs()) {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if (moving_[ua] || moving_[ub]) {
      selfPairs_.pairs.emplace_back(a, b);
      selfPairs_.isArm.push_back(exact.isArmLink(a) && exact.isArmLink(b));
      selfPairs_.a.push_back(a);
      selfPairs_.b.push_back(b);
      selfPairs_.radiusSum.push_back(links_[ua].boundRadius + links_[ub].boundRadius);
    } else if (exact.linkPairCollides(poses, a, b)) {
      static_.self.emplace_back(a, b);
      if (exact.isArmLink(a) && exact.isArmLink(b)) static_.armSelf.emplace_back(a, b);
    }
  }
  weights_ = MotionWeights(*task.robot, selfPairs_.pairs, geometric_.links, moving_);
  for (std::size_t p = 0; p < pairCount(); ++p) {
    auto links = kinematics_.emptyLinkSet();
    if (p < selfPairs_.size()) {
      const auto [a, b] = selfPairs_.pairs[p];
      kinematics_.addWithAncestors(links, a);
      kinematics_.addWithAncestors(links, b);
      const int frame = kinematics_.commonAncestor(a, b);
      auto above = kinematics_.emptyLinkSet(), relative = links;
      kinematics_.addWithAncestors(above, frame);
      for (std::size_t w = 0; w < relative.size(); ++w) relative[w] &= ~above[w];
      pairLinks_.frame.push_back(frame);
      pairLinks_.relative.push_back(std::move(relative));
    } else {
      kinematics_.addWithAncestors(links, geometric_.links[(p - selfPairs_.size()) % geometric_.size()]);
    }
    pairLinks_.world.push_back(std::move(links));
  }
  partPairs_ = PartPairTable(links_, obstacles_, partOffset_, selfPairs_.a, selfPairs_.b, geometric_.links);

  for (std::size_t l = 0; l < n; ++l)
    if (!moving_[l] && !links_[l].empty())
      for (std::size_t o = 0; o < obstacles_.size(); ++o)
        if (exact.linkObstacleCollides(poses, static_cast<int>(l), o))
          static_.environment.emplace_back(static_cast<int>(l), o);
}

}  // namespace pmdplan::fast
