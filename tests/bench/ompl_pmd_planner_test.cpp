#include "pmdplan/bench/ompl_pmd_planner.hpp"

#include <gtest/gtest.h>
#include <ompl/base/PlannerData.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include <filesystem>
#include <fstream>

#include "pmdplan/bench/ompl_task_space.hpp"
#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

namespace pmdplan {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

/// can_on_table as an OMPL problem in the normalised joint box, with our fast checks.
struct CanOnTable {
  Task task = loadTaskByName("can_on_table");
  PlanningSpace space = planningSpaceFromRobot(*task.robot);
  CollisionChecking checking{task, CheckerKind::Fast};
  OmplTaskSpace omplSpace = makeOmplTaskSpace(space, checking.states(), checking.motions());
  std::shared_ptr<const SynergyModel> synergies = std::make_shared<const SynergyModel>(
      loadSynergyModel(std::string(PMDPLAN_TEST_DATA_DIR) + "/synergies/sah_tx90_default.yaml"));

  og::SimpleSetup setup() const {
    og::SimpleSetup ss(omplSpace.spaceInformation);
    ob::ScopedState<> start(omplSpace.spaceInformation), goal(omplSpace.spaceInformation);
    setOmplState(space, task.start, start.get());
    setOmplState(space, task.goal, goal.get());
    ss.setStartAndGoalStates(start, goal);
    return ss;
  }
  std::vector<Configuration> configurations(const og::PathGeometric& path) const {
    std::vector<Configuration> points;
    for (std::size_t i = 0; i < path.getStateCount(); ++i)
      points.push_back(configurationOfOmplState(space, path.getState(i)));
    return points;
  }
};

TEST(OmplPmdPlanner, SettingsAreOmplParameters) {
  CanOnTable p;
  OmplPmdPlanner planner(p.omplSpace.spaceInformation, p.space, HandSamplingMode::Synergy, p.synergies);
  EXPECT_EQ(planner.getName(), "PMD");
  for (const char* name : {"rho_a", "rho_a_growth", "neighbours", "neighbour_threshold", "arm_trials", "hand_trials",
                           "sweep_visits", "max_samples", "smooth", "seed"})
    EXPECT_TRUE(planner.params().hasParam(name)) << name;
  EXPECT_TRUE(planner.params().setParam("neighbours", "5"));
  EXPECT_TRUE(planner.params().setParam("arm_trials", "7"));
  EXPECT_TRUE(planner.params().setParam("rho_a_growth", "linear"));
  EXPECT_EQ(planner.parameters().neighbours, 5u);
  EXPECT_EQ(planner.parameters().armTrials, 7);
  EXPECT_EQ(planner.parameters().rhoAGrowth, ArmBoxGrowth::Linear);
  std::string value;
  ASSERT_TRUE(planner.params().getParam("arm_trials", value));
  EXPECT_EQ(value, "7");
  EXPECT_EQ(OmplPmdPlanner(p.omplSpace.spaceInformation, p.space, HandSamplingMode::FullSpace, nullptr)
                .parameters()
                .armTrials,
            20);
}

TEST(OmplPmdPlanner, SolvesThroughSimpleSetupWithAValidPathAndExportsItsRoadmap) {
  CanOnTable p;
  og::SimpleSetup ss = p.setup();
  auto planner =
      std::make_shared<OmplPmdPlanner>(p.omplSpace.spaceInformation, p.space, HandSamplingMode::Synergy, p.synergies);
  planner->params().setParam("seed", "3");
  ss.setPlanner(planner);
  ASSERT_EQ(ss.solve(30.0), ob::PlannerStatus::EXACT_SOLUTION);
  const auto points = p.configurations(ss.getSolutionPath());
  ASSERT_GE(points.size(), 2u);
  EXPECT_LT(p.space.distance(points.front(), p.task.start), 1e-9);
  EXPECT_LT(p.space.distance(points.back(), p.task.goal), 1e-9);
  ExactCollisionChecker exact(p.task);
  SegmentChecker segments(exact, *p.task.robot);
  // The ends went through the normalised box and back: equal up to rounding.
  std::vector<Configuration> path = points;
  path.front() = p.task.start;
  path.back() = p.task.goal;
  const PathValidation validation = validatePath(exact, segments, path, p.task.start, p.task.goal);
  EXPECT_TRUE(validation.valid) << (validation.problems.empty() ? "" : validation.problems.front());

  ob::PlannerData data(p.omplSpace.spaceInformation);
  planner->getPlannerData(data);
  EXPECT_EQ(data.numVertices(), planner->statistics().roadmapNodes);
  EXPECT_EQ(data.numEdges(), 2 * planner->statistics().roadmapEdges);  // both directions
  EXPECT_EQ(data.numStartVertices(), 1u);
  EXPECT_EQ(data.numGoalVertices(), 1u);
  EXPECT_EQ(data.properties.at("samples INTEGER"), std::to_string(planner->statistics().samples));
}

TEST(OmplPmdPlanner, RunsInOmplsBenchmarkBesideRRTConnect) {
  CanOnTable p;
  og::SimpleSetup ss = p.setup();
  ompl::tools::Benchmark benchmark(ss, "can_on_table");
  benchmark.addPlanner(
      std::make_shared<OmplPmdPlanner>(p.omplSpace.spaceInformation, p.space, HandSamplingMode::Synergy, p.synergies));
  benchmark.addPlanner(std::make_shared<og::RRTConnect>(p.omplSpace.spaceInformation));
  std::size_t validPmdPaths = 0;
  std::vector<double> pmdPathLengths;
  benchmark.setPostRunEvent([&](const ob::PlannerPtr& planner, ompl::tools::Benchmark::RunProperties&) {
    if (planner->getName() != "PMD" || !planner->getProblemDefinition()->hasExactSolution()) return;
    const auto& solution = *planner->getProblemDefinition()->getSolutionPath()->as<og::PathGeometric>();
    pmdPathLengths.push_back(solution.length());
    auto points = p.configurations(solution);
    points.front() = p.task.start;
    points.back() = p.task.goal;
    ExactCollisionChecker exact(p.task);
    SegmentChecker segments(exact, *p.task.robot);
    validPmdPaths += validatePath(exact, segments, points, p.task.start, p.task.goal).valid;
  });
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::tools::Benchmark::Request request(30.0, 4096.0, 3, 0.05, false, false, false);
  benchmark.benchmark(request);

  const auto& experiment = benchmark.getRecordedExperimentData();
  ASSERT_EQ(experiment.planners.size(), 2u);
  const auto& pmd = experiment.planners[0];
  EXPECT_EQ(pmd.name, "geometric_PMD");
  ASSERT_EQ(pmd.runs.size(), 3u);
  for (const auto& run : pmd.runs) {
    EXPECT_EQ(run.at("solved BOOLEAN"), "1");
    EXPECT_GT(std::stoul(run.at("graph states INTEGER")), 2u);
    EXPECT_GT(std::stoul(run.at("samples INTEGER")), 0u);
  }
  EXPECT_EQ(validPmdPaths, 3u);
  // seed 0: each run draws its own seed, so the three runs are not one run repeated (their
  // smoothed paths differ in length).
  ASSERT_EQ(pmdPathLengths.size(), 3u);
  EXPECT_FALSE(pmdPathLengths[0] == pmdPathLengths[1] && pmdPathLengths[1] == pmdPathLengths[2]);
  // The settings are recorded as the planner's parameters in OMPL's log.
  const std::filesystem::path log = std::filesystem::temp_directory_path() / "pmdplan_ompl_pmd_planner_test.log";
  ASSERT_TRUE(benchmark.saveResultsToFile(log.c_str()));
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(log);
  EXPECT_NE(text.find("geometric_PMD"), std::string::npos);
  EXPECT_NE(text.find("neighbours = 10"), std::string::npos);
}

}  // namespace
}  // namespace pmdplan
