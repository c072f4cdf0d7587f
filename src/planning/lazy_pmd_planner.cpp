#include "pmdplan/planning/lazy_pmd_planner.hpp"

#include <algorithm>
#include <string>

#include "pmdplan/planning/hand_arm_draw.hpp"
#include "pmdplan/planning/van_der_corput.hpp"

namespace pmdplan {
namespace {

Configuration interpolate(const Configuration& a, const Configuration& b, double t) { return a + t * (b - a); }

}  // namespace

LazyPmdPlanner::LazyPmdPlanner(PlanningSpace space, StateValidator& stateValidator, MotionValidator& motionValidator,
                               std::unique_ptr<HandSampler> handSampler, PlannerSettings parameters)
    : PmdPlannerBase(std::move(space), stateValidator, motionValidator, std::move(handSampler), parameters,
                     "LazyPmdPlanner") {}

void LazyPmdPlanner::setup() {
  setupProblem();
  radius_ = parameters_.lazy.radius * space_.distance(start_, goal_);
}

void LazyPmdPlanner::clear() {
  roadmap_.clear();
  draws_ = 0;
  clearResults();
}

PlannerStatus LazyPmdPlanner::solve() {
  setup();
  clear();
  beginRun();
  if (const auto invalid = checkStartAndGoalStates()) return endRun(*invalid);
  const NodeIndex start = roadmap_.addNode(start_, space_.normalise(start_));
  const NodeIndex goal = roadmap_.addNode(goal_, space_.normalise(goal_));
  if (roadmap_.distance(start, goal) == 0.0) return finish({{start, goal}, {}});
  roadmap_.addEdge(start, goal);  // the first candidate: the straight segment

  double rho = parameters_.rhoA;
  for (std::size_t round = 1;; ++round) {
    statistics_.sweeps = round;
    statistics_.finalArmHalfSize = rho;
    for (LazyPath candidate = roadmap_.shortestPath(start, goal); !candidate.nodes.empty();
         candidate = roadmap_.shortestPath(start, goal)) {
      if (certify(candidate)) return finish(candidate);
      if (run_.timeIsUp()) return endRun(PlannerStatus::TimeLimit);
    }
    std::optional<PlannerStatus> stop;
    // Where the arm boxes are centred on the segment: every round first at the goal and at the
    // start (their neighbourhoods decide most tasks), in boxes of the initial rho_a (so that some
    // samples stay next to them however far rho_a has grown) and of this round's, then on along
    // the segment at 1/2, 1/4, 3/4, 1/8, ...
    for (std::size_t i = 0; i < 4 + parameters_.lazy.batch && !stop; ++i) {
      if (i < 4)
        stop = sampleNode(i % 2 == 0 ? 1.0 : 0.0, i < 2 ? parameters_.rhoA : rho);
      else
        stop = sampleNode(radicalInverse(++draws_), rho);
    }
    if (stop) return endRun(*stop);
    rho = std::min(rho * parameters_.lazy.armGrowth, 1.0);
  }
}

std::optional<PlannerStatus> LazyPmdPlanner::sampleNode(double step, double armHalfSize) {
  const HandArmDraw draw = drawHandArm({space_, *armSampler_, *handSampler_, stateValidator_, parameters_}, step,
                                       armHalfSize, start_, points_, run_, statistics_);
  if (draw.sample) connect(roadmap_.addNode(*draw.sample, space_.normalise(*draw.sample)), step);
  return draw.stop;
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
  path_ = run_.finishPath(unsmoothedPath_, space_, motionValidator_, parameters_.smooth, statistics_);
  return endRun(PlannerStatus::Solved);
}

PlannerStatus LazyPmdPlanner::endRun(PlannerStatus status) {
  return finishRun(status, roadmap_.nodeCount(), roadmap_.edgeCount());
}

}  // namespace pmdplan
