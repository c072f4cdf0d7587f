// The five built-in tasks (data/scenes/*.yaml) load with the hand-arm model and carry the paper's
// scenes, bases and published configurations (docs/reference_data.md §5).
#include <gtest/gtest.h>

#include <array>
#include <numbers>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
const std::array<std::string, 5> kTaskNames = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf",
                                               "t_in_clutter"};

Task loadBuiltIn(const std::string& name) {
  return loadTask(std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "scenes" / (name + ".yaml"));
}

/// Arm J1..J6 then the hand in the order of docs/reference_data.md §5, degrees, positive = flexion.
using PublishedConfiguration = std::array<double, 19>;
const std::array<std::string, 19> kPublishedOrder = {
    "tx90_joint_1",    "tx90_joint_2",   "tx90_joint_3",    "tx90_joint_4",     "tx90_joint_5",
    "tx90_joint_6",    "thumb_base",     "thumb_abduction", "thumb_proximal",   "thumb_medium",
    "index_abduction", "index_proximal", "index_medium",    "middle_abduction", "middle_proximal",
    "middle_medium",   "ring_abduction", "ring_proximal",   "ring_medium"};
constexpr PublishedConfiguration kStart013 = {-87.8, -37.6, 136.0, -20.5, 4.1,  109.6, 43.8, -5.5, 17.7, 26.6,
                                              -2.9,  20.9,  13.2,  0.0,   15.3, 21.8,  2.4,  17.5, 17.7};
constexpr PublishedConfiguration kGoal01 = {-81.4, 32.3, 89.9, -7.0, -30.1, 90.7, 90.0, 3.1,  -2.6, 34.2,
                                            -0.5,  20.1, 30.7, 0.0,  22.0,  34.8, 2.6,  29.3, 28.7};
constexpr PublishedConfiguration kStart2 = {-111.6, -0.4, 89.9, -12.4, 6.9,  112.3, 27.7, -8.2, 28.4, 33.7,
                                            4.6,    42.4, 28.1, 0.0,   40.2, 32.8,  -3.3, 36.8, 29.9};
constexpr PublishedConfiguration kGoal2 = {-78.5, 27.1, 61.5, -17.8, 82.9, 88.0, 74.3, 1.1,  -3.8, 25.8,
                                           -10.4, 0.1,  26.7, 0.0,   -2.8, 41.0, 10.4, 12.5, 32.7};
constexpr PublishedConfiguration kGoal3 = {-84.6, 27.3, 95.4, -7.0, -30.1, 90.7, 75.6, -6.4, -4.0, 4.0,
                                           1.3,   47.1, 4.0,  0.0,  46.6,  11.2, 0.1,  49.6, 9.3};

/// Every joint as published except `changed` (documented in the task file).
void expectPublished(const Task& task, const Configuration& q, const PublishedConfiguration& degrees,
                     const std::string& changed = "") {
  ASSERT_EQ(q.size(), 19);
  for (std::size_t i = 0; i < kPublishedOrder.size(); ++i) {
    if (kPublishedOrder[i] == changed) continue;
    const int index = task.robot->activeIndex(kPublishedOrder[i]);
    ASSERT_GE(index, 0) << kPublishedOrder[i];
    EXPECT_NEAR(q[index], degrees[i] * kDegree, 1e-9) << task.name << " " << kPublishedOrder[i];
  }
}

double boxTop(const Obstacle& obstacle) {
  return obstacle.pose.translation().z() + std::get<BoxShape>(obstacle.shape).size.z() / 2;
}

TEST(BuiltInTasks, AllFiveLoadWithTheHandArmModel) {
  for (const auto& name : kTaskNames) {
    SCOPED_TRACE(name);
    const Task task = loadBuiltIn(name);
    EXPECT_EQ(task.name, name);
    EXPECT_NE(task.description.find("of the paper"), std::string::npos);
    ASSERT_NE(task.robot, nullptr);
    EXPECT_EQ(task.robot->name(), "sah_tx90");
    EXPECT_EQ(task.robot->dof(), 19);
    EXPECT_TRUE(task.robot->withinLimits(task.start, 0.0));
    EXPECT_TRUE(task.robot->withinLimits(task.goal, 0.0));
    ASSERT_TRUE(task.target.has_value());
    EXPECT_NE(task.findObstacle(*task.target), nullptr);
  }
}

TEST(BuiltInTasks, LoadByName) { EXPECT_EQ(loadTaskByName("cans_in_shelf").obstacles.size(), 12u); }

TEST(BuiltInTasks, ObstacleCounts) {
  EXPECT_EQ(loadBuiltIn("can_on_table").obstacles.size(), 4u);    // floor, table, 2 cans
  EXPECT_EQ(loadBuiltIn("cans_on_desk").obstacles.size(), 5u);    // + stacked can
  EXPECT_EQ(loadBuiltIn("can_in_box").obstacles.size(), 7u);      // floor, table, 4 walls, can
  EXPECT_EQ(loadBuiltIn("cans_in_shelf").obstacles.size(), 12u);  // floor, 2 panels, 5 boards, 2 cans, T
  EXPECT_EQ(loadBuiltIn("t_in_clutter").obstacles.size(), 12u);
}

TEST(BuiltInTasks, EveryTaskHasTheFloorSixMillimetresBelowTheBase) {
  for (const auto& name : kTaskNames) {
    const Task task = loadBuiltIn(name);
    const Obstacle* floor = task.findObstacle("floor");
    ASSERT_NE(floor, nullptr) << name;
    EXPECT_NEAR(boxTop(*floor), -0.006, 1e-12) << name;
    EXPECT_NEAR(task.base.translation().z(), 0.0, 1e-12) << name;
  }
}

TEST(BuiltInTasks, TableIsTheHalfMetreDesk) {
  for (const std::string name : {"can_on_table", "cans_on_desk", "can_in_box"}) {
    const Task task = loadBuiltIn(name);
    const Obstacle* table = task.findObstacle("table");
    ASSERT_NE(table, nullptr) << name;
    EXPECT_TRUE(std::get<BoxShape>(table->shape).size.isApprox(Eigen::Vector3d(0.5, 0.5, 0.5))) << name;
    EXPECT_TRUE(table->pose.translation().isApprox(Eigen::Vector3d(-0.5, 1.15, 0.25))) << name;
  }
}

TEST(BuiltInTasks, CansAreUprightCylindersOfThePublishedSize) {
  const Task task = loadBuiltIn("can_on_table");
  for (const std::string name : {"goal_can", "obstacle_can"}) {
    const Obstacle* can = task.findObstacle(name);
    ASSERT_NE(can, nullptr);
    const auto& cylinder = std::get<CylinderShape>(can->shape);
    EXPECT_DOUBLE_EQ(cylinder.radius, 0.0317);
    EXPECT_DOUBLE_EQ(cylinder.length, 0.1206);
    EXPECT_TRUE((can->pose.linear() * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitZ()));
  }
  EXPECT_TRUE(task.findObstacle("goal_can")->pose.translation().isApprox(Eigen::Vector3d(-0.47, 1.10, 0.56)));
}

TEST(BuiltInTasks, CanInTheBoxLiesAlongY) {
  const Task task = loadBuiltIn("can_in_box");
  const Eigen::Vector3d axis = task.findObstacle("goal_can")->pose.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(std::abs(axis.y()), 1.0, 1e-12) << axis.transpose();
}

TEST(BuiltInTasks, BasesAsPublished) {
  const Eigen::Vector3d facingMinusX = -Eigen::Vector3d::UnitX();
  for (const std::string name : {"can_on_table", "cans_on_desk"}) {
    const Task task = loadBuiltIn(name);
    EXPECT_TRUE(task.base.translation().isApprox(Eigen::Vector3d(-0.2005, 0.2301, 0.0))) << name;
    EXPECT_TRUE((task.base.linear() * Eigen::Vector3d::UnitX()).isApprox(facingMinusX, 1e-12)) << name;
  }
  for (const std::string name : {"can_in_box", "cans_in_shelf"}) {
    const Task task = loadBuiltIn(name);
    EXPECT_TRUE(task.base.translation().isApprox(Eigen::Vector3d(-0.3185, 0.4251, 0.0))) << name;
    EXPECT_TRUE((task.base.linear() * Eigen::Vector3d::UnitX()).isApprox(facingMinusX, 1e-12)) << name;
  }
  const Task clutter = loadBuiltIn("t_in_clutter");
  EXPECT_TRUE(clutter.base.translation().isApprox(Eigen::Vector3d(1.484, 0.0, 0.0)));
  EXPECT_TRUE((clutter.base.linear() * Eigen::Vector3d::UnitX()).isApprox(facingMinusX, 1e-12));
}

TEST(BuiltInTasks, PublishedStartsAndGoals) {
  const Task task0 = loadBuiltIn("can_on_table");
  expectPublished(task0, task0.start, kStart013);
  expectPublished(task0, task0.goal, kGoal01);
  const Task task1 = loadBuiltIn("cans_on_desk");
  expectPublished(task1, task1.start, kStart013);
  expectPublished(task1, task1.goal, kGoal01);
  const Task task2 = loadBuiltIn("can_in_box");
  expectPublished(task2, task2.start, kStart2);
  expectPublished(task2, task2.goal, kGoal2);
  const Task task3 = loadBuiltIn("cans_in_shelf");
  expectPublished(task3, task3.start, kStart013);
  // The published thumb cuts into the stem with our geometry: the file opens it (less opposition).
  expectPublished(task3, task3.goal, kGoal3, "thumb_base");
  EXPECT_LT(task3.goal[task3.robot->activeIndex("thumb_base")], kGoal3[6] * kDegree);
}

// Published values written at a limit in degrees land on it within rounding and never past it.
TEST(BuiltInTasks, PublishedValuesAtLimitsSitOnThem) {
  const Task task0 = loadBuiltIn("can_on_table");
  const int thumbBase = task0.robot->activeIndex("thumb_base");
  EXPECT_NEAR(task0.goal[thumbBase], task0.robot->activeJoints()[thumbBase].upper, 1e-9);
  EXPECT_LE(task0.goal[thumbBase], task0.robot->activeJoints()[thumbBase].upper);
  const Task task3 = loadBuiltIn("cans_in_shelf");
  for (const std::string joint : {"thumb_proximal", "thumb_medium", "index_medium"}) {
    const int index = task3.robot->activeIndex(joint);
    EXPECT_NEAR(task3.goal[index], task3.robot->activeJoints()[index].lower, 1e-9) << joint;
    EXPECT_GE(task3.goal[index], task3.robot->activeJoints()[index].lower) << joint;
  }
}

TEST(BuiltInTasks, ShelfTaskTargetsTheStemOfTheT) {
  const Task task = loadBuiltIn("cans_in_shelf");
  EXPECT_EQ(*task.target, "t_stem");
  const auto& stem = std::get<CylinderShape>(task.findObstacle("t_stem")->shape);
  EXPECT_DOUBLE_EQ(stem.radius, 0.02);
  EXPECT_DOUBLE_EQ(stem.length, 0.30);
  EXPECT_NE(task.findObstacle("t_bar"), nullptr);
}

}  // namespace
}  // namespace pmdplan
