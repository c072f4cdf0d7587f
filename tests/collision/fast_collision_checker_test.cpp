// Done-when 1 of issue 6 (states): the fast checker's answers equal the exact checker's on 100,000
// random configurations over the five tasks, and its sphere stage flags every pair FCL finds in
// collision. (Segments: batched_segment_checker_test.cpp.)
#include "pmdplan/collision/fast_collision_checker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "collision/task_configurations.hpp"

namespace pmdplan {
namespace {

const std::vector<std::string> kTasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf", "t_in_clutter"};

bool flagged(const SphereStageVerdict& verdict, const RobotModel& model, const Task& task, const CollisionPair& pair) {
  const int a = model.linkIndex(pair.first);
  const int b = model.linkIndex(pair.second);
  if (b >= 0) {
    const auto sorted = std::minmax(a, b);
    return std::find(verdict.selfPairs.begin(), verdict.selfPairs.end(), std::pair<int, int>(sorted.first, sorted.second)) !=
           verdict.selfPairs.end();
  }
  for (const auto& [link, obstacle] : verdict.obstaclePairs)
    if (link == a && task.obstacles[obstacle].name == pair.second) return true;
  return false;
}

TEST(FastCollisionChecker, EqualsTheExactCheckerOnRandomConfigurationsOfEveryTask) {
  constexpr int kPerTask = 20000;
  std::size_t total = 0, colliding = 0, sphereFree = 0, flaggedFree = 0, armColliding = 0;
  for (const auto& name : kTasks) {
    const Task task = loadTaskByName(name);
    ExactCollisionChecker exact(task);
    ExactCollisionChecker reference(task);  // untouched by the fast checker
    FastCollisionChecker fast(task, exact);
    RandomSource random(2026);
    for (int s = 0; s < kPerTask; ++s) {
      const Configuration q = testing::taskConfiguration(task, random, s % 3);
      const CollisionReport report = reference.check(q);
      const SphereStageVerdict verdict = fast.sphereStage(q);
      // The sphere stage is conservative: every pair FCL finds in collision is flagged.
      for (const auto& pair : report.pairs)
        ASSERT_TRUE(flagged(verdict, *task.robot, task, pair))
            << name << " sample " << s << ": " << pair.first << " - " << pair.second << " collides but was not flagged";
      const bool fastValid = fast.isValid(q);
      ASSERT_EQ(fastValid, report.free()) << name << " sample " << s;
      if (s % 4 == 0) {
        const bool exactArm = reference.isArmValid(q);
        ASSERT_EQ(fast.isArmValid(q), exactArm) << name << " sample " << s << " (arm only)";
        armColliding += !exactArm;
      }
      ++total;
      colliding += !report.free();
      sphereFree += verdict.free();
      flaggedFree += !verdict.free() && report.free();
    }
    EXPECT_EQ(fast.statistics().colliding + fast.statistics().sphereFree + fast.statistics().confirmedFree, fast.checkCount());
  }
  std::printf("[ fast vs exact ] %zu configurations: %zu colliding, %zu free by spheres alone, %zu flagged and confirmed free; "
              "%zu arm-only collisions\n", total, colliding, sphereFree, flaggedFree, armColliding);
  ::testing::Test::RecordProperty("configurations", static_cast<int>(total));
  ::testing::Test::RecordProperty("colliding", static_cast<int>(colliding));
  ::testing::Test::RecordProperty("sphere_free", static_cast<int>(sphereFree));
  ::testing::Test::RecordProperty("flagged_free", static_cast<int>(flaggedFree));
  EXPECT_GE(total, 100000u);
  // The mix must exercise both answers, not only trivially free configurations.
  EXPECT_GT(colliding, total / 10);
  EXPECT_GT(total - colliding, total / 10);
}

}  // namespace
}  // namespace pmdplan
