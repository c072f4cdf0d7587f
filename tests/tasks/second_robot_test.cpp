// The second built-in robot, panda_allegro (docs/robot_model.md, "The second robot: panda_allegro"):
// its URDF is the generator's output byte for byte, the model is the Panda's 7 arm joints and the
// Allegro Hand's 16 with the published kinematics and positive flexion, the shipped synergy model
// fits its hand, and its task allegro_can_on_table needs planning and is solved by pmd over seeds
// 1..5 with paths that validate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/collision/exact_collision_checker.hpp"
#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/model/forward_kinematics.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/hand_fit.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"
#include "support/run_cli.hpp"
#include "support/sanitizer_build.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

const std::filesystem::path kData = PMDPLAN_TEST_DATA_DIR;
const std::filesystem::path kSourceDir = kData.parent_path();
constexpr const char* kTask = "allegro_can_on_table";

const std::vector<std::string> kArmJoints = {"panda_joint1", "panda_joint2", "panda_joint3", "panda_joint4",
                                             "panda_joint5", "panda_joint6", "panda_joint7"};
const std::vector<std::string> kHandJoints = {"index_abduction",  "index_proximal",  "index_medium",   "index_distal",
                                              "middle_abduction", "middle_proximal", "middle_medium",  "middle_distal",
                                              "ring_abduction",   "ring_proximal",   "ring_medium",    "ring_distal",
                                              "thumb_base",       "thumb_abduction", "thumb_proximal", "thumb_distal"};

std::vector<std::string> groupNames(const RobotModel& model, const std::string& group) {
  std::vector<std::string> names;
  for (const auto& joint : model.groupJoints(group)) names.push_back(joint.name);
  return names;
}

/// A link's origin in the palm frame at `q`.
Eigen::Vector3d inPalm(const RobotModel& model, const Configuration& q, const std::string& link) {
  const LinkPoses poses = ForwardKinematics(model).linkPoses(q);
  return poses[static_cast<std::size_t>(model.palmLink())].inverse() *
         poses[static_cast<std::size_t>(model.linkIndex(link))].translation();
}

TEST(SecondRobot, TheUrdfIsTheGeneratorsOutputByteForByte) {
  const test::TempDir dir;
  const auto urdf = dir.path() / "panda_allegro.urdf";
  const std::string command = "python3 " + test::quoted(kSourceDir / "scripts" / "generate-panda-allegro-urdf.py") +
                              " " + test::quoted(urdf) + " >/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::string shipped = test::contents(kData / "robots" / "panda_allegro" / "panda_allegro.urdf");
  ASSERT_FALSE(shipped.empty());
  EXPECT_TRUE(test::contents(urdf) == shipped) << "regenerate the URDF with scripts/generate-panda-allegro-urdf.py";
}

TEST(SecondRobot, TheModelIsThePandasSevenArmJointsAndTheAllegrosSixteenHandJoints) {
  const RobotModel model = RobotModel::loadBuiltIn("panda_allegro");
  EXPECT_EQ(model.dof(), 23) << "no mimic joints: every Allegro joint has its own motor";
  EXPECT_EQ(groupNames(model, "arm"), kArmJoints);
  EXPECT_EQ(groupNames(model, "hand"), kHandJoints);
  EXPECT_EQ(model.links()[static_cast<std::size_t>(model.palmLink())].name, "palm");
  // The published limits of the Panda's joint 4 and 6 and of the Allegro's thumb base (rad).
  const auto& joints = model.activeJoints();
  EXPECT_DOUBLE_EQ(joints[static_cast<std::size_t>(model.activeIndex("panda_joint4"))].upper, -0.0698);
  EXPECT_DOUBLE_EQ(joints[static_cast<std::size_t>(model.activeIndex("panda_joint6"))].lower, -0.0175);
  EXPECT_DOUBLE_EQ(joints[static_cast<std::size_t>(model.activeIndex("thumb_base"))].lower, 0.263);
  EXPECT_DOUBLE_EQ(joints[static_cast<std::size_t>(model.activeIndex("thumb_base"))].upper, 1.396);
}

TEST(SecondRobot, ForwardKinematicsFollowsThePandasDhTableAndTheAllegrosLinkLengths) {
  const RobotModel model = RobotModel::loadBuiltIn("panda_allegro");
  const Configuration zero = Configuration::Zero(model.dof());
  // At all joints 0 the Panda stands straight with its flange pointing down: x = a4 + a5 + a7,
  // z = d1 + d3 + d5 - flange (Franka's published table).
  const Eigen::Isometry3d flange =
      ForwardKinematics(model).linkPoses(zero)[static_cast<std::size_t>(model.linkIndex("panda_link8"))];
  EXPECT_LT((flange.translation() - Eigen::Vector3d(0.088, 0.0, 0.926)).norm(), 1e-9);
  EXPECT_LT((flange.linear().col(2) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-9);
  // The straight middle finger: base 0.7 mm above the palm, then 16.4 + 54 + 38.4 mm of links to
  // its distal joint.
  EXPECT_LT((inPalm(model, zero, "middle_distal_link") - Eigen::Vector3d(0, 0, 0.1095)).norm(), 1e-9);
}

TEST(SecondRobot, PositiveFlexionTurnsTheFingersTowardThePalmNormal) {
  const RobotModel model = RobotModel::loadBuiltIn("panda_allegro");
  Configuration q = Configuration::Zero(model.dof());
  q[model.activeIndex("thumb_base")] = 0.263;
  for (const std::string finger : {"index", "middle", "ring"}) {
    const double open = inPalm(model, q, finger + "_distal_link").x();
    Configuration flexed = q;
    flexed[model.activeIndex(finger + "_proximal")] = 0.5;
    EXPECT_GT(inPalm(model, flexed, finger + "_distal_link").x(), open + 0.02) << finger;
  }
  // The thumb base turns the thumb from beside the palm (+y) to in front of it (+x): opposition.
  Configuration opposed = q;
  opposed[model.activeIndex("thumb_base")] = 1.396;
  EXPECT_GT(inPalm(model, opposed, "thumb_distal_link").x(), inPalm(model, q, "thumb_distal_link").x() + 0.05);
}

TEST(SecondRobot, TheShippedSynergyModelFitsTheHand) {
  const auto file = kData / "synergies" / "panda_allegro_default.yaml";
  const SynergyModel synergies = loadSynergyModel(file);
  EXPECT_NO_THROW(checkSynergyModelFitsHand(synergies, kHandJoints, file.string()));
  EXPECT_EQ(synergies.ownAxisJoints, std::vector<std::string>{"thumb_base"});
  const RobotModel model = RobotModel::loadBuiltIn("panda_allegro");
  for (const auto& joint : model.groupJoints("hand")) {
    const int i = synergies.jointIndex(joint.name);
    ASSERT_GE(i, 0) << joint.name;
    EXPECT_EQ(synergies.joints[static_cast<std::size_t>(i)].lower, joint.lower) << joint.name;
    EXPECT_EQ(synergies.joints[static_cast<std::size_t>(i)].upper, joint.upper) << joint.name;
  }
  EXPECT_EQ(synergies.directionCount(), 14);  // 16 joints less the own axis and the fixed middle spread
}

TEST(SecondRobot, StartAndGoalAreValidAndTheStraightSegmentIsBlocked) {
  const Task task = loadTaskByName(kTask);
  EXPECT_EQ(task.robot->name(), "panda_allegro");
  ExactCollisionChecker checker(task);
  const auto start = checker.check(task.start);
  const auto goal = checker.check(task.goal);
  EXPECT_TRUE(start.free()) << (start.free() ? "" : start.pairs.front().first + " - " + start.pairs.front().second);
  EXPECT_TRUE(goal.free()) << (goal.free() ? "" : goal.pairs.front().first + " - " + goal.pairs.front().second);
  SegmentChecker segments(checker, *task.robot, 0.001);
  EXPECT_FALSE(segments.isValid(task.start, task.goal)) << "the straight segment needs no planning";
}

TEST(SecondRobot, TheGoalHandWrapsTheCanWithoutTouchingIt) {
  const Task task = loadTaskByName(kTask);
  ASSERT_TRUE(task.target);
  ExactCollisionChecker checker(task);
  const RobotModel& model = *task.robot;
  for (const std::string link :
       {"palm", "thumb_distal_link", "index_distal_link", "middle_distal_link", "ring_distal_link"}) {
    const double d = checker.distanceToObstacle(task.goal, {model.linkIndex(link)}, *task.target);
    EXPECT_GT(d, 0.0) << link << " touches " << *task.target;
    EXPECT_LT(d, 0.005) << link << " is " << d * 1000 << " mm from " << *task.target;
  }
}

// The fast checker (the planners' default) on the new geometry: boxes for links, a palm box the
// thumb turns out of, capsules on a 7-joint arm. Uniform configurations, and ones near the goal grasp
// where links pass within millimetres of the can, the table and each other.
TEST(SecondRobot, TheFastCheckerAgreesWithTheExactOne) {
  const Task task = loadTaskByName(kTask);
  CollisionChecking fast(task, CheckerKind::Fast);
  ExactCollisionChecker exact(task);
  const JointLimits& limits = task.robot->activeJoints();
  std::mt19937_64 random(1);
  int valid = 0, invalid = 0;
  for (int i = 0; i < 20000; ++i) {
    Configuration q(task.robot->dof());
    for (Eigen::Index j = 0; j < q.size(); ++j) {
      const auto& limit = limits[static_cast<std::size_t>(j)];
      const double near = task.goal[j] + std::normal_distribution<double>(0.0, 0.03)(random);
      q[j] = i % 2 ? std::uniform_real_distribution<double>(limit.lower, limit.upper)(random)
                   : std::clamp(near, limit.lower, limit.upper);
    }
    const bool expected = exact.isValid(q);
    ASSERT_EQ(fast.states().isValid(q), expected) << "configuration " << i;
    ++(expected ? valid : invalid);
  }
  EXPECT_GT(valid, 2000);
  EXPECT_GT(invalid, 2000);
}

TEST(SecondRobot, PmdSolvesEverySeedWithAValidPath) {
  const Task task = loadTaskByName(kTask);
  const SynergyModel synergies = loadSynergyModel(kData / "synergies" / "panda_allegro_default.yaml");
  CollisionChecking checking(task, CheckerKind::Fast);
  SegmentChecker segments(checking.exact(), *task.robot, checking.tolerance());
  for (std::uint64_t seed = 1; seed <= test::trials(5, 1); ++seed) {
    TaskPlanningSettings options;
    options.parameters.seed = seed;
    options.parameters.timeLimit = 60.0;
    options.synergies = &synergies;
    const TaskPlanningResult result = planTask(task, checking, options);
    ASSERT_TRUE(result.statistics.solved()) << "seed " << seed << ": " << plannerStatusName(result.status);
    EXPECT_FALSE(result.closingFrom) << "the goal touches nothing: no closing phase";
    const PathValidation validation =
        GraspRule(task).validatePath(checking.exact(), segments, result.path, PathPhases{result.closingFrom});
    EXPECT_TRUE(validation.valid) << "seed " << seed << ": "
                                  << (validation.problems.empty() ? "" : validation.problems.front());
    EXPECT_EQ(result.path.front(), task.start);
    EXPECT_EQ(result.path.back(), task.goal);
  }
}

}  // namespace
}  // namespace pmdplan
