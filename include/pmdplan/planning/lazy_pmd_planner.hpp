#pragma once
// Our fast planner (`--planner pmd-lazy`): the PMD planner's samples in a lazy roadmap (Bohlin &
// Kavraki's Lazy PRM). Nodes are the paper's hand-arm samples: arms in a box of half-size rho_a
// around a point of the start-goal arm segment, hands from the thumb base + the first PMDs, the
// dimension growing by one per failed hand draw (Algorithms 1 and 2). Edges are added without a
// motion check; the shortest path is searched, and only its edges are checked: first a few inner
// states of every unknown edge, then the full motion checks, the longest edge first. A blocked
// edge is dropped and the search repeated; when no path is left, a new batch of samples is drawn
// with rho_a grown. The first candidate is the straight segment from c_ini to c_goal.
// A Planner (planner.hpp), registered as `pmd-lazy` (planner_registry.hpp): construct,
// setStartAndGoal, solve, read path() and statistics().
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "pmdplan/planning/lazy_roadmap.hpp"
#include "pmdplan/planning/pmd_planner_base.hpp"

namespace pmdplan {

class LazyPmdPlanner : public PmdPlannerBase {
 public:
  /// The validators are borrowed and must outlive the planner. Of `parameters` it uses rho_a,
  /// n_A, n_H, N, the PMD box (through the hand sampler), the time limit, the seed, smoothing and
  /// the `lazy` settings.
  LazyPmdPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                 std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters = {});

  std::string name() const override { return "pmd-lazy"; }
  /// Throws InputError for bad parameters, std::invalid_argument for a malformed space or problem.
  void setup() override;
  /// One run from the seed, from an empty roadmap.
  PlannerStatus solve() override;
  void clear() override;

  const LazyRoadmap& roadmap() const { return roadmap_; }

 private:
  /// Draws up to n_A arms around the segment point at `step`, each with up to n_H hands
  /// (drawHandArm); adds and lazily connects the first free one. A limit reached is returned.
  std::optional<PlannerStatus> sampleNode(double step, double armHalfSize);
  void connect(NodeIndex node, double step);
  /// Checks the candidate's unknown edges; true if all are free, false once one is blocked.
  bool certify(const LazyPath& candidate);
  bool probe(LazyEdge& edge);
  PlannerStatus finish(const LazyPath& path);
  PlannerStatus endRun(PlannerStatus status);

  double radius_ = 0.0;
  LazyRoadmap roadmap_;
  std::size_t draws_ = 0;  ///< hypercubes visited: the index of the next step
};

}  // namespace pmdplan
