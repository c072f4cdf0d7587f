#include "pmdplan/planning/lazy_pmd_planner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pmdplan/planning/path_smoothing.hpp"

namespace pmdplan {
namespace {

/// The base-2 radical inverse of n >= 1: 1/2, 1/4, 3/4, 1/8, 5/8, ... (never 0 or 1).
double radicalInverse(std::size_t n) {
  double value = 0.0;
  for (double scale = 0.5; n != 0; n >>= 1, scale *= 0.5)
    if ((n & 1u) != 0) value += scale;
  return value;
}

Configuration interpolate(const Configuration& a, const Configuration& b, double t) { return a + t * (b - a); }

}  // namespace

LazyPmdPlanner::LazyPmdPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                               std::unique_ptr<HandSampler> handSampler, PlannerParameters parameters)
    : space_(std::move(space)),
      stateValidator_(stateValidator),
      motionValidator_(motionValidator),
      handSampler_(std::move(handSampler)),
      parameters_(parameters) {
  if (!handSampler_) throw std::invalid_argument("LazyPmdPlanner: a hand sampler is required");
}

void LazyPmdPlanner::setStartAndGoal(Configuration start, Configuration goal) {
  start_ = std::move(start);
  goal_ = std::move(goal);
  armSampler_.reset();
}

void LazyPmdPlanner::setup() {
  parameters_.check();
  space_.check();
  for (const auto& [q, which] : {std::pair{&start_, "start"}, std::pair{&goal_, "goal"}}) {
    if (q->size() != space_.dof())
      throw std::invalid_argument(std::string("LazyPmdPlanner: the ") + which + " has " + std::to_string(q->size()) +
                                  " values, the space " + std::to_string(space_.dof()) +
                                  " joints (setStartAndGoal first)");
    if (!q->allFinite() || !space_.withinLimits(*q))
      throw std::invalid_argument(std::string("LazyPmdPlanner: the ") + which + " is outside the joint limits");
  }
  armSampler_.emplace(space_, start_, goal_);
  radius_ = parameters_.lazy.radiusFactor * space_.distance(start_, goal_);
}

void LazyPmdPlanner::clear() {
  roadmap_.clear();
  draws_ = 0;
  path_.clear();
  unsmoothedPath_.clear();
  statistics_ = {};
}

PlannerStatus LazyPmdPlanner::solve() {
  setup();
  clear();
  random_.reseed(parameters_.seed);
  began_ = Clock::now();
  deadline_.reset();
  if (std::isfinite(parameters_.timeLimit))
    deadline_ =
        began_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(parameters_.timeLimit));
  motionChecksAtStart_ = motionValidator_.statesChecked();

  statistics_.stateChecks += 2;
  if (!stateValidator_.isValid(start_)) return endRun(PlannerStatus::InvalidStart);
  if (!stateValidator_.isValid(goal_)) return endRun(PlannerStatus::InvalidGoal);
  const NodeIndex start = roadmap_.addNode(start_, space_.normalise(start_));
  const NodeIndex goal = roadmap_.addNode(goal_, space_.normalise(goal_));
  if (roadmap_.distance(start, goal) == 0.0) return finish({{start, goal}, {}});
  roadmap_.addEdge(start, goal);  // the first candidate: the straight segment

  double rho = parameters_.initialArmHalfSize;
  for (std::size_t round = 1;; ++round) {
    statistics_.sweeps = round;
    statistics_.finalArmHalfSize = rho;
    for (LazyPath candidate = roadmap_.shortestPath(start, goal); !candidate.nodes.empty();
         candidate = roadmap_.shortestPath(start, goal)) {
      if (certify(candidate)) return finish(candidate);
      if (timeIsUp()) return endRun(PlannerStatus::TimeLimit);
    }
    std::optional<PlannerStatus> stop;
    // Where the arm boxes are centred on the segment: every round first at the goal and at the
    // start (their neighbourhoods decide most tasks), in boxes of the initial rho_a (so that some
    // samples stay next to them however far rho_a has grown) and of this round's, then on along
    // the segment at 1/2, 1/4, 3/4, 1/8, ...
    for (std::size_t i = 0; i < 4 + parameters_.lazy.batch && !stop; ++i) {
      if (i < 4)
        sampleNode(i % 2 == 0 ? 1.0 : 0.0, i < 2 ? parameters_.initialArmHalfSize : rho, stop);
      else
        sampleNode(radicalInverse(++draws_), rho, stop);
    }
    if (stop) return endRun(*stop);
    rho = std::min(rho * parameters_.lazy.armGrowth, 1.0);
  }
}

void LazyPmdPlanner::sampleNode(double step, double armHalfSize, std::optional<PlannerStatus>& stop) {
  Configuration q = start_;
  std::size_t trials = 0;
  for (int j = 0; j < parameters_.armTrials; ++j) {
    if (statistics_.samples >= parameters_.maxSamples || statistics_.armTrials >= parameters_.maxSamples) {
      stop = PlannerStatus::SampleLimit;
      return;
    }
    if (timeIsUp()) {
      stop = PlannerStatus::TimeLimit;
      return;
    }
    ++statistics_.armTrials;
    if (!space_.armIndices.empty()) {
      ++statistics_.stateChecks;
      if (!armSampler_->sample(step, armHalfSize, random_, stateValidator_, q)) continue;
    }
    int dimension = handSampler_->initialDimension();
    for (int h = 0; h < parameters_.handTrials; ++h) {
      if (statistics_.samples >= parameters_.maxSamples) {
        stop = PlannerStatus::SampleLimit;
        return;
      }
      handSampler_->sample(dimension, random_, q);
      ++statistics_.samples;
      ++statistics_.stateChecks;
      ++trials;
      if (stateValidator_.isValid(q)) {
        statistics_.maxTrials = std::max(statistics_.maxTrials, trials);
        ++statistics_.nodesByHandDimension[dimension];
        connect(roadmap_.addNode(q, space_.normalise(q)), step);
        return;
      }
      dimension = std::min(dimension + 1, handSampler_->maxDimension());
    }
  }
}

// Lazy edges to the nearest nodes within the radius; a sample of the start's (goal's) arm box is
// always joined to c_ini (c_goal), nodes 0 and 1, as in Sect. 5.2. An edge costs nothing until a
// candidate path uses it.
void LazyPmdPlanner::connect(NodeIndex node, double step) {
  std::vector<NodeIndex> neighbours = roadmap_.nearest(node, parameters_.lazy.neighbours, radius_);
  const std::optional<NodeIndex> forced = step == 0.0   ? std::optional<NodeIndex>{0}
                                          : step == 1.0 ? std::optional<NodeIndex>{1}
                                                        : std::nullopt;
  if (forced && std::find(neighbours.begin(), neighbours.end(), *forced) == neighbours.end())
    neighbours.push_back(*forced);
  for (const NodeIndex other : neighbours) roadmap_.addEdge(other, node);
}

bool LazyPmdPlanner::certify(const LazyPath& candidate) {
  std::vector<EdgeIndex> unknown;
  for (const EdgeIndex e : candidate.edges)
    if (roadmap_.edge(e).status == LazyEdgeStatus::Unknown) unknown.push_back(e);
  // Longest first: the most likely to be blocked.
  std::stable_sort(unknown.begin(), unknown.end(),
                   [&](EdgeIndex a, EdgeIndex b) { return roadmap_.edge(a).length > roadmap_.edge(b).length; });
  for (std::size_t level = 1; level <= parameters_.lazy.probes; ++level)
    for (const EdgeIndex e : unknown) {
      LazyEdge& edge = roadmap_.edge(e);
      if (edge.probesChecked >= level) continue;
      if (!probe(edge)) return false;
    }
  for (const EdgeIndex e : unknown) {
    LazyEdge& edge = roadmap_.edge(e);
    const bool free = motionValidator_.isValid(roadmap_.configuration(edge.from), roadmap_.configuration(edge.to));
    edge.status = free ? LazyEdgeStatus::Free : LazyEdgeStatus::Blocked;
    if (!free) return false;
  }
  return true;
}

// The next inner state of the edge in Van der Corput order (1/2, 1/4, 3/4, ...).
bool LazyPmdPlanner::probe(LazyEdge& edge) {
  ++edge.probesChecked;
  ++statistics_.stateChecks;
  const Configuration q = interpolate(roadmap_.configuration(edge.from), roadmap_.configuration(edge.to),
                                      radicalInverse(edge.probesChecked));
  if (stateValidator_.isValid(q)) return true;
  edge.status = LazyEdgeStatus::Blocked;
  return false;
}

PlannerStatus LazyPmdPlanner::finish(const LazyPath& path) {
  for (const NodeIndex node : path.nodes) unsmoothedPath_.push_back(roadmap_.configuration(node));
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

PlannerStatus LazyPmdPlanner::endRun(PlannerStatus status) {
  statistics_.status = status;
  if (status != PlannerStatus::Solved) statistics_.planningTime = elapsedSeconds();
  statistics_.roadmapNodes = roadmap_.nodeCount();
  statistics_.roadmapEdges = roadmap_.edgeCount();
  statistics_.motionChecks = motionValidator_.statesChecked() - motionChecksAtStart_;
  return status;
}

bool LazyPmdPlanner::timeIsUp() const { return deadline_ && Clock::now() >= *deadline_; }

double LazyPmdPlanner::elapsedSeconds() const { return std::chrono::duration<double>(Clock::now() - began_).count(); }

}  // namespace pmdplan
