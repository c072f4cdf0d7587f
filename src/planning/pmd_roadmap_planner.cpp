#include "pmdplan/planning/pmd_roadmap_planner.hpp"

#include <algorithm>
#include <string>

#include "pmdplan/planning/hand_arm_draw.hpp"
#include "pmdplan/planning/roadmap_path_search.hpp"
#include "pmdplan/planning/sample_connection.hpp"
#include "pmdplan/planning/van_der_corput.hpp"

namespace pmdplan {

PmdRoadmapPlanner::PmdRoadmapPlanner(PlanningSpace space, StateValidator& stateValidator,
                                     MotionValidator& motionValidator, std::unique_ptr<HandSampler> handSampler,
                                     PlannerSettings parameters)
    : PmdPlannerBase(std::move(space), stateValidator, motionValidator, std::move(handSampler), parameters,
                     "PmdRoadmapPlanner") {}

void PmdRoadmapPlanner::setup() {
  setupProblem();
  // FINDNEIGHBORS' threshold: the start-goal distance (times a factor, 1 in the paper), in the
  // same normalised full space as all other distances (docs/deviations.md).
  startGoalDistance_ = space_.distance(start_, goal_);
  neighbourThreshold_ = parameters_.neighbourThreshold * startGoalDistance_;
}

void PmdRoadmapPlanner::clear() {
  roadmap_.clear();
  clearResults();
}

// Algorithm 4 (RoadMap). The j and h loops live in drawHandArm (hand_arm_draw.hpp), FINDPATH in
// findPath.
PlannerStatus PmdRoadmapPlanner::solve() {
  setup();
  clear();
  beginRun();
  if (const auto invalid = checkStartAndGoalStates()) return endRun(*invalid);

  startNode_ = addNode(start_, 0.0, 0);
  goalNode_ = addNode(goal_, 1.0, 0);
  if (startGoalDistance_ == 0.0) {  // c_ini = c_goal: nothing to plan, and no neighbour could be found.
    roadmap_.addEdge(startNode_, goalNode_);
    return findPath();
  }
  const ConnectionRule rule{parameters_.neighbours, neighbourThreshold_};

  double rho = parameters_.rhoA;
  for (std::size_t k = 1;; ++k) {
    // rho_a = k·rho_a (or k·rho_a(1), see ArmBoxGrowth), capped at 1: a box of that half-size
    // around any point of the segment already covers the whole normalised arm box, and k! would
    // overflow after ~170 fruitless sweeps.
    const double grown = parameters_.rhoAGrowth == ArmBoxGrowth::Factorial ? rho : parameters_.rhoA;
    rho = std::min(static_cast<double>(k) * grown, 1.0);
    statistics_.sweeps = k;
    statistics_.finalArmHalfSize = rho;
    const std::size_t maxsteps = segmentIntervals(armSampler_->segmentLength(), rho);
    SearchRange searchRange;
    // One pass over the hypercubes in the search range, as the paper; when the range has
    // narrowed to fewer than sweepVisits of them, more passes while they still add nodes.
    std::size_t visits = 0;
    for (bool added = true; added && visits < parameters_.sweepVisits;) {
      added = false;
      for (std::size_t i = 0; i <= maxsteps; ++i) {
        const double step = vanDerCorput(i, maxsteps);
        if (!searchRange.contains(step)) continue;
        ++visits;
        if (progress_)
          progress_({k, rho, i, maxsteps + 1, searchRange, statistics_.samples, roadmap_.nodeCount(),
                     roadmap_.componentCount(), run_.elapsedSeconds()});
        const HandArmDraw draw = drawHandArm({space_, *armSampler_, *handSampler_, stateValidator_, parameters_}, step,
                                             rho, start_, points_, run_, statistics_);
        if (draw.stop) return endRun(*draw.stop);
        if (!draw.sample) continue;
        added = true;
        connectSample(roadmap_, addNode(*draw.sample, step, draw.handDimension), rule, forcedNeighbour(step),
                      motionValidator_);
        if (roadmap_.sameComponent(startNode_, goalNode_)) return findPath();
        searchRange = updateSearchRange(roadmap_, startNode_, goalNode_);
      }
    }
  }
}

NodeIndex PmdRoadmapPlanner::addNode(const Configuration& q, double step, int handDimension) {
  return roadmap_.addNode({q, space_.normalise(q), step, handDimension});
}

// Sect. 5.2: samples of the first (last) hypercube always try c_ini (c_goal).
std::optional<NodeIndex> PmdRoadmapPlanner::forcedNeighbour(double step) const {
  if (step == 0.0) return startNode_;
  if (step == 1.0) return goalNode_;
  return std::nullopt;
}

// FINDPATH: A* on the roadmap, then the smoothing of Sect. 5.3.
PlannerStatus PmdRoadmapPlanner::findPath() {
  for (const NodeIndex node : findRoadmapPath(roadmap_, startNode_, goalNode_))
    unsmoothedPath_.push_back(roadmap_.node(node).configuration);
  path_ = run_.finishPath(unsmoothedPath_, space_, motionValidator_, parameters_.smooth, statistics_);
  return endRun(PlannerStatus::Solved);
}

PlannerStatus PmdRoadmapPlanner::endRun(PlannerStatus status) {
  return finishRun(status, roadmap_.nodeCount(), roadmap_.edgeCount());
}

}  // namespace pmdplan
