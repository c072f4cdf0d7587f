// Our planners (`pmd-lazy`, `pmd-connect`) on the built-in tasks of both robots: over several seeds
// every run solves, and its path passes the exact checker's validation at the planning tolerance
// (the closing phase of a grasp with the grasp rule); the same seed gives the same path. No timing:
// `pmdplan bench TASK --planners pmd,pmd-lazy,pmd-connect,ompl:RRTConnect` prints the times.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <tuple>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"
#include "support/sanitizer_build.hpp"

namespace pmdplan {
namespace {

// Fewer seeds in the sanitizer build (tests/support/sanitizer_build.hpp): there each plan is slowed
// several times, and the Release suite covers the seeds.
constexpr int kSeeds = test::trials(5, 1);

using TaskAndPlanner = std::tuple<std::string, std::string>;  // task, planner

class OurPlannerOnTask : public ::testing::TestWithParam<TaskAndPlanner> {
 protected:
  void SetUp() override {
    task_ = loadTaskByName(std::get<0>(GetParam()));
    model_ = loadSynergyModel(shippedSynergyModelPath(task_.robot->name()));
    checking_ = std::make_unique<CollisionChecking>(task_, CheckerKind::Fast);
  }

  TaskPlanningResult plan(std::uint64_t seed) {
    TaskPlanningSettings options;
    options.planner = &ourPlanners().at(std::get<1>(GetParam()));
    options.parameters.seed = seed;
    options.parameters.timeLimit = 60.0;
    options.synergies = &model_;
    return planTask(task_, *checking_, options);
  }

  Task task_;
  SynergyModel model_;
  std::unique_ptr<CollisionChecking> checking_;
};

TEST_P(OurPlannerOnTask, EverySeedSolvesWithAValidPath) {
  SegmentChecker segments(checking_->exact(), *task_.robot, checking_->tolerance());
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const TaskPlanningResult result = plan(seed);
    ASSERT_TRUE(result.statistics.solved()) << "seed " << seed << ": " << plannerStatusName(result.status);
    const PathValidation validation =
        GraspRule(task_).validatePath(checking_->exact(), segments, result.path, PathPhases{result.closingFrom});
    EXPECT_TRUE(validation.valid) << "seed " << seed << ": "
                                  << (validation.problems.empty() ? "" : validation.problems.front());
    EXPECT_EQ(result.path.front(), task_.start);
    EXPECT_EQ(result.path.back(), task_.goal);
  }
}

TEST_P(OurPlannerOnTask, TheSameSeedGivesTheSamePath) {
  const TaskPlanningResult first = plan(7);
  const TaskPlanningResult second = plan(7);
  ASSERT_TRUE(first.statistics.solved());
  ASSERT_EQ(first.path.size(), second.path.size());
  for (std::size_t i = 0; i < first.path.size(); ++i)
    EXPECT_EQ(first.path[i], second.path[i]) << "point " << i << " differs: not bit for bit the same";
  EXPECT_EQ(first.statistics.samples, second.statistics.samples);
  EXPECT_EQ(first.statistics.motionChecks, second.statistics.motionChecks);
}

std::string testName(const ::testing::TestParamInfo<TaskAndPlanner>& info) {
  return std::get<0>(info.param) + (std::get<1>(info.param) == "pmd-lazy" ? "_lazy" : "_connect");
}

INSTANTIATE_TEST_SUITE_P(BuiltInTasks, OurPlannerOnTask,
                         ::testing::Combine(::testing::Values("can_on_table", "cans_on_desk", "can_in_box",
                                                              "cans_in_shelf", "t_in_clutter", "allegro_can_on_table"),
                                            ::testing::Values("pmd-lazy", "pmd-connect")),
                         testName);

}  // namespace
}  // namespace pmdplan
