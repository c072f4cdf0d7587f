// The lazy PMD planner (`pmd-lazy`) on the five built-in tasks: over several seeds every run
// solves, and its path passes the exact checker's validation at the planning tolerance (the
// closing phase of a grasp with the grasp rule); the same seed gives the same path. No timing:
// `pmdplan bench TASK --planners pmd,pmd-lazy,ompl:RRTConnect` prints the times.
#include <gtest/gtest.h>

#include <string>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {
namespace {

constexpr int kSeeds = 5;

class LazyPlannerOnTask : public ::testing::TestWithParam<std::string> {};

TaskPlanningResult planLazy(const Task& task, CollisionChecking& checking, const SynergyModel& model,
                            std::uint64_t seed) {
  TaskPlanningOptions options;
  options.algorithm = RoadmapAlgorithm::Lazy;
  options.parameters.seed = seed;
  options.parameters.timeLimit = 60.0;
  options.synergies = &model;
  return planTask(task, checking, options);
}

TEST_P(LazyPlannerOnTask, EverySeedSolvesWithAValidPath) {
  const Task task = loadTaskByName(GetParam());
  const SynergyModel model = loadSynergyModel(dataDirectory() / "synergies" / "sah_tx90_default.yaml");
  CollisionChecking checking(task, CheckerKind::Fast);
  SegmentChecker segments(checking.exact(), *task.robot, checking.tolerance());
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    const TaskPlanningResult result = planLazy(task, checking, model, seed);
    ASSERT_TRUE(result.statistics.solved()) << "seed " << seed << ": " << plannerStatusName(result.status);
    const PathValidation validation =
        validateTaskPath(checking.exact(), segments, task, result.path, result.closingFrom);
    EXPECT_TRUE(validation.valid) << "seed " << seed << ": "
                                  << (validation.problems.empty() ? "" : validation.problems.front());
    EXPECT_EQ(result.path.front(), task.start);
    EXPECT_EQ(result.path.back(), task.goal);
  }
}

TEST_P(LazyPlannerOnTask, TheSameSeedGivesTheSamePath) {
  const Task task = loadTaskByName(GetParam());
  const SynergyModel model = loadSynergyModel(dataDirectory() / "synergies" / "sah_tx90_default.yaml");
  CollisionChecking checking(task, CheckerKind::Fast);
  const TaskPlanningResult first = planLazy(task, checking, model, 7);
  const TaskPlanningResult second = planLazy(task, checking, model, 7);
  ASSERT_TRUE(first.statistics.solved());
  ASSERT_EQ(first.path.size(), second.path.size());
  for (std::size_t i = 0; i < first.path.size(); ++i)
    EXPECT_EQ(first.path[i], second.path[i]) << "point " << i << " differs: not bit for bit the same";
  EXPECT_EQ(first.statistics.samples, second.statistics.samples);
  EXPECT_EQ(first.statistics.motionChecks, second.statistics.motionChecks);
}

INSTANTIATE_TEST_SUITE_P(BuiltInTasks, LazyPlannerOnTask,
                         ::testing::Values("can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf",
                                           "t_in_clutter"));

}  // namespace
}  // namespace pmdplan
