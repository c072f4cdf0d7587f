#include "pmdplan/planning/pmd_roadmap_planner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/roadmap_path_search.hpp"
#include "pmdplan/planning/sample_connection.hpp"
#include "pmdplan/planning/van_der_corput.hpp"

namespace pmdplan {

PmdRoadmapPlanner::PmdRoadmapPlanner(PlanningSpace space, StateValidator& stateValidator,
                                     MotionValidator& motionValidator, std::unique_ptr<HandSampler> handSampler,
                                     PlannerParameters parameters)
    : space_(std::move(space)),
      stateValidator_(stateValidator),
      motionValidator_(motionValidator),
      handSampler_(std::move(handSampler)),
      parameters_(parameters) {
  if (!handSampler_) throw std::invalid_argument("PmdRoadmapPlanner: a hand sampler is required");
}

void PmdRoadmapPlanner::setStartAndGoal(Configuration start, Configuration goal) {
  start_ = std::move(start);
  goal_ = std::move(goal);
  armSampler_.reset();
}

void PmdRoadmapPlanner::setup() {
  parameters_.check();
  space_.check();
  for (const auto& [q, which] : {std::pair{&start_, "start"}, std::pair{&goal_, "goal"}}) {
    if (q->size() != space_.dof())
      throw std::invalid_argument(std::string("PmdRoadmapPlanner: the ") + which + " has " + std::to_string(q->size()) +
                                  " values, the space " + std::to_string(space_.dof()) +
                                  " joints (setStartAndGoal first)");
    if (!q->allFinite() || !space_.withinLimits(*q))
      throw std::invalid_argument(std::string("PmdRoadmapPlanner: the ") + which + " is outside the joint limits");
  }
  armSampler_.emplace(space_, start_, goal_);
  // FINDNEIGHBORS' threshold: the start-goal distance (times a factor, 1 in the paper), in the
  // same normalised full space as all other distances (docs/deviations.md).
  startGoalDistance_ = space_.distance(start_, goal_);
  neighbourThreshold_ = parameters_.neighbourThresholdFactor * startGoalDistance_;
}

void PmdRoadmapPlanner::clear() {
  roadmap_.clear();
  path_.clear();
  unsmoothedPath_.clear();
  statistics_ = {};
}

// Algorithm 4 (RoadMap). The j and h loops live in sampleHypercube, FINDPATH in findPath.
PlannerStatus PmdRoadmapPlanner::solve() {
  setup();
  beginRun();
  ++statistics_.stateChecks;
  if (!stateValidator_.isValid(start_)) return endRun(PlannerStatus::InvalidStart);
  ++statistics_.stateChecks;
  if (!stateValidator_.isValid(goal_)) return endRun(PlannerStatus::InvalidGoal);

  startNode_ = addNode(start_, 0.0, 0);
  goalNode_ = addNode(goal_, 1.0, 0);
  if (startGoalDistance_ == 0.0) {  // c_ini = c_goal: nothing to plan, and no neighbour could be found.
    roadmap_.addEdge(startNode_, goalNode_);
    return findPath();
  }
  const ConnectionRule rule{parameters_.neighbourCount, neighbourThreshold_};

  double rho = parameters_.initialArmHalfSize;
  for (std::size_t k = 1;; ++k) {
    // rho_a = k·rho_a (or k·rho_a(1), see ArmBoxGrowth), capped at 1: a box of that half-size
    // around any point of the segment already covers the whole normalised arm box, and k! would
    // overflow after ~170 fruitless sweeps.
    const double grown = parameters_.armBoxGrowth == ArmBoxGrowth::Factorial ? rho : parameters_.initialArmHalfSize;
    rho = std::min(static_cast<double>(k) * grown, 1.0);
    statistics_.sweeps = k;
    statistics_.finalArmHalfSize = rho;
    const std::size_t maxsteps = segmentIntervals(armSampler_->segmentLength(), rho);
    SearchRange searchRange;
    // One pass over the hypercubes in the search range, as the paper; when the range has
    // narrowed to fewer than minSweepVisits of them, more passes while they still add nodes.
    std::size_t visits = 0;
    for (bool added = true; added && visits < parameters_.minSweepVisits;) {
      added = false;
      for (std::size_t i = 0; i <= maxsteps; ++i) {
        const double step = vanDerCorput(i, maxsteps);
        if (!searchRange.contains(step)) continue;
        ++visits;
        if (progress_)
          progress_({k, rho, i, maxsteps + 1, searchRange, statistics_.samples, roadmap_.nodeCount(),
                     roadmap_.componentCount(), elapsedSeconds()});
        const HypercubeOutcome outcome = sampleHypercube(step, rho);
        if (outcome.stop) return endRun(*outcome.stop);
        if (!outcome.node) continue;
        added = true;
        connectSample(roadmap_, *outcome.node, rule, forcedNeighbour(step), motionValidator_);
        if (roadmap_.sameComponent(startNode_, goalNode_)) return findPath();
        searchRange = updateSearchRange(roadmap_, startNode_, goalNode_);
      }
    }
  }
}

// One hypercube B^a(step): up to n_A arm configurations (Algorithm 1, one trial each), each with up
// to n_H hand configurations (Algorithm 2, one trial each), the hand dimension growing by one per
// failed hand sample. A sample is one hand-arm draw (Table 2's count); N bounds the samples and,
// so that an arm that never comes free cannot loop for ever, the arm trials too. N and the time
// limit are checked before every draw.
PmdRoadmapPlanner::HypercubeOutcome PmdRoadmapPlanner::sampleHypercube(double step, double armHalfSize) {
  Configuration q = start_;
  std::size_t trials = 0;
  for (int j = 0; j < parameters_.armTrials; ++j) {
    if (statistics_.samples >= parameters_.maxSamples || statistics_.armTrials >= parameters_.maxSamples)
      return {std::nullopt, PlannerStatus::SampleLimit};
    if (timeIsUp()) return {std::nullopt, PlannerStatus::TimeLimit};
    ++statistics_.armTrials;
    // A hand alone has no arm to sample (its segment has length 0: the hypercubes at 0 and 1
    // only, which try c_ini and c_goal in turn).
    if (!space_.armIndices.empty()) {
      ++statistics_.stateChecks;
      if (!armSampler_->sample(step, armHalfSize, random_, stateValidator_, q)) continue;
    }
    int dimSch = handSampler_->initialDimension();
    for (int h = 0; h < parameters_.handTrials; ++h) {
      if (statistics_.samples >= parameters_.maxSamples) return {std::nullopt, PlannerStatus::SampleLimit};
      if (timeIsUp()) return {std::nullopt, PlannerStatus::TimeLimit};
      handSampler_->sample(dimSch, random_, q);
      ++statistics_.samples;
      ++statistics_.stateChecks;
      ++trials;
      if (stateValidator_.isValid(q)) {
        statistics_.maxTrials = std::max(statistics_.maxTrials, trials);
        ++statistics_.nodesByHandDimension[dimSch];
        return {addNode(q, step, dimSch), std::nullopt};
      }
      dimSch = std::min(dimSch + 1, handSampler_->maxDimension());
    }
  }
  return {};
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
  statistics_.planningTime = elapsedSeconds();
  const Clock::time_point smoothingBegan = Clock::now();
  path_ = parameters_.smooth ? smoothPath(unsmoothedPath_, space_, motionValidator_) : unsmoothedPath_;
  statistics_.smoothingTime = std::chrono::duration<double>(Clock::now() - smoothingBegan).count();
  statistics_.pathNodesBeforeSmoothing = unsmoothedPath_.size();
  statistics_.pathNodes = path_.size();
  statistics_.pathLengthBeforeSmoothing = pathLength(unsmoothedPath_, space_);
  statistics_.pathLength = pathLength(path_, space_);
  return endRun(PlannerStatus::Solved);
}

void PmdRoadmapPlanner::beginRun() {
  clear();
  random_.reseed(parameters_.seed);
  began_ = Clock::now();
  deadline_.reset();
  if (std::isfinite(parameters_.timeLimit))
    deadline_ =
        began_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(parameters_.timeLimit));
  motionChecksAtStart_ = motionValidator_.statesChecked();
}

PlannerStatus PmdRoadmapPlanner::endRun(PlannerStatus status) {
  statistics_.status = status;
  if (status != PlannerStatus::Solved) statistics_.planningTime = elapsedSeconds();
  statistics_.roadmapNodes = roadmap_.nodeCount();
  statistics_.roadmapEdges = roadmap_.edgeCount();
  statistics_.motionChecks = motionValidator_.statesChecked() - motionChecksAtStart_;
  return status;
}

bool PmdRoadmapPlanner::timeIsUp() const { return deadline_ && Clock::now() >= *deadline_; }

double PmdRoadmapPlanner::elapsedSeconds() const {
  return std::chrono::duration<double>(Clock::now() - began_).count();
}

}  // namespace pmdplan
