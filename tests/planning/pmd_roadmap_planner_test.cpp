#include "pmdplan/planning/pmd_roadmap_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "planning/toy_problem.hpp"
#include "pmdplan/planning/full_space_hand_sampler.hpp"
#include "pmdplan/planning/path_smoothing.hpp"
#include "pmdplan/planning/synergy_hand_sampler.hpp"

namespace pmdplan {
namespace {

/// Wraps a sampler and records the dimension of every call.
class RecordingHandSampler : public HandSampler {
 public:
  explicit RecordingHandSampler(std::unique_ptr<HandSampler> inner, std::vector<int>& dimensions)
      : inner_(std::move(inner)), dimensions_(dimensions) {}
  int initialDimension() const override { return inner_->initialDimension(); }
  int maxDimension() const override { return inner_->maxDimension(); }
  void sample(int dimension, UnitPoints& points, Configuration& q) const override {
    dimensions_.push_back(dimension);
    inner_->sample(dimension, points, q);
  }
  std::string name() const override { return inner_->name(); }

 private:
  std::unique_ptr<HandSampler> inner_;
  std::vector<int>& dimensions_;
};

/// A planner with its validators, for one toy run.
struct ToyRun {
  toy::WallStateValidator stateValidator;
  toy::WallMotionValidator motionValidator;
  PmdRoadmapPlanner planner;

  explicit ToyRun(PlannerSettings parameters, HandSamplingMode mode = HandSamplingMode::Synergy, toy::Wall wall = {})
      : stateValidator(wall),
        motionValidator(wall),
        planner(toy::space(), stateValidator, motionValidator, makeSampler(mode), parameters) {
    planner.setStartAndGoal(toy::start(), toy::goal());
  }

  static std::unique_ptr<HandSampler> makeSampler(HandSamplingMode mode) {
    const SynergyModel model = toy::synergyModel();
    return makeHandSampler(mode, toy::space(), &model);
  }
};

// What every planner does (a valid path, repeatable runs, statuses, limits, errors) is the contract
// suite's (tests/bench/planner_contract_test.cpp); here is what is the paper planner's own.

TEST(PmdRoadmapPlanner, StatisticsCountTheRoadmapAndTheDrawsOfAlgorithm4) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    ToyRun run(toy::withSeed(seed));
    ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved) << "seed " << seed;
    EXPECT_TRUE(toy::densePathIsFree(run.planner.unsmoothedPath())) << "seed " << seed;
    for (const Configuration& q : run.planner.path()) EXPECT_TRUE(toy::space().withinLimits(q, 0.0));

    const PlanningStatistics& stats = run.planner.statistics();
    EXPECT_EQ(stats.pathNodesBeforeSmoothing, run.planner.unsmoothedPath().size());
    EXPECT_EQ(stats.roadmapNodes, run.planner.roadmap().nodeCount());
    EXPECT_GE(stats.samples, stats.roadmapNodes - 2);
    EXPECT_GE(stats.armTrials, stats.roadmapNodes - 2);
    EXPECT_GE(stats.samples, stats.armTrials - (stats.roadmapNodes - 2))
        << "every arm trial that gave a node drew a hand";
    EXPECT_GE(stats.maxTrials, 1u);
    EXPECT_LE(stats.maxTrials, 100u);
    EXPECT_EQ(stats.finalArmHalfSize, 0.001) << "the first sweep suffices here";
    EXPECT_EQ(stats.stateChecks, run.stateValidator.checkCount());
    EXPECT_EQ(stats.motionChecks, run.motionValidator.statesChecked());
    std::size_t byDimension = 0;
    for (const auto& [dimension, count] : stats.nodesByHandDimension) {
      EXPECT_GE(dimension, 2);
      EXPECT_LE(dimension, 4);
      byDimension += count;
    }
    EXPECT_EQ(byDimension, stats.roadmapNodes - 2);
  }
}

TEST(PmdRoadmapPlanner, AProgressCallbackOnlyObserves) {
  ToyRun quiet(toy::withSeed(5));
  ToyRun watched(toy::withSeed(5));
  std::size_t calls = 0;
  std::size_t lastNodes = 0;
  watched.planner.setProgressCallback([&](const PlannerProgress& progress) {
    ++calls;
    EXPECT_EQ(progress.sweep, 1u);
    EXPECT_EQ(progress.hypercubes, 1025u);
    EXPECT_LT(progress.hypercube, progress.hypercubes);
    EXPECT_GE(progress.roadmapNodes, lastNodes);
    lastNodes = progress.roadmapNodes;
  });
  ASSERT_EQ(quiet.planner.solve(), PlannerStatus::Solved);
  ASSERT_EQ(watched.planner.solve(), PlannerStatus::Solved);
  EXPECT_GT(calls, 0u);
  EXPECT_EQ(quiet.planner.path(), watched.planner.path());
}

TEST(PmdRoadmapPlanner, TheFullSpaceSwitchSolvesWithWholeHandSamples) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    ToyRun run(toy::withSeed(seed, HandSamplingMode::FullSpace), HandSamplingMode::FullSpace);
    EXPECT_EQ(run.planner.handSampler().name(), "full");
    EXPECT_EQ(run.planner.parameters().armTrials, 20);
    EXPECT_EQ(run.planner.parameters().handTrials, 20);
    ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved) << "seed " << seed;
    EXPECT_TRUE(toy::densePathIsFree(run.planner.path()));
    const auto& byDimension = run.planner.statistics().nodesByHandDimension;
    ASSERT_EQ(byDimension.size(), 1u);
    EXPECT_EQ(byDimension.begin()->first, 4) << "every hand joint at once";
    for (NodeIndex i = 2; i < run.planner.roadmap().nodeCount(); ++i)
      EXPECT_EQ(run.planner.roadmap().node(i).handDimension, 4);
  }
}

/// Start and goal free (the first two checks), every sample in collision.
class NothingButTheEndsIsFree : public StateValidator {
 public:
  bool isValid(const Configuration&) override { return ++checks_ <= 2; }
  bool isArmValid(const Configuration&) override { return true; }
  std::size_t checkCount() const override { return checks_; }

 private:
  std::size_t checks_ = 0;
};

// Algorithm 4: every arm configuration starts at dimension 2 and each failed hand sample adds one,
// up to the model's maximum (here thumb base + 3 PMDs = 4).
TEST(PmdRoadmapPlanner, HandDimensionGrowsFromTwoToTheMaximum) {
  NothingButTheEndsIsFree stateValidator;
  toy::WallMotionValidator motionValidator;
  const SynergyModel model = toy::synergyModel();
  std::vector<int> recorded;
  PlannerSettings parameters = toy::withSeed(1);
  parameters.maxSamples = 30;  // N bounds the samples (hand-arm draws): n_H = 10 for each of 3 arms
  PmdRoadmapPlanner planner(
      toy::space(), stateValidator, motionValidator,
      std::make_unique<RecordingHandSampler>(std::make_unique<SynergyHandSampler>(toy::space(), model), recorded),
      parameters);
  planner.setStartAndGoal(toy::start(), toy::goal());
  EXPECT_EQ(planner.solve(), PlannerStatus::SampleLimit);
  const std::vector<int> perArmConfiguration = {2, 3, 4, 4, 4, 4, 4, 4, 4, 4};
  ASSERT_EQ(recorded.size(), 3 * perArmConfiguration.size()) << "n_H hand samples for each of 3 arm samples";
  for (std::size_t i = 0; i < recorded.size(); ++i)
    EXPECT_EQ(recorded[i], perArmConfiguration[i % perArmConfiguration.size()]) << "hand sample " << i;
  EXPECT_EQ(planner.statistics().armTrials, 3u);
  EXPECT_EQ(planner.statistics().samples, 30u) << "Table 2's samples: one per hand-arm draw";
  EXPECT_EQ(planner.statistics().roadmapNodes, 2u);
}

TEST(PmdRoadmapPlanner, NodesRecordTheDimensionThatMadeThem) {
  ToyRun run(toy::withSeed(4));
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  std::map<int, std::size_t> counted;
  for (NodeIndex i = 2; i < run.planner.roadmap().nodeCount(); ++i)
    ++counted[run.planner.roadmap().node(i).handDimension];
  EXPECT_EQ(counted, run.planner.statistics().nodesByHandDimension);
  EXPECT_EQ(run.planner.roadmap().node(0).handDimension, 0) << "c_ini";
  EXPECT_EQ(run.planner.roadmap().node(1).handDimension, 0) << "c_goal";
}

TEST(PmdRoadmapPlanner, ARunThatCannotSucceedStopsAtTheSampleLimit) {
  PlannerSettings parameters = toy::withSeed(3);
  parameters.maxSamples = 50'000;
  ToyRun run(parameters, HandSamplingMode::Synergy, toy::Wall{false});
  EXPECT_EQ(run.planner.solve(), PlannerStatus::SampleLimit);
  EXPECT_EQ(run.planner.statistics().samples, 50'000u);
  EXPECT_TRUE(run.planner.path().empty());
  EXPECT_FALSE(run.planner.statistics().solved());
  EXPECT_GT(run.planner.statistics().sweeps, 1u) << "rho_a grows once a sweep fails";
  EXPECT_GT(run.planner.statistics().finalArmHalfSize, 0.001);
}

/// The same answer for every state and for every arm.
class FixedAnswers : public StateValidator {
 public:
  FixedAnswers(bool states, bool arms) : states_(states), arms_(arms) {}
  bool isValid(const Configuration&) override { return ++checks_, states_; }
  bool isArmValid(const Configuration&) override { return ++checks_, arms_; }
  std::size_t checkCount() const override { return checks_; }

 private:
  bool states_, arms_;
  std::size_t checks_ = 0;
};

// Algorithm 4: rho_a = k·rho_a per failed sweep (1, 2, 6, 24, 120, 720 × rho_a, capped at 1), or
// k·rho_a(1) with the linear reading; every sweep starts from the whole segment.
TEST(PmdRoadmapPlanner, ArmBoxesGrowSweepBySweep) {
  for (const ArmBoxGrowth growth : {ArmBoxGrowth::Factorial, ArmBoxGrowth::Linear}) {
    PlannerSettings parameters = toy::withSeed(3);
    parameters.rhoAGrowth = growth;
    parameters.maxSamples = 40000;
    FixedAnswers stateValidator(true, false);  // start and goal free, every arm draw in self-collision
    toy::WallMotionValidator motionValidator;
    const SynergyModel model = toy::synergyModel();
    PmdRoadmapPlanner planner(toy::space(), stateValidator, motionValidator,
                              makeHandSampler(HandSamplingMode::Synergy, toy::space(), &model), parameters);
    planner.setStartAndGoal(toy::start(), toy::goal());
    std::vector<double> halfSizes;
    std::vector<std::size_t> hypercubes;
    planner.setProgressCallback([&](const PlannerProgress& progress) {
      if (progress.sweep > halfSizes.size()) {
        EXPECT_EQ(progress.sweep, halfSizes.size() + 1);
        EXPECT_EQ(progress.hypercube, 0u) << "a sweep starts at c_ini's hypercube";
        EXPECT_EQ(progress.searchRange.low, 0.0);
        EXPECT_EQ(progress.searchRange.high, 1.0);
        halfSizes.push_back(progress.armHalfSize);
        hypercubes.push_back(progress.hypercubes);
      }
    });
    EXPECT_EQ(planner.solve(), PlannerStatus::SampleLimit);
    ASSERT_GE(halfSizes.size(), 8u);
    const std::vector<double> expected =
        growth == ArmBoxGrowth::Factorial ? std::vector<double>{0.001, 0.002, 0.006, 0.024, 0.12, 0.72, 1.0, 1.0}
                                          : std::vector<double>{0.001, 0.002, 0.003, 0.004, 0.005, 0.006, 0.007, 0.008};
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_NEAR(halfSizes[k], expected[k], 1e-15) << "sweep " << k + 1;
      // STEPS: the hypercube centres are at most rho_a apart along the 0.8-long arm segment.
      EXPECT_LE(0.8 / static_cast<double>(hypercubes[k] - 1), halfSizes[k]);
    }
    EXPECT_EQ(planner.statistics().finalArmHalfSize, halfSizes.back());
    EXPECT_EQ(planner.statistics().sweeps, halfSizes.size());
  }
}

/// Every motion free except into or out of the goal, which nothing reaches.
class GoalUnreachable : public MotionValidator {
 public:
  bool isValid(const Configuration& from, const Configuration& to) override {
    ++states_;
    return from != toy::goal() && to != toy::goal();
  }
  std::size_t statesChecked() const override { return states_; }

 private:
  std::size_t states_ = 0;
};

// Once c_ini's component reaches the goal's hypercube, the search range is that hypercube alone:
// a sweep then passes over it again (while it still adds nodes) until sweepVisits visits,
// rather than growing rho_a after one or two.
TEST(PmdRoadmapPlanner, ANarrowSearchRangeIsPassedOverAgainBeforeRhoGrows) {
  for (const std::size_t minimum : {std::size_t{1}, std::size_t{10}}) {
    PlannerSettings parameters = toy::withSeed(5);
    parameters.sweepVisits = minimum;
    parameters.maxSamples = 400;
    FixedAnswers stateValidator(true, true);
    GoalUnreachable motionValidator;
    const SynergyModel model = toy::synergyModel();
    PmdRoadmapPlanner planner(toy::space(), stateValidator, motionValidator,
                              makeHandSampler(HandSamplingMode::Synergy, toy::space(), &model), parameters);
    planner.setStartAndGoal(toy::start(), toy::goal());
    std::vector<std::size_t> visits;
    planner.setProgressCallback([&](const PlannerProgress& progress) {
      if (progress.sweep > visits.size()) visits.push_back(0);
      ++visits.back();
    });
    EXPECT_EQ(planner.solve(), PlannerStatus::SampleLimit);
    ASSERT_GE(visits.size(), 4u);
    // Sweep 1 visits c_ini's and c_goal's hypercubes, and the range is [1, 1] from then on.
    for (std::size_t k = 1; k + 1 < visits.size(); ++k)
      EXPECT_EQ(visits[k], minimum == 1 ? 2u : minimum) << "sweep " << k + 1;
  }
}

TEST(PmdRoadmapPlanner, StartEqualToGoalIsATwoPointPath) {
  ToyRun run(toy::withSeed(1));
  run.planner.setStartAndGoal(toy::start(), toy::start());
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  EXPECT_EQ(run.planner.path(), (std::vector<Configuration>{toy::start(), toy::start()}));
}

// The threshold bounds every edge: no roadmap edge is longer than factor · d(c_ini, c_goal),
// except the edges to a forced neighbour.
TEST(PmdRoadmapPlanner, EdgesRespectTheNeighbourThreshold) {
  for (const double factor : {0.5, 1.0, 3.0}) {
    PlannerSettings parameters = toy::withSeed(6);
    parameters.neighbourThreshold = factor;
    ToyRun run(parameters);
    run.planner.solve();
    const Roadmap& roadmap = run.planner.roadmap();
    const double threshold = factor * toy::space().distance(toy::start(), toy::goal());
    for (NodeIndex a = 0; a < roadmap.nodeCount(); ++a)
      for (const RoadmapEdge& edge : roadmap.edges(a)) {
        const NodeIndex b = edge.target;
        const bool forced = (a == 0 && roadmap.node(b).step == 0.0) || (b == 0 && roadmap.node(a).step == 0.0) ||
                            (a == 1 && roadmap.node(b).step == 1.0) || (b == 1 && roadmap.node(a).step == 1.0);
        if (!forced) {
          EXPECT_LE(edge.length, threshold) << "factor " << factor;
        }
      }
  }
}

TEST(PmdRoadmapPlanner, ClearDropsTheRoadmap) {
  ToyRun run(toy::withSeed(2));
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  run.planner.clear();
  EXPECT_EQ(run.planner.roadmap().nodeCount(), 0u);
  EXPECT_TRUE(run.planner.unsmoothedPath().empty());
}

}  // namespace
}  // namespace pmdplan
