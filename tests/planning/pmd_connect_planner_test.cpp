#include "pmdplan/planning/pmd_connect_planner.hpp"

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

/// A bidirectional planner with its validators, for one toy run.
struct ConnectToyRun {
  toy::WallStateValidator stateValidator;
  toy::WallMotionValidator motionValidator;
  PmdConnectPlanner planner;

  explicit ConnectToyRun(PlannerSettings parameters, toy::Wall wall = {}, const Configuration& start = toy::start(),
                         const Configuration& goal = toy::goal())
      : stateValidator(wall),
        motionValidator(wall),
        planner(toy::space(), stateValidator, motionValidator,
                std::make_unique<SynergyHandSampler>(toy::space(), toy::synergyModel()), parameters) {
    planner.setStartAndGoal(start, goal);
  }
};

// What every planner does (a valid path, repeatable runs, statuses, limits, errors) is the contract
// suite's (tests/bench/planner_contract_test.cpp); here is what is the bidirectional planner's own.

TEST(PmdConnectPlanner, EverySeedSolvesAndTheStatisticsCountTheLiveTrees) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    ConnectToyRun run(toy::withSeed(seed));
    ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved) << "seed " << seed;
    EXPECT_TRUE(toy::densePathIsFree(run.planner.path())) << "seed " << seed;
    EXPECT_TRUE(toy::densePathIsFree(run.planner.unsmoothedPath())) << "seed " << seed;

    const PlanningStatistics& stats = run.planner.statistics();
    EXPECT_EQ(stats.roadmapNodes, run.planner.tree(0).liveCount() + run.planner.tree(1).liveCount());
    EXPECT_EQ(stats.stateChecks, run.stateValidator.checkCount());
    EXPECT_EQ(stats.motionChecks, run.motionValidator.statesChecked());
    EXPECT_GT(stats.samples, 0u);
    for (const auto& [dimension, count] : stats.nodesByHandDimension) {
      EXPECT_GE(dimension, 2) << "hands from the thumb base and at least one PMD";
      EXPECT_LE(dimension, 4);
    }
  }
}

// Lazy: the motion checks settle only segments of candidate paths; every segment of the path the
// trees returned was certified.
TEST(PmdConnectPlanner, MotionChecksOnlyCandidatePaths) {
  ConnectToyRun run(toy::withSeed(3));
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  std::size_t checked = 0;
  std::size_t segments = 0;
  for (std::size_t which : {PmdConnectPlanner::kStartTree, PmdConnectPlanner::kGoalTree}) {
    const ConnectTree& tree = run.planner.tree(which);
    for (ConnectTree::Node n = 1; n < tree.size(); ++n) {
      if (!tree.isLive(n)) continue;
      ++segments;
      checked += tree.segmentChecked(n) ? 1 : 0;
    }
  }
  EXPECT_GE(checked, run.planner.unsmoothedPath().size() - 2) << "the path's segments, the meeting node's two sides";
  // The straight segment, the candidate paths' segments and the smoothing's shortcuts.
  EXPECT_LT(run.motionValidator.calls(), 1 + segments + run.planner.unsmoothedPath().size() * 2);
}

TEST(PmdConnectPlanner, AFreeStraightSegmentIsOneMotionCheckAndNoSample) {
  ConnectToyRun run(toy::withSeed(1), toy::Wall{}, toy::start(), toy::fromUnit({0.3, 0.5, 0.3, 0.9, 0.7, 0.5}));
  ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
  EXPECT_EQ(run.planner.path().size(), 2u);
  EXPECT_EQ(run.planner.statistics().samples, 0u);
  EXPECT_EQ(run.motionValidator.calls(), 1u);
}

TEST(PmdConnectPlanner, TheArmRegionGrowsOnlyWhileTheTreesStayApart) {
  PlannerSettings parameters = toy::withSeed(2);
  parameters.maxSamples = 500;
  ConnectToyRun closed(parameters, toy::Wall{false});
  EXPECT_EQ(closed.planner.solve(), PlannerStatus::SampleLimit);
  EXPECT_TRUE(closed.planner.path().empty());
  EXPECT_GE(closed.planner.statistics().samples, 500u);
  EXPECT_EQ(closed.planner.statistics().finalArmHalfSize, 1.0) << "grown to the whole arm box";

  // Without growth every sample's box is rho_a: the passage is still found (it lies on the segment).
  parameters = toy::withSeed(2);
  parameters.connect.armGrowth = 1.0;
  ConnectToyRun fixed(parameters);
  ASSERT_EQ(fixed.planner.solve(), PlannerStatus::Solved);
  EXPECT_EQ(fixed.planner.statistics().finalArmHalfSize, parameters.rhoA);
  for (const Configuration& q : fixed.planner.unsmoothedPath()) {
    const Eigen::VectorXd u = toy::space().normalise(q);
    EXPECT_NEAR(u[1], 0.5, parameters.rhoA + 1e-12) << "the elbow stays in the box around the segment";
  }
}

TEST(PmdConnectPlanner, ShortStepsProbesOffAndEverySequenceStillSolve) {
  for (const auto& change : std::vector<void (*)(PlannerSettings&)>{
           [](PlannerSettings& p) { p.connect.range = 0.1; },
           [](PlannerSettings& p) { p.connect.range = std::numeric_limits<double>::infinity(); },
           [](PlannerSettings& p) { p.connect.probes = 0; },
           [](PlannerSettings& p) { p.sequence = SampleSequence::Halton; },
           [](PlannerSettings& p) { p.sequence = SampleSequence::Sdk; }}) {
    PlannerSettings parameters = toy::withSeed(5);
    change(parameters);
    ConnectToyRun run(parameters);
    ASSERT_EQ(run.planner.solve(), PlannerStatus::Solved);
    EXPECT_TRUE(toy::densePathIsFree(run.planner.path()));
    EXPECT_TRUE(toy::densePathIsFree(run.planner.unsmoothedPath()));
  }
}

TEST(PmdConnectPlanner, BadSettingsAreInputErrorsNamingTheFlag) {
  const auto expectRejected = [](const std::string& flag, auto change) {
    PlannerSettings parameters = toy::withSeed(1);
    change(parameters.connect);
    ConnectToyRun run(parameters);
    try {
      run.planner.solve();
      ADD_FAILURE() << flag << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), flag);
      EXPECT_FALSE(e.message().empty());
    }
  };
  expectRejected("connect-range", [](PmdConnectSettings& s) { s.range = 0.0; });
  expectRejected("connect-range", [](PmdConnectSettings& s) { s.range = std::nan(""); });
  expectRejected("connect-round", [](PmdConnectSettings& s) { s.round = 0; });
  expectRejected("connect-arm-growth", [](PmdConnectSettings& s) { s.armGrowth = 0.5; });
  expectRejected("connect-arm-growth", [](PmdConnectSettings& s) { s.armGrowth = INFINITY; });
  expectRejected("connect-probes", [](PmdConnectSettings& s) { s.probes = 65; });
}

}  // namespace
}  // namespace pmdplan
