#include "pmdplan/planning/pmd_connect_planner.hpp"

#include <algorithm>
#include <utility>

#include "pmdplan/planning/arm_box_scales.hpp"
#include "pmdplan/planning/hand_arm_draw.hpp"
#include "pmdplan/planning/van_der_corput.hpp"

namespace pmdplan {

PmdConnectPlanner::PmdConnectPlanner(PlanningSpace space, StateValidator& stateValidator,
                                     MotionValidator& motionValidator, std::unique_ptr<HandSampler> handSampler,
                                     PlannerSettings parameters)
    : PmdPlannerBase(std::move(space), stateValidator, motionValidator, std::move(handSampler), parameters,
                     "PmdConnectPlanner") {}

void PmdConnectPlanner::setup() {
  setupProblem();
  range_ = parameters_.connect.range * space_.distance(start_, goal_);
}

void PmdConnectPlanner::clear() {
  for (ConnectTree& tree : trees_) tree.clear();
  clearResults();
}

PlannerStatus PmdConnectPlanner::solve() {
  setup();
  clear();
  beginRun(2);  // a segment point and a box scale per sample
  if (const auto invalid = checkStartAndGoalStates()) return endRun(*invalid);
  ConnectTree& starts = trees_[kStartTree];
  ConnectTree& goals = trees_[kGoalTree];
  const ConnectTree::Node startRoot = starts.add(start_, space_.normalise(start_), ConnectTree::kNoParent);
  const ConnectTree::Node goalRoot = goals.add(goal_, space_.normalise(goal_), ConnectTree::kNoParent);
  if (space_.distance(start_, goal_) == 0.0 || motionValidator_.isValid(start_, goal_))
    return finish(startRoot, goalRoot);

  const HandArmSources sources{space_, *armSampler_, *handSampler_, stateValidator_, parameters_};
  ArmBoxScales scales(parameters_.rhoA, parameters_.connect.armGrowth);
  for (std::size_t round = 1;; ++round) {
    statistics_.sweeps = round;
    statistics_.finalArmHalfSize = scales.largest();
    for (std::size_t s = 0; s < parameters_.connect.round; ++s) {
      double point[2];  // where on the segment, and the box's scale
      points_.next(PointStream::SegmentPoint, 2, point);
      const HandArmDraw draw =
          drawHandArm(sources, point[0], scales.halfSize(point[1]), start_, points_, run_, statistics_);
      if (draw.stop) return endRun(*draw.stop);
      if (!draw.sample) continue;
      const Eigen::VectorXd unit = space_.normalise(*draw.sample);
      const Reach fromGoal = connect(goals, *draw.sample, unit);
      if (fromGoal.reached) {
        const Reach fromStart = connect(starts, *draw.sample, unit);
        if (fromStart.reached && certify(fromStart.node, fromGoal.node)) return finish(fromStart.node, fromGoal.node);
      }
      if (run_.timeIsUp()) return endRun(PlannerStatus::TimeLimit);
    }
    scales.grow();
  }
}

PmdConnectPlanner::Reach PmdConnectPlanner::connect(ConnectTree& tree, const Configuration& target,
                                                    const Eigen::VectorXd& targetUnit) {
  for (;;) {
    const ConnectTree::Node near = tree.nearest(targetUnit);
    const double distance = (tree.unit(near) - targetUnit).norm();
    if (distance == 0.0) return {true, near};
    const bool reaches = distance <= range_;
    const Configuration& from = tree.configuration(near);
    Configuration to = reaches ? target : Configuration(from + (range_ / distance) * (target - from));
    if (!reaches) {
      ++statistics_.stateChecks;
      if (!stateValidator_.isValid(to)) return {};
    }
    if (!probe(from, to)) return {};
    const Eigen::VectorXd unit = reaches ? targetUnit : space_.normalise(to);
    const ConnectTree::Node added = tree.add(std::move(to), unit, near);
    if (reaches) return {true, added};
    if (run_.timeIsUp()) return {};
  }
}

bool PmdConnectPlanner::probe(const Configuration& from, const Configuration& to) {
  const std::size_t count = parameters_.connect.probes;
  if (count == 0) return true;
  probeStates_.resize(count);
  probePointers_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    probeStates_[i] = from + radicalInverse(i + 1) * (to - from);
    probePointers_[i] = &probeStates_[i];
  }
  const std::size_t checksBefore = stateValidator_.checkCount();
  const int firstColliding = stateValidator_.firstWithValidity(probePointers_.data(), static_cast<int>(count), false);
  statistics_.stateChecks += stateValidator_.checkCount() - checksBefore;
  return firstColliding == static_cast<int>(count);
}

bool PmdConnectPlanner::certify(ConnectTree::Node startSide, ConnectTree::Node goalSide) {
  struct Pending {
    std::size_t tree;
    ConnectTree::Node node;
    double length;
  };
  std::vector<Pending> pending;
  for (const auto& [which, end] : {std::pair{kStartTree, startSide}, std::pair{kGoalTree, goalSide}}) {
    const ConnectTree& tree = trees_[which];
    for (const ConnectTree::Node n : tree.branch(end))
      if (!tree.segmentChecked(n)) pending.push_back({which, n, (tree.unit(n) - tree.unit(tree.parent(n))).norm()});
  }
  // Longest first: the most likely to be blocked.
  std::stable_sort(pending.begin(), pending.end(),
                   [](const Pending& a, const Pending& b) { return a.length > b.length; });
  for (const Pending& p : pending) {
    ConnectTree& tree = trees_[p.tree];
    if (!motionValidator_.isValid(tree.configuration(tree.parent(p.node)), tree.configuration(p.node))) {
      tree.cut(p.node);
      return false;
    }
    tree.markSegmentFree(p.node);
  }
  return true;
}

PlannerStatus PmdConnectPlanner::finish(ConnectTree::Node startSide, ConnectTree::Node goalSide) {
  const std::vector<ConnectTree::Node> toStart = trees_[kStartTree].branch(startSide);
  for (auto n = toStart.rbegin(); n != toStart.rend(); ++n)
    unsmoothedPath_.push_back(trees_[kStartTree].configuration(*n));
  // The two branches meet in the same configuration: keep it once.
  for (const ConnectTree::Node n : trees_[kGoalTree].branch(goalSide))
    if (trees_[kGoalTree].configuration(n) != unsmoothedPath_.back())
      unsmoothedPath_.push_back(trees_[kGoalTree].configuration(n));
  path_ = run_.finishPath(unsmoothedPath_, space_, motionValidator_, parameters_.smooth, statistics_);
  return endRun(PlannerStatus::Solved);
}

PlannerStatus PmdConnectPlanner::endRun(PlannerStatus status) {
  std::size_t nodes = 0;
  std::size_t edges = 0;
  for (const ConnectTree& tree : trees_) {
    nodes += tree.liveCount();
    edges += tree.liveCount() > 0 ? tree.liveCount() - 1 : 0;  // every live node but the root: its parent's segment
  }
  return finishRun(status, nodes, edges);
}

}  // namespace pmdplan
