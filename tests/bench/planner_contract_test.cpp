// The contract of planning/planner.hpp, kept by every planner of the roster (ours and OMPL's,
// bench/planner_roster.hpp): the suite is instantiated over plannerRoster(), so a new registry line
// is tested here without a line more. The problem is a gate in the toy's wall
// (tests/planning/toy_problem.hpp: its space, start, goal and synergy model), wide enough for
// every planner (the toy's narrow passage takes OMPL's PRM and EST a minute), its checks analytic
// and exact.
// OMPL's seed is process-wide and honoured only before OMPL's first random number
// (bench/ompl_planner.hpp): for OMPL's planners the runs that must repeat each other run in a
// forked process (forked_run.hpp), as `pmdplan bench` runs them; ours run in this one. A planner
// whose runs are not repeatable (PlannerEntry::repeatable: OMPL's PRM grows its roadmap in a
// second thread) skips the checks that compare runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "planning/toy_problem.hpp"
#include "pmdplan/bench/forked_run.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/path_smoothing.hpp"

namespace pmdplan {
namespace {

/// The wall of the toy (0.45 <= u_shoulder <= 0.55) with a gate: inside the wall a configuration
/// is free only with the elbow near its middle (|u_elbow - 0.5| <= 0.2) and the hand half closed
/// (u_a + u_b <= 1); the toy's start and goal have open hands, so the path must bend. Closed: nothing
/// passes. The gate is convex, so a segment is free exactly when it enters and leaves the wall
/// through it.
struct Gate {
  bool open = true;

  bool inWall(const Eigen::VectorXd& u) const { return u[0] >= 0.45 && u[0] <= 0.55; }
  bool inGate(const Eigen::VectorXd& u) const { return open && std::abs(u[1] - 0.5) <= 0.2 && u[3] + u[4] <= 1.0; }
  bool free(const Eigen::VectorXd& u) const { return u[1] <= 0.95 && (!inWall(u) || inGate(u)); }

  bool segmentFree(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    if (!free(a) || !free(b)) return false;
    const double d = b[0] - a[0];
    if (d == 0.0) return true;  // both ends free, the same shoulder value
    const double t0 = std::max(std::min((0.45 - a[0]) / d, (0.55 - a[0]) / d), 0.0);
    const double t1 = std::min(std::max((0.45 - a[0]) / d, (0.55 - a[0]) / d), 1.0);
    return t0 > t1 || (inGate(a + t0 * (b - a)) && inGate(a + t1 * (b - a)));
  }
};

class GateStates : public StateValidator {
 public:
  explicit GateStates(Gate gate) : gate_(gate), space_(toy::space()) {}
  bool isValid(const Configuration& q) override { return ++checks_, gate_.free(space_.normalise(q)); }
  bool isArmValid(const Configuration& q) override { return ++checks_, space_.normalise(q)[1] <= 0.95; }
  std::size_t checkCount() const override { return checks_; }

 private:
  Gate gate_;
  PlanningSpace space_;
  std::size_t checks_ = 0;
};

class GateMotions : public MotionValidator {
 public:
  explicit GateMotions(Gate gate) : gate_(gate), space_(toy::space()) {}
  bool isValid(const Configuration& from, const Configuration& to) override {
    states_ += 2;
    return gate_.segmentFree(space_.normalise(from), space_.normalise(to));
  }
  std::size_t statesChecked() const override { return states_; }

 private:
  Gate gate_;
  PlanningSpace space_;
  std::size_t states_ = 0;
};

/// An independent check of a path: every segment sampled every 1e-4 (normalised), states only.
bool densePathIsFree(const std::vector<Configuration>& path) {
  const PlanningSpace space = toy::space();
  for (std::size_t k = 0; k + 1 < path.size(); ++k) {
    const Eigen::VectorXd a = space.normalise(path[k]), b = space.normalise(path[k + 1]);
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 1e-4)));
    for (int i = 0; i <= n; ++i)
      if (!Gate{}.free(a + (static_cast<double>(i) / n) * (b - a))) return false;
  }
  return true;
}

/// A planner of the roster on the gate problem, with validators of its own.
struct ToyPlanner {
  GateStates states;
  GateMotions motions;
  SynergyModel model = toy::synergyModel();
  std::unique_ptr<Planner> planner;

  ToyPlanner(const PlannerEntry& entry, const PlannerSettings& settings, Gate gate = {}) : states(gate), motions(gate) {
    planner = entry.allocate({toy::space(), states, motions, settings, &model});
    planner->setStartAndGoal(toy::start(), toy::goal());
  }
};

/// Inside the wall, outside its passage.
Configuration inTheWall() { return toy::fromUnit({0.5, 0.9, 0.3, 0.9, 0.9, 0.5}); }

/// A run's outcome as exact text: the status, every path value in hexadecimal and the counts.
std::string outcomeText(const Planner& planner) {
  const PlanningStatistics& s = planner.statistics();
  std::string text = plannerStatusName(s.status);
  char number[64];
  for (const Configuration& q : planner.path()) {
    text += "\n";
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      std::snprintf(number, sizeof number, " %a", q[i]);
      text += number;
    }
  }
  text += "\nsamples " + std::to_string(s.samples) + " state checks " + std::to_string(s.stateChecks) +
          " motion checks " + std::to_string(s.motionChecks) + " nodes " + std::to_string(s.roadmapNodes);
  return text;
}

class PlannerContract : public ::testing::TestWithParam<std::string> {
 protected:
  const PlannerEntry& entry() const { return plannerRoster().at(GetParam()); }
  PlannerSettings settings(std::uint64_t seed) const { return toy::withSeed(seed, entry().mode); }

  /// Skips a test that compares runs for a planner whose runs differ by design.
  bool skipUnlessRepeatable() const {
    if (entry().repeatable) return false;
    std::printf("%s: runs are not repeatable (PlannerEntry::repeatable); not compared\n", GetParam().c_str());
    return true;
  }

  /// `work`'s text, from a forked process for OMPL's planners.
  std::string isolated(const std::function<std::string()>& work) const {
    if (entry().family != PlannerFamily::Ompl) return work();
    const ChildOutcome child = runInChildProcess(work, 300.0);
    EXPECT_TRUE(child.finished()) << child.problem;
    return child.output;
  }
};

TEST_P(PlannerContract, IsMadeUnderItsRegistryName) {
  ToyPlanner run(entry(), settings(1));
  EXPECT_EQ(run.planner->name(), GetParam());
  EXPECT_TRUE(run.planner->path().empty());
  EXPECT_EQ(run.planner->statistics().status, PlannerStatus::NotRun);
}

TEST_P(PlannerContract, SolvesTheToyProblemWithAPathTheValidatorsAccept) {
  for (std::uint64_t seed = 1; seed <= 2; ++seed) {
    ToyPlanner run(entry(), settings(seed));
    ASSERT_EQ(run.planner->solve(), PlannerStatus::Solved) << "seed " << seed;
    const std::vector<Configuration>& path = run.planner->path();
    ASSERT_GE(path.size(), 3u) << "the straight segment is blocked, so the path must bend";
    EXPECT_EQ(path.front(), toy::start());
    EXPECT_EQ(path.back(), toy::goal());
    GateStates states{Gate{}};
    GateMotions motions{Gate{}};
    for (const Configuration& q : path) {
      EXPECT_TRUE(toy::space().withinLimits(q)) << "seed " << seed;
      EXPECT_TRUE(states.isValid(q)) << "seed " << seed;
    }
    for (std::size_t i = 0; i + 1 < path.size(); ++i) EXPECT_TRUE(motions.isValid(path[i], path[i + 1])) << i;
    EXPECT_TRUE(densePathIsFree(path)) << "seed " << seed;

    const PlanningStatistics& s = run.planner->statistics();
    EXPECT_EQ(s.status, PlannerStatus::Solved);
    EXPECT_TRUE(s.solved());
    EXPECT_GT(s.samples, 0u);
    EXPECT_GT(s.stateChecks, 0u);
    EXPECT_LE(s.stateChecks, run.states.checkCount()) << "no more checks reported than made";
    EXPECT_EQ(s.motionChecks, run.motions.statesChecked());
    EXPECT_EQ(s.collisionChecks(), s.stateChecks + s.motionChecks);
    EXPECT_GE(s.roadmapNodes, 2u);
    EXPECT_GT(s.planningTime, 0.0);
    EXPECT_EQ(s.pathNodes, path.size());
    EXPECT_GE(s.pathNodesBeforeSmoothing, 2u);
    EXPECT_NEAR(s.pathLength, pathLength(path, toy::space()), 1e-12);
    EXPECT_LE(s.pathLength, s.pathLengthBeforeSmoothing + 1e-12) << "smoothing never lengthens the path";
  }
}

TEST_P(PlannerContract, TheSameSeedGivesTheSamePath) {
  if (skipUnlessRepeatable()) GTEST_SKIP();
  const auto solved = [&] {
    ToyPlanner run(entry(), settings(7));
    run.planner->solve();
    return outcomeText(*run.planner);
  };
  const std::string first = isolated(solved);
  EXPECT_EQ(first.rfind("solved\n", 0), 0u) << first;
  EXPECT_EQ(isolated(solved), first);
}

TEST_P(PlannerContract, OtherSeedsGiveOtherRuns) {
  std::set<std::string> outcomes;
  for (std::uint64_t seed = 20; seed < 24; ++seed)
    outcomes.insert(isolated([&] {
      ToyPlanner run(entry(), settings(seed));
      run.planner->solve();
      return outcomeText(*run.planner);
    }));
  EXPECT_GT(outcomes.size(), 1u) << "the seed reaches the planner's sampling";
}

TEST_P(PlannerContract, AProgressCallbackOnlyObserves) {
  if (skipUnlessRepeatable()) GTEST_SKIP();
  const auto solved = [&](bool watched) {
    ToyPlanner run(entry(), settings(5));
    std::size_t calls = 0;
    if (watched) run.planner->setProgressCallback([&](const PlannerProgress&) { ++calls; });
    run.planner->solve();
    return outcomeText(*run.planner);
  };
  EXPECT_EQ(isolated([&] { return solved(true); }), isolated([&] { return solved(false); }));
}

TEST_P(PlannerContract, ClearThenSolveRepeatsTheRun) {
  const std::string twice = isolated([&] {
    ToyPlanner run(entry(), settings(5));
    run.planner->solve();
    const std::string first = outcomeText(*run.planner);
    run.planner->clear();
    if (!run.planner->path().empty() || run.planner->statistics().status != PlannerStatus::NotRun)
      return std::string("clear() left the run");
    run.planner->solve();
    return first + "\n--\n" + outcomeText(*run.planner);
  });
  const std::size_t cut = twice.find("\n--\n");
  ASSERT_NE(cut, std::string::npos) << twice;
  EXPECT_EQ(twice.rfind("solved\n", 0), 0u) << twice;
  if (entry().repeatable)
    EXPECT_EQ(twice.substr(0, cut), twice.substr(cut + 4));
  else
    EXPECT_EQ(twice.rfind("solved\n", cut + 4), cut + 4) << "solves again: " << twice;
}

TEST_P(PlannerContract, ACollidingStartOrGoalIsAStatusNotAPath) {
  ToyPlanner run(entry(), settings(1));
  run.planner->setStartAndGoal(inTheWall(), toy::goal());
  EXPECT_EQ(run.planner->solve(), PlannerStatus::InvalidStart);
  EXPECT_EQ(run.planner->statistics().status, PlannerStatus::InvalidStart);
  EXPECT_FALSE(run.planner->statistics().solved());
  EXPECT_TRUE(run.planner->path().empty());
  EXPECT_GE(run.planner->statistics().stateChecks, 1u);
  run.planner->setStartAndGoal(toy::start(), inTheWall());
  EXPECT_EQ(run.planner->solve(), PlannerStatus::InvalidGoal);
  EXPECT_EQ(run.planner->statistics().status, PlannerStatus::InvalidGoal);
  EXPECT_TRUE(run.planner->path().empty());
}

TEST_P(PlannerContract, TheTimeLimitEndsARunThatCannotSucceed) {
  PlannerSettings limited = settings(3);
  limited.maxSamples = std::numeric_limits<std::size_t>::max();
  limited.timeLimit = 0.3;
  ToyPlanner run(entry(), limited, Gate{false});
  const auto began = std::chrono::steady_clock::now();
  EXPECT_EQ(run.planner->solve(), PlannerStatus::TimeLimit);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  EXPECT_LT(seconds, 10.0) << "the limit must stop the run; generous for a loaded machine";
  EXPECT_GE(run.planner->statistics().planningTime, 0.25);
  EXPECT_TRUE(run.planner->path().empty());
}

TEST_P(PlannerContract, BadSettingsAreInputErrors) {
  const auto expectRejected = [&](const std::string& field, PlannerSettings bad) {
    ToyPlanner run(entry(), bad);
    try {
      run.planner->setup();
      ADD_FAILURE() << field << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field);
    }
    EXPECT_THROW(run.planner->solve(), InputError) << field;
  };
  PlannerSettings bad = settings(1);
  bad.timeLimit = -1.0;
  expectRejected("time-limit", bad);
  bad = settings(1);
  bad.rhoA = 2.0;
  expectRejected("rho-a", bad);
}

TEST_P(PlannerContract, AMalformedProblemIsAnInvalidArgument) {
  ToyPlanner run(entry(), settings(1));
  run.planner->setStartAndGoal(Eigen::VectorXd::Zero(3), toy::goal());
  EXPECT_THROW(run.planner->setup(), std::invalid_argument);
  Configuration outside = toy::start();
  outside[0] = 5.0;
  run.planner->setStartAndGoal(outside, toy::goal());
  EXPECT_THROW(run.planner->solve(), std::invalid_argument);
}

std::vector<std::string> rosterNames() {
  std::vector<std::string> names;
  for (const PlannerEntry& entry : plannerRoster().entries()) names.push_back(entry.name);
  return names;
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryPlanner, PlannerContract, ::testing::ValuesIn(rosterNames()), testName);

}  // namespace
}  // namespace pmdplan
