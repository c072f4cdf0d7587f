#include "pmdplan/planning/lazy_pmd_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "planning/toy_problem.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/synergy_hand_sampler.hpp"

namespace pmdplan {
namespace {

/// A lazy planner with its validators, for one toy run.
struct LazyToyRun {
  toy::WallStateValidator stateValidator;
  toy::WallMotionValidator motionValidator;
  LazyPmdPlanner planner;

  explicit LazyToyRun(PlannerSettings parameters, toy::Wall wall = {}, const Configuration& start = toy::start(),
                      const Configuration& goal = toy::goal())
      : stateValidator(wall),
        motionValidator(wall),
        planner(toy::space(), stateValidator, motionValidator, makeSampler(), parameters) {
    planner.setStartAndGoal(start, goal);
  }

  static std::unique_ptr<HandSampler> makeSampler() {
    const SynergyModel model = toy::synergyModel();
    return std::make_unique<SynergyHandSampler>(toy::space(), model);
  }
};

// What every planner does (a valid path, repeatable runs, statuses, limits, errors) is the contract
// suite's (tests/bench/planner_contract_test.cpp); here is what is the lazy planner's own.

TEST(LazyPmdPlanner, EverySeedSolvesAndTheStatisticsCountTheLazyRoadmap) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    LazyToyRun run(toy::withSeed(seed));
    ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved) << "seed " << seed;
    EXPECT_TRUE(toy::densePathIsFree(run.planner.path())) << "seed " << seed;
    EXPECT_TRUE(toy::densePathIsFree(run.planner.unsmoothedPath())) << "seed " << seed;

    const PlanningStatistics& stats = run.planner.statistics();
    EXPECT_EQ(stats.roadmapNodes, run.planner.roadmap().nodeCount());
    EXPECT_EQ(stats.stateChecks, run.stateValidator.checkCount());
    EXPECT_EQ(stats.motionChecks, run.motionValidator.statesChecked());
    std::size_t byDimension = 0;
    for (const auto& [dimension, count] : stats.nodesByHandDimension) {
      EXPECT_GE(dimension, 2) << "hands from the thumb base and at least one PMD";
      EXPECT_LE(dimension, 4);
      byDimension += count;
    }
    EXPECT_EQ(byDimension, stats.roadmapNodes - 2);
  }
}

// Lazy: far fewer motion checks than edges (only candidate paths' edges are checked).
TEST(LazyPmdPlanner, ChecksOnlyTheEdgesOfCandidatePaths) {
  LazyToyRun run(toy::withSeed(3));
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  std::size_t checked = 0;
  std::size_t free = 0;
  for (EdgeIndex e = 0; e < run.planner.roadmap().edgeCount(); ++e) {
    const LazyEdge& edge = run.planner.roadmap().edge(e);
    checked += edge.status != LazyEdgeStatus::Unknown ? 1 : 0;
    free += edge.status == LazyEdgeStatus::Free ? 1 : 0;
  }
  EXPECT_GE(free, run.planner.unsmoothedPath().size() - 1) << "every edge of the returned path was certified";
  EXPECT_LT(checked, run.planner.roadmap().edgeCount());
  EXPECT_LE(run.motionValidator.calls(), free + run.planner.roadmap().edgeCount())
      << "a motion check settles an edge once";
}

TEST(LazyPmdPlanner, AFreeStraightSegmentIsOneMotionCheckAndNoSample) {
  LazyToyRun run(toy::withSeed(1), toy::Wall{}, toy::start(), toy::fromUnit({0.3, 0.5, 0.3, 0.9, 0.7, 0.5}));
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  EXPECT_EQ(run.planner.path().size(), 2u);
  EXPECT_EQ(run.planner.statistics().samples, 0u);
  EXPECT_EQ(run.motionValidator.calls(), 1u);
}

TEST(LazyPmdPlanner, AClosedWallStopsAtTheSampleLimit) {
  PlannerSettings parameters = toy::withSeed(2);
  parameters.maxSamples = 500;
  LazyToyRun run(parameters, toy::Wall{false});
  EXPECT_EQ(run.planner.solve(), PlannerStatus::SampleLimit);
  EXPECT_TRUE(run.planner.path().empty());
  EXPECT_GE(run.planner.statistics().samples, 500u);
  EXPECT_EQ(run.planner.statistics().finalArmHalfSize, 1.0) << "rho_a grew to the whole arm box";
}

TEST(LazyPmdPlanner, BadSettingsAreInputErrorsNamingTheFlag) {
  const auto expectRejected = [](const std::string& flag, auto change) {
    PlannerSettings parameters = toy::withSeed(1);
    change(parameters.lazy);
    LazyToyRun run(parameters);
    try {
      run.planner.solve();
      ADD_FAILURE() << flag << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), flag);
      EXPECT_FALSE(e.message().empty());
    }
  };
  expectRejected("lazy-batch", [](LazyPmdSettings& s) { s.batch = 1'000'001; });
  expectRejected("lazy-neighbours", [](LazyPmdSettings& s) { s.neighbours = 0; });
  expectRejected("lazy-radius", [](LazyPmdSettings& s) { s.radius = 0.0; });
  expectRejected("lazy-radius", [](LazyPmdSettings& s) { s.radius = std::numeric_limits<double>::infinity(); });
  expectRejected("lazy-probes", [](LazyPmdSettings& s) { s.probes = 65; });
  expectRejected("lazy-arm-growth", [](LazyPmdSettings& s) { s.armGrowth = 0.5; });
  expectRejected("lazy-arm-growth", [](LazyPmdSettings& s) { s.armGrowth = std::nan(""); });
}

TEST(LazyPmdPlanner, WithoutProbesItStillSolves) {
  PlannerSettings parameters = toy::withSeed(4);
  parameters.lazy.probes = 0;
  LazyToyRun run(parameters);
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  EXPECT_TRUE(toy::densePathIsFree(run.planner.path()));
}

}  // namespace
}  // namespace pmdplan
