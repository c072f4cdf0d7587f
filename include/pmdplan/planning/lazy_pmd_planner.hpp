#pragma once
// Our fast planner (`--planner pmd-lazy`): the PMD planner's samples in a lazy roadmap (Bohlin &
// Kavraki's Lazy PRM). Nodes are the paper's hand-arm samples: arms in a box of half-size rho_a
// around a point of the start-goal arm segment, hands from the thumb base + the first PMDs, the
// dimension growing by one per failed hand draw (Algorithms 1 and 2). Edges are added without a
// motion check; the shortest path is searched, and only its edges are checked: first a few inner
// states of every unknown edge, then the full motion checks, the longest edge first. A blocked
// edge is dropped and the search repeated; when no path is left, a new batch of samples is drawn
// with rho_a grown. The first candidate is the straight segment from c_ini to c_goal.
// Shaped like PmdRoadmapPlanner: construct, setStartAndGoal, solve, read path() and statistics().
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/collision/state_validator.hpp"
#include "pmdplan/core/random_source.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/arm_segment_sampler.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/lazy_roadmap.hpp"
#include "pmdplan/planning/planner_parameters.hpp"
#include "pmdplan/planning/planner_run.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {

class LazyPmdPlanner {
 public:
  /// The validators are borrowed and must outlive the planner. Of `parameters` it uses rho_a,
  /// n_A, n_H, N, the PMD box (through the hand sampler), the time limit, the seed, smoothing and
  /// the `lazy` settings.
  LazyPmdPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                 std::unique_ptr<HandSampler> handSampler, PlannerParameters parameters = {});
  LazyPmdPlanner(const LazyPmdPlanner&) = delete;
  LazyPmdPlanner& operator=(const LazyPmdPlanner&) = delete;

  void setStartAndGoal(Configuration start, Configuration goal);
  /// Throws InputError for bad parameters, std::invalid_argument for a malformed space or problem.
  void setup();
  /// One run from the seed, from an empty roadmap.
  PlannerStatus solve();
  void clear();

  /// The (smoothed) path, c_ini first, c_goal last; empty unless solved.
  const std::vector<Configuration>& path() const { return path_; }
  const std::vector<Configuration>& unsmoothedPath() const { return unsmoothedPath_; }
  const PlanningStatistics& statistics() const { return statistics_; }
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

  PlanningSpace space_;
  StateValidator& stateValidator_;
  MotionValidator& motionValidator_;
  std::unique_ptr<HandSampler> handSampler_;
  PlannerParameters parameters_;

  Configuration start_;
  Configuration goal_;
  std::optional<ArmSegmentSampler> armSampler_;
  double radius_ = 0.0;

  RandomSource random_;
  LazyRoadmap roadmap_;
  std::size_t draws_ = 0;  ///< hypercubes visited: the index of the next step
  std::vector<Configuration> path_;
  std::vector<Configuration> unsmoothedPath_;
  PlanningStatistics statistics_;
  PlannerRun run_;
};

}  // namespace pmdplan
