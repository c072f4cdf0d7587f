// Grasps as goals (docs/grasp_goals.md): a goal whose hand sinks up to 2 mm into its target, as
// grasp planners give them, plans as an approach to a pre-grasp and a closing with hand-target
// contact allowed; a goal touching anything else is refused with the pair named; validation
// applies the same rule phase by phase (GraspRule, grasp_rule.hpp).
#include <gtest/gtest.h>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "support/grasp_task.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

constexpr double kDepth = 0.0015;  // 1.5 mm into the can

bool names(const std::vector<std::string>& problems, const std::string& a, const std::string& b) {
  for (const auto& p : problems)
    if (p.find(a) != std::string::npos && p.find(b) != std::string::npos) return true;
  return false;
}

TEST(GraspGoal, TheRuleAllowsHandLinksWithTheTargetOnly) {
  const Task task = test::graspingTask(kDepth);
  const GraspContactRule rule(task);
  EXPECT_EQ(rule.target(), "goal_can");
  EXPECT_TRUE(rule.allows({"palm", "goal_can"}));
  EXPECT_TRUE(rule.allows({"index_proximal_link", "goal_can"}));
  EXPECT_TRUE(rule.allows({"thumb_distal_link", "goal_can"}));
  EXPECT_FALSE(rule.allows({"tx90_link_6", "goal_can"})) << "the flange carries the hand but is the arm's";
  EXPECT_FALSE(rule.allows({"index_proximal_link", "obstacle_can"}));
  EXPECT_FALSE(rule.allows({"index_proximal_link", "middle_proximal_link"}));
}

TEST(GraspGoal, CheckMeasuresThePenetrationDepthAndTheClearance) {
  const Task published = loadTaskByName("can_on_table");
  ExactCollisionChecker free(published);
  const auto clearance = free.clearance(published.goal, "goal_can");
  ASSERT_TRUE(clearance);
  EXPECT_GT(clearance->metres, 0.0);
  const Task task = test::graspingTask(kDepth);
  ExactCollisionChecker checker(task);
  const auto depth = checker.clearance(task.goal, "goal_can");
  ASSERT_TRUE(depth);
  EXPECT_NEAR(depth->metres, -kDepth, 2e-4) << depth->pair.first;
  EXPECT_EQ(depth->pair.second, "goal_can");
}

TEST(GraspGoal, AGoalTouchingOnlyTheTargetIsAGraspAndAnyOtherContactIsRefused) {
  const Task published = loadTaskByName("can_on_table");
  ExactCollisionChecker publishedChecker(published);
  EXPECT_EQ(GraspRule(published).judgeGoal(publishedChecker).contact, GoalContact::Free);

  const Task task = test::graspingTask(kDepth);
  ExactCollisionChecker checker(task);
  const auto grasp = GraspRule(task).judgeGoal(checker);
  EXPECT_EQ(grasp.contact, GoalContact::GraspsTarget);
  EXPECT_FALSE(grasp.refusal);
  ASSERT_FALSE(grasp.pairs.free());
  for (const auto& [link, obstacle] : grasp.pairs.pairs) EXPECT_EQ(obstacle, "goal_can") << link;

  Task otherTarget = task;
  otherTarget.target = "obstacle_can";
  ExactCollisionChecker otherChecker(otherTarget);
  const auto refused = GraspRule(otherTarget).judgeGoal(otherChecker);
  EXPECT_EQ(refused.contact, GoalContact::Refused);
  ASSERT_TRUE(refused.refusal);
  EXPECT_EQ(refused.refusal->field, "goal");
  EXPECT_EQ(refused.refusal->pairs.pairs, grasp.pairs.pairs) << "the hand-goal_can pairs are what the rule forbids";
  test::expectInputError([&] { graspApproach(otherTarget, otherChecker, 0.001); }, otherTarget.file.string(), "goal",
                         grasp.pairs.pairs.front().first + " - goal_can");

  // Without a target any contact is refused, naming every pair.
  Task noTarget = task;
  noTarget.target.reset();
  ExactCollisionChecker noTargetChecker(noTarget);
  const auto untargeted = GraspRule(noTarget).judgeGoal(noTargetChecker);
  EXPECT_EQ(untargeted.contact, GoalContact::Refused);
  ASSERT_TRUE(untargeted.refusal);
  EXPECT_NE(untargeted.refusal->reason.find("names none"), std::string::npos) << untargeted.refusal->reason;
}

TEST(GraspGoal, TheRuleSortsAStatesPairsIntoCollisionsAndGraspContactByPhase) {
  Task task = test::graspingTask(kDepth);
  ExactCollisionChecker checker(task);
  const GraspRule rule(task);
  const auto approach = rule.judgeState(checker, task.goal, PathPhase::Approach);
  EXPECT_FALSE(approach.free()) << "while approaching, touching the target is a collision";
  EXPECT_TRUE(approach.allowed.free());
  const auto closing = rule.judgeState(checker, task.goal, PathPhase::Closing);
  EXPECT_TRUE(closing.free());
  EXPECT_EQ(closing.allowed.pairs, approach.collisions.pairs) << "the same pairs, allowed as grasp contact";
  EXPECT_TRUE(rule.counts({"index_distal_link", "goal_can"}, PathPhase::Approach));
  EXPECT_FALSE(rule.counts({"index_distal_link", "goal_can"}, PathPhase::Closing));
  EXPECT_TRUE(rule.counts({"tx90_link_6", "goal_can"}, PathPhase::Closing));
  EXPECT_TRUE(rule.counts({"index_distal_link", "table"}, PathPhase::Closing));

  task.target.reset();
  ExactCollisionChecker untargeted(task);
  EXPECT_FALSE(GraspRule(task).judgeState(untargeted, task.goal, PathPhase::Closing).free())
      << "without a target nothing is grasp contact";
}

TEST(GraspGoal, PhasesSplitAPathAtItsPregrasp) {
  const PathPhases phases{2};
  EXPECT_EQ(phases.segment(1), PathPhase::Approach);
  EXPECT_EQ(phases.segment(2), PathPhase::Closing);
  EXPECT_EQ(phases.point(2), PathPhase::Approach) << "the pre-grasp ends the approach: every pair counts there";
  EXPECT_EQ(phases.point(3), PathPhase::Closing);
  EXPECT_EQ(PathPhases{}.segment(5), PathPhase::Approach);
}

TEST(GraspGoal, TheDerivedPregraspClearsTheTargetAndClosesOntoTheGoal) {
  const Task task = test::graspingTask(kDepth);
  ExactCollisionChecker checker(task);
  const GraspSettings settings;
  const auto approach = graspApproach(task, checker, 0.001, settings);
  ASSERT_TRUE(approach);
  EXPECT_TRUE(approach->derived);
  EXPECT_GT(approach->opening, 0.0);
  EXPECT_GE(approach->clearance, settings.clearance);
  EXPECT_TRUE(checker.check(approach->pregrasp).free());
  for (int i : task.robot->group("arm")) EXPECT_EQ(approach->pregrasp[i], task.goal[i]) << "only the hand opens";

  const Task published = loadTaskByName("can_on_table");
  ExactCollisionChecker publishedChecker(published);
  EXPECT_FALSE(graspApproach(published, publishedChecker, 0.001)) << "a free goal needs no pre-grasp";
}

TEST(GraspGoal, AGivenPregraspThatTouchesTheTargetIsRefused) {
  Task task = test::graspingTask(kDepth);
  task.pregrasp = task.goal;
  ExactCollisionChecker checker(task);
  test::expectInputError([&] { graspApproach(task, checker, 0.001); }, task.file.string(), "pregrasp", "goal_can");
}

class GraspPlanning : public ::testing::Test {
 protected:
  GraspPlanning()
      : task_(test::graspingTask(kDepth)),
        checking_(task_, CheckerKind::Fast),
        segments_(checking_.exact(), *task_.robot),
        synergies_(loadSynergyModel(dataDirectory() / "synergies" / "sah_tx90_default.yaml")) {
    TaskPlanningSettings options;
    options.synergies = &synergies_;
    options.parameters.seed = 1;
    result_ = planTask(task_, checking_, options);
  }
  Task task_;
  CollisionChecking checking_;
  SegmentChecker segments_;
  SynergyModel synergies_;
  TaskPlanningResult result_;
};

TEST_F(GraspPlanning, PlansAnApproachThenTheClosingAndValidates) {
  ASSERT_TRUE(result_.statistics.solved());
  ASSERT_TRUE(result_.closingFrom);
  ASSERT_TRUE(result_.grasp);
  const std::size_t k = *result_.closingFrom;
  EXPECT_EQ(k + 2, result_.path.size()) << "one closing segment";
  EXPECT_EQ(result_.path[k], result_.grasp->pregrasp);
  EXPECT_EQ(result_.path.back(), task_.goal);
  EXPECT_EQ(result_.statistics.pathNodes, result_.path.size());
  const auto validation =
      GraspRule(task_).validatePath(checking_.exact(), segments_, result_.path, PathPhases{result_.closingFrom});
  EXPECT_TRUE(validation.valid) << (validation.problems.empty() ? "" : validation.problems.front());
  // Without its phases the same path touches the target: the rule is what makes it valid.
  const auto unmarked = GraspRule(task_).validatePath(checking_.exact(), segments_, result_.path, PathPhases{});
  EXPECT_FALSE(unmarked.valid);
  EXPECT_TRUE(names(unmarked.problems, "goal_can", "segment"));
}

TEST_F(GraspPlanning, ValidationRejectsAnApproachThatTouchesTheTarget) {
  ASSERT_TRUE(result_.closingFrom);
  // Approach: the planned one, on to the goal and back to the pre-grasp; closing as planned.
  std::vector<Configuration> path = result_.path;
  const Configuration pregrasp = path[*result_.closingFrom];
  path.push_back(pregrasp);
  path.push_back(task_.goal);
  const auto validation =
      GraspRule(task_).validatePath(checking_.exact(), segments_, path, PathPhases{path.size() - 2});
  EXPECT_FALSE(validation.valid);
  EXPECT_TRUE(names(validation.problems, "approach", "goal_can")) << validation.problems.front();
}

TEST_F(GraspPlanning, ValidationRejectsAClosingThatTouchesAnotherObstacle) {
  ASSERT_TRUE(result_.closingFrom);
  // A small ball where the index fingertip passes halfway through the closing.
  const Configuration middle = 0.5 * (result_.path[*result_.closingFrom] + task_.goal);
  const auto poses = checking_.exact().kinematics().linkPoses(middle);
  Task blocked = task_;
  blocked.obstacles.push_back(
      {"stray_ball", SphereShape{0.003},
       Eigen::Isometry3d(Eigen::Translation3d(poses[task_.robot->linkIndex("index_distal_link")].translation()))});
  ExactCollisionChecker checker(blocked);
  const SegmentChecker segments(checker, *blocked.robot);
  const auto validation =
      GraspRule(blocked).validatePath(checker, segments, result_.path, PathPhases{result_.closingFrom});
  EXPECT_FALSE(validation.valid);
  EXPECT_TRUE(names(validation.problems, "closing", "stray_ball")) << validation.problems.front();
  EXPECT_FALSE(names(validation.problems, "closing", "goal_can")) << "the target itself is allowed while closing";
}

TEST(GraspGoal, AClosingPhaseNeedsATarget) {
  Task task = test::graspingTask(kDepth);
  task.target.reset();
  ExactCollisionChecker checker(task);
  const SegmentChecker segments(checker, *task.robot);
  const auto validation =
      GraspRule(task).validatePath(checker, segments, {task.start, task.start, task.goal}, PathPhases{1});
  EXPECT_FALSE(validation.valid);
  EXPECT_TRUE(names(validation.problems, "closing phase", "no target"));
}

}  // namespace
}  // namespace pmdplan
