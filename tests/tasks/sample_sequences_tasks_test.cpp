// Both PMD planners with the Halton and the SDK sequence (`--sequence`) on an easy and a hard
// built-in task: every seed solves with a path the exact checker validates, and the same seed
// gives the same path, bit for bit. No timing: planning_bench compares the sequences' times.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"
#include "support/sanitizer_build.hpp"

namespace pmdplan {
namespace {

constexpr int kSequenceSeeds = test::trials(3, 1);  // one seed in the sanitizer build

using Case = std::tuple<std::string, std::string, SampleSequence>;  // task, planner, sequence
class SequenceOnTask : public ::testing::TestWithParam<Case> {};

TaskPlanningResult plan(const Task& task, CollisionChecking& checking, const SynergyModel& model, std::uint64_t seed) {
  TaskPlanningSettings options;
  options.planner = &ourPlanners().at(std::get<1>(SequenceOnTask::GetParam()));
  options.parameters.sequence = std::get<2>(SequenceOnTask::GetParam());
  options.parameters.seed = seed;
  options.parameters.timeLimit = 60.0;
  options.synergies = &model;
  return planTask(task, checking, options);
}

TEST_P(SequenceOnTask, EverySeedSolvesWithAValidPathAndRepeatsItself) {
  const Task task = loadTaskByName(std::get<0>(GetParam()));
  const SynergyModel model = loadSynergyModel(dataDirectory() / "synergies" / "sah_tx90_default.yaml");
  CollisionChecking checking(task, CheckerKind::Fast);
  SegmentChecker segments(checking.exact(), *task.robot, checking.tolerance());
  for (std::uint64_t seed = 1; seed <= kSequenceSeeds; ++seed) {
    const TaskPlanningResult result = plan(task, checking, model, seed);
    ASSERT_TRUE(result.statistics.solved()) << "seed " << seed << ": " << plannerStatusName(result.status);
    const PathValidation validation =
        GraspRule(task).validatePath(checking.exact(), segments, result.path, PathPhases{result.closingFrom});
    EXPECT_TRUE(validation.valid) << "seed " << seed << ": "
                                  << (validation.problems.empty() ? "" : validation.problems.front());
    const TaskPlanningResult again = plan(task, checking, model, seed);
    ASSERT_EQ(again.path.size(), result.path.size()) << "seed " << seed;
    for (std::size_t i = 0; i < result.path.size(); ++i) EXPECT_EQ(again.path[i], result.path[i]) << "point " << i;
    EXPECT_EQ(again.statistics.samples, result.statistics.samples);
  }
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  return std::get<0>(info.param) + "_" + (std::get<1>(info.param) == "pmd-lazy" ? "lazy" : "pmd") + "_" +
         sampleSequenceName(std::get<2>(info.param));
}

INSTANTIATE_TEST_SUITE_P(HaltonAndSdk, SequenceOnTask,
                         ::testing::Combine(::testing::Values("can_on_table", "can_in_box"),
                                            ::testing::Values("pmd", "pmd-lazy"),
                                            ::testing::Values(SampleSequence::Halton, SampleSequence::Sdk)),
                         caseName);

}  // namespace
}  // namespace pmdplan
