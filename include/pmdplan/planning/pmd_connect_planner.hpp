#pragma once
// Our bidirectional PMD planner (`--planner pmd-connect`): RRT-Connect (Kuffner & LaValle 2000)
// grown with the PMD planner's samples, checked lazily (Bohlin & Kavraki 2000).
//
// Samples: every sample is a hand-arm draw of Algorithms 1 and 2 — the arm in a box around a point
// of the straight start-goal arm segment, the hand from the thumb base + the first PMDs, the
// dimension growing by one per colliding hand draw — so the trees stay in the PMD subspace between
// c_ini and c_goal, as the paper's roadmap does. The box's half-size is drawn log-uniformly between
// rho_a and the round's largest half-size, which starts at rho_a and grows by a factor after every
// round of samples that did not join the trees: most samples stay near the segment, and the
// region grows only while the trees stay apart.
//
// Trees: one from c_goal, one from c_ini. The goal tree steps toward every sample (steps of at most
// the range); a sample it reaches, the start tree then steps toward. Near the goal, where the
// objects crowd the hand, most samples fail, so the goal side is asked first. A step's end is
// state-checked and a few inner states of the step probed; its full motion check waits until the
// sample has joined both trees: then the path through them is certified, its unchecked steps
// longest first, and a blocked step cuts its node off its tree with everything below it.
//
// The first candidate is the straight segment from c_ini to c_goal. A Planner (planner.hpp),
// registered as `pmd-connect` (planner_registry.hpp): construct, setStartAndGoal, solve, read
// path() and statistics().
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/planning/connect_tree.hpp"
#include "pmdplan/planning/pmd_planner_base.hpp"

namespace pmdplan {

class PmdConnectPlanner : public PmdPlannerBase {
 public:
  static constexpr std::size_t kStartTree = 0;
  static constexpr std::size_t kGoalTree = 1;

  /// The validators are borrowed and must outlive the planner. Of `parameters` it uses rho_a,
  /// n_A, n_H, N, the PMD box (through the hand sampler), the time limit, the seed, the sequence,
  /// smoothing and the `connect` settings.
  PmdConnectPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                    std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters = {});

  std::string name() const override { return "pmd-connect"; }
  /// Throws InputError for bad parameters, std::invalid_argument for a malformed space or problem.
  void setup() override;
  /// One run from the seed, from two trees of their roots only.
  PlannerStatus solve() override;
  void clear() override;

  /// The tree rooted at c_ini (kStartTree) or at c_goal (kGoalTree).
  const ConnectTree& tree(std::size_t which) const { return trees_.at(which); }

 private:
  /// Where a tree's steps toward a target ended: the target reached (its node) or a step blocked.
  struct Reach {
    bool reached = false;
    ConnectTree::Node node = 0;
  };

  /// Steps of `tree` toward `target` (free), each from the tree's node nearest to it and at most
  /// the range long, until it is reached or a step's end or probes collide.
  Reach connect(ConnectTree& tree, const Configuration& target, const Eigen::VectorXd& targetUnit);
  /// The `probes` first inner states of the segment in Van der Corput order (midpoint, quarters,
  /// ...), checked together (StateValidator::firstWithValidity); false if one collides.
  bool probe(const Configuration& from, const Configuration& to);
  /// Motion-checks the unchecked segments from the two nodes to their roots, longest first; a
  /// blocked one is cut off its tree. True if the whole path is free.
  bool certify(ConnectTree::Node startSide, ConnectTree::Node goalSide);
  PlannerStatus finish(ConnectTree::Node startSide, ConnectTree::Node goalSide);
  PlannerStatus endRun(PlannerStatus status);

  double range_ = 0.0;
  std::array<ConnectTree, 2> trees_;
  std::vector<Configuration> probeStates_;
  std::vector<const Configuration*> probePointers_;
};

}  // namespace pmdplan
