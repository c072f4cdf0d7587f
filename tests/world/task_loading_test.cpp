// Good task files: what loadTask reads from each key of the schema.
#include <gtest/gtest.h>

#include <numbers>

#include "pmdplan/core/data_directory.hpp"
#include "toy_task_files.hpp"

namespace pmdplan {
namespace {

using test::kValidToyTask;
using test::replaceOnce;
using test::ToyTaskFolder;

constexpr double kOneDegree = std::numbers::pi / 180.0;

class TaskLoading : public ::testing::Test {
 protected:
  ToyTaskFolder folder;
  Task load(const std::string& text) { return loadTask(folder.write("task.yaml", text)); }
};

TEST_F(TaskLoading, ReadsNameDescriptionRobotAndFile) {
  const auto path = folder.write("task.yaml", kValidToyTask);
  const Task task = loadTask(path);
  EXPECT_EQ(task.file, path);
  EXPECT_EQ(task.name, "toy_task");
  EXPECT_EQ(task.description, "a toy robot for the loader tests");
  ASSERT_NE(task.robot, nullptr);
  EXPECT_EQ(task.robot->name(), "toy");
  EXPECT_EQ(task.robot->dof(), 3);
}

TEST_F(TaskLoading, ThePregraspIsOptionalAndReadLikeTheGoal) {
  EXPECT_FALSE(load(kValidToyTask).pregrasp);
  const Task task =
      load(std::string(kValidToyTask) + "pregrasp:\n  joints_deg: {wrist: 10, shoulder: -20, elbow: 30}\n");
  ASSERT_TRUE(task.pregrasp);
  EXPECT_NEAR((*task.pregrasp)[task.robot->activeIndex("shoulder")], -20 * kOneDegree, 1e-12);
  EXPECT_NEAR((*task.pregrasp)[task.robot->activeIndex("wrist")], 10 * kOneDegree, 1e-12);
}

TEST_F(TaskLoading, BasePoseFollowsXyzAndYaw) {
  const Task task = load(kValidToyTask);
  EXPECT_TRUE(task.base.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.0)));
  // A yaw of 90 deg turns the base's x axis onto the world y axis.
  EXPECT_TRUE((task.base.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
}

TEST_F(TaskLoading, ReadsEveryObstacleInFileOrder) {
  const Task task = load(kValidToyTask);
  ASSERT_EQ(task.obstacles.size(), 4u);
  EXPECT_EQ(task.obstacles[0].name, "table");
  EXPECT_EQ(task.obstacles[1].name, "can");
  EXPECT_EQ(task.obstacles[2].name, "ball");
  EXPECT_EQ(task.obstacles[3].name, "part");
  ASSERT_TRUE(task.target.has_value());
  EXPECT_EQ(*task.target, "can");
  EXPECT_EQ(task.findObstacle("can"), &task.obstacles[1]);
  EXPECT_EQ(task.findObstacle("nothing"), nullptr);
}

TEST_F(TaskLoading, BoxSizesAreFullExtentsAndPoseIsTheCentre) {
  const Task task = load(kValidToyTask);
  const auto* box = std::get_if<BoxShape>(&task.obstacles[0].shape);
  ASSERT_NE(box, nullptr);
  EXPECT_TRUE(box->size.isApprox(Eigen::Vector3d(0.5, 0.4, 0.3)));
  EXPECT_TRUE(task.obstacles[0].pose.translation().isApprox(Eigen::Vector3d(1.0, 0.0, 0.15)));
  EXPECT_TRUE(task.obstacles[0].pose.linear().isIdentity());
}

TEST_F(TaskLoading, CylinderAxisIsLocalZTurnedByRoll) {
  const Task task = load(kValidToyTask);
  const auto* cylinder = std::get_if<CylinderShape>(&task.obstacles[1].shape);
  ASSERT_NE(cylinder, nullptr);
  EXPECT_DOUBLE_EQ(cylinder->radius, 0.03);
  EXPECT_DOUBLE_EQ(cylinder->length, 0.12);
  // roll = 90 deg about x takes the local z axis (the cylinder's axis) onto world -y.
  const Eigen::Vector3d axis = task.obstacles[1].pose.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_TRUE(axis.isApprox(-Eigen::Vector3d::UnitY(), 1e-12)) << axis.transpose();
}

TEST_F(TaskLoading, SphereIsARadius) {
  const Task task = load(kValidToyTask);
  const auto* sphere = std::get_if<SphereShape>(&task.obstacles[2].shape);
  ASSERT_NE(sphere, nullptr);
  EXPECT_DOUBLE_EQ(sphere->radius, 0.05);
}

// URDF's convention applies roll first, then yaw, both about fixed axes: R = Rz(yaw)·Ry(pitch)·Rx(roll).
// For rpy = (90, 0, 90) deg the local z axis goes to -y under the roll and then to +x under the yaw;
// the other order (Rx·Rz) would leave it at -y.
TEST_F(TaskLoading, RollPitchYawIsFixedAxisLikeUrdf) {
  const Task task = load(kValidToyTask);
  const Eigen::Matrix3d rotation = task.obstacles[3].pose.linear();
  EXPECT_TRUE((rotation * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
  EXPECT_TRUE((rotation * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE((rotation * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST_F(TaskLoading, GeneralRollPitchYawMatchesElementaryRotations) {
  const double roll = 10 * kOneDegree, pitch = -25 * kOneDegree, yaw = 130 * kOneDegree;
  const auto c = [](double a) { return std::cos(a); };
  const auto s = [](double a) { return std::sin(a); };
  Eigen::Matrix3d rx, ry, rz;
  rx << 1, 0, 0, 0, c(roll), -s(roll), 0, s(roll), c(roll);
  ry << c(pitch), 0, s(pitch), 0, 1, 0, -s(pitch), 0, c(pitch);
  rz << c(yaw), -s(yaw), 0, s(yaw), c(yaw), 0, 0, 0, 1;
  const Task task = load(replaceOnce(kValidToyTask, "rpy_deg: [90, 0, 90]", "rpy_deg: [10, -25, 130]"));
  EXPECT_TRUE(task.obstacles[3].pose.linear().isApprox(rz * ry * rx, 1e-12));
  EXPECT_TRUE(task.obstacles[3].pose.translation().isApprox(Eigen::Vector3d(0, 0.5, 1)));
}

TEST_F(TaskLoading, RelativeMeshPathIsRelativeToTheTaskFileNotTheWorkingDirectory) {
  folder.write("scenes/meshes/part.stl", test::kTetrahedronStl);
  const auto path =
      folder.write("scenes/nested.yaml", replaceOnce(kValidToyTask, "robot: toy.urdf", "robot: ../toy.urdf"));
  ASSERT_NE(std::filesystem::current_path(), path.parent_path());
  const Task task = loadTask(path);
  const auto* mesh = std::get_if<MeshShape>(&task.obstacles[3].shape);
  ASSERT_NE(mesh, nullptr);
  EXPECT_TRUE(mesh->file.is_absolute());
  EXPECT_TRUE(std::filesystem::equivalent(mesh->file, folder.directory() / "scenes/meshes/part.stl"));
  EXPECT_TRUE(mesh->scale.isApprox(Eigen::Vector3d(0.001, 0.002, 0.003)));
}

TEST_F(TaskLoading, AbsoluteMeshPathIsKept) {
  const auto absolute = folder.directory() / "meshes/part.stl";
  const Task task = load(replaceOnce(kValidToyTask, "file: meshes/part.stl", "file: " + absolute.string()));
  EXPECT_TRUE(std::filesystem::equivalent(std::get<MeshShape>(task.obstacles[3].shape).file, absolute));
}

TEST_F(TaskLoading, MeshScaleDefaultsToOne) {
  const Task task = load(replaceOnce(kValidToyTask, ", scale: [0.001, 0.002, 0.003]", ""));
  EXPECT_TRUE(std::get<MeshShape>(task.obstacles[3].shape).scale.isApprox(Eigen::Vector3d::Ones()));
}

TEST_F(TaskLoading, ConfigurationFollowsTheModelOrderNotTheFileOrder) {
  const Task task = load(kValidToyTask);
  const RobotModel& robot = *task.robot;
  ASSERT_EQ(task.goal.size(), 3);
  EXPECT_DOUBLE_EQ(task.goal[robot.activeIndex("shoulder")], -0.5);
  EXPECT_DOUBLE_EQ(task.goal[robot.activeIndex("elbow")], 1.0);
  EXPECT_DOUBLE_EQ(task.goal[robot.activeIndex("wrist")], 0.25);
}

TEST_F(TaskLoading, DegreesAreConvertedToRadians) {
  const Task task = load(kValidToyTask);
  const RobotModel& robot = *task.robot;
  EXPECT_NEAR(task.start[robot.activeIndex("shoulder")], 10 * kOneDegree, 1e-15);
  EXPECT_NEAR(task.start[robot.activeIndex("elbow")], 20 * kOneDegree, 1e-15);
  EXPECT_NEAR(task.start[robot.activeIndex("wrist")], -30 * kOneDegree, 1e-15);
}

TEST_F(TaskLoading, JointsInRadiansEqualJointsInDegrees) {
  const Task inDegrees = load(kValidToyTask);
  const std::string radians = "joints: {shoulder: " + std::to_string(10 * kOneDegree) +
                              ", elbow: " + std::to_string(20 * kOneDegree) +
                              ", wrist: " + std::to_string(-30 * kOneDegree) + "}";
  const Task inRadians =
      load(replaceOnce(kValidToyTask, "joints_deg:\n    shoulder: 10\n    elbow: 20\n    wrist: -30", radians));
  EXPECT_TRUE(inRadians.start.isApprox(inDegrees.start, 1e-6));
  const Task goalInDegrees = load(replaceOnce(kValidToyTask, "joints: {wrist: 0.25, shoulder: -0.5, elbow: 1.0}",
                                              "joints_deg: {wrist: " + std::to_string(0.25 / kOneDegree) +
                                                  ", shoulder: " + std::to_string(-0.5 / kOneDegree) +
                                                  ", elbow: " + std::to_string(1.0 / kOneDegree) + "}"));
  EXPECT_TRUE(goalInDegrees.goal.isApprox(inDegrees.goal, 1e-6));
}

// 120 deg is the elbow's upper limit, written in the URDF in radians: the degree value lands on it
// within rounding and is kept exactly at the limit.
TEST_F(TaskLoading, ValueWrittenAtALimitInDegreesIsAccepted) {
  const Task task = load(replaceOnce(kValidToyTask, "elbow: 20", "elbow: 120"));
  const int elbow = task.robot->activeIndex("elbow");
  EXPECT_DOUBLE_EQ(task.start[elbow], task.robot->activeJoints()[elbow].upper);
  EXPECT_TRUE(task.robot->withinLimits(task.start, 0.0));
}

TEST_F(TaskLoading, OptionalKeysMayBeLeftOut) {
  std::string text = replaceOnce(kValidToyTask, "description: a toy robot for the loader tests\n", "");
  text = replaceOnce(text, "target: can\n", "");
  text = replaceOnce(text, "\n    rpy_deg: [90, 0, 0]", "");
  const Task task = load(text);
  EXPECT_TRUE(task.description.empty());
  EXPECT_FALSE(task.target.has_value());
  EXPECT_TRUE(task.obstacles[1].pose.linear().isIdentity());
}

TEST_F(TaskLoading, EmptyObstacleListIsAllowed) {
  std::string text = replaceOnce(kValidToyTask, "target: can\n", "");
  const auto from = text.find("obstacles:");
  const auto to = text.find("start:");
  text = text.substr(0, from) + "obstacles: []\n" + text.substr(to);
  EXPECT_TRUE(load(text).obstacles.empty());
}

TEST_F(TaskLoading, UrdfBesideItsSrdfUsesTheSrdf) {
  folder.write("toy.srdf", R"(<?xml version="1.0"?>
<robot name="toy">
  <group name="arm"><joint name="shoulder"/><joint name="elbow"/></group>
</robot>
)");
  const Task task = load(kValidToyTask);
  ASSERT_TRUE(task.robot->hasGroup("arm"));
  EXPECT_EQ(task.robot->group("arm").size(), 2u);
}

TEST_F(TaskLoading, LoadTaskByNameTakesAPath) {
  const auto path = folder.write("by_path.yaml", kValidToyTask);
  EXPECT_EQ(loadTaskByName(path.string()).name, "toy_task");
}

// A built-in robot comes from the caller's loader when one is given (one robot for many tasks);
// a URDF path is still read from its file.
TEST_F(TaskLoading, ABuiltInRobotComesFromTheGivenLoader) {
  const auto builtIn = std::make_shared<const RobotModel>(RobotModel::loadBuiltIn("sah_tx90"));
  int calls = 0;
  const BuiltInRobotLoader loader = [&](const std::string& name) {
    ++calls;
    EXPECT_EQ(name, "sah_tx90");
    return builtIn;
  };
  const auto scene = resolveTaskPath("can_on_table");
  EXPECT_EQ(loadTask(scene, loader).robot, builtIn);
  EXPECT_EQ(loadTask(scene, loader).robot, builtIn);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(loadTask(scene).robot->activeJointNames(), builtIn->activeJointNames());
  EXPECT_EQ(loadTask(folder.write("task.yaml", kValidToyTask), loader).robot->name(), "toy");
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace pmdplan
