// Done-when 1 of issue 6 (states): the fast checker's answers equal the exact checker's on 100,000
// random configurations over the five tasks; its geometric stages flag every pair FCL finds in
// collision, and every pair they prove overlapping FCL finds in collision too. (Segments:
// fast_segment_checker_test.cpp.)
#include "pmdplan/collision/fast/fast_collision_checker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "collision/task_configurations.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "support/paper_tasks.hpp"
#include "support/sanitizer_build.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

bool listed(const std::vector<std::pair<int, int>>& selfPairs,
            const std::vector<std::pair<int, std::size_t>>& obstaclePairs, const RobotModel& model, const Task& task,
            const CollisionPair& pair) {
  const int a = model.linkIndex(pair.first);
  const int b = model.linkIndex(pair.second);
  if (b >= 0) {
    const auto sorted = std::minmax(a, b);
    return std::find(selfPairs.begin(), selfPairs.end(), std::pair<int, int>(sorted.first, sorted.second)) !=
           selfPairs.end();
  }
  for (const auto& [link, obstacle] : obstaclePairs)
    if (link == a && task.obstacles[obstacle].name == pair.second) return true;
  return false;
}

CollisionPair named(const RobotModel& model, int a, int b) {
  return {model.links()[static_cast<std::size_t>(a)].name, model.links()[static_cast<std::size_t>(b)].name};
}

TEST(FastCollisionChecker, EqualsTheExactCheckerOnRandomConfigurationsOfEveryTask) {
  constexpr int kPerTask = test::trials(20000, 2000);
  std::size_t total = 0, colliding = 0, provenFree = 0, provenColliding = 0, uncertain = 0, armColliding = 0;
  for (const auto& name : test::kPaperTasks) {
    const Task task = loadTaskByName(name);
    ExactCollisionChecker exact(task);
    ExactCollisionChecker reference(task);  // untouched by the fast checker
    FastCollisionChecker fast(task, exact);
    RandomSource random(2026);
    for (int s = 0; s < kPerTask; ++s) {
      const Configuration q = testing::taskConfiguration(task, random, s % 3);
      const CollisionReport report = reference.check(q);
      const ScreenResult screen = fast.screen(q);
      // Conservative: every pair FCL finds in collision is flagged (overlapping or uncertain) ...
      for (const auto& pair : report.pairs)
        ASSERT_TRUE(listed(screen.overlappingSelf, screen.overlappingObstacle, *task.robot, task, pair) ||
                    listed(screen.uncertainSelf, screen.uncertainObstacle, *task.robot, task, pair))
            << name << " sample " << s << ": " << pair.first << " - " << pair.second << " collides but was not flagged";
      // ... and every pair proven overlapping is one FCL finds in collision.
      for (const auto& [a, b] : screen.overlappingSelf) {
        const CollisionPair pair = named(*task.robot, a, b);
        ASSERT_NE(std::find(report.pairs.begin(), report.pairs.end(), pair), report.pairs.end())
            << name << " sample " << s << ": " << pair.first << " - " << pair.second
            << " proven overlapping, FCL finds it free";
      }
      for (const auto& [link, obstacle] : screen.overlappingObstacle) {
        const CollisionPair pair{task.robot->links()[static_cast<std::size_t>(link)].name,
                                 task.obstacles[obstacle].name};
        ASSERT_NE(std::find(report.pairs.begin(), report.pairs.end(), pair), report.pairs.end())
            << name << " sample " << s << ": " << pair.first << " - " << pair.second
            << " proven overlapping, FCL finds it free";
      }
      const bool fastValid = fast.isValid(q);
      ASSERT_EQ(fastValid, report.free()) << name << " sample " << s;
      if (s % 4 == 0) {
        const bool exactArm = reference.isArmValid(q);
        ASSERT_EQ(fast.isArmValid(q), exactArm) << name << " sample " << s << " (arm only)";
        armColliding += !exactArm;
      }
      ++total;
      colliding += !report.free();
      provenFree += screen.provenFree();
      provenColliding += !screen.overlappingSelf.empty() || !screen.overlappingObstacle.empty();
      uncertain += !screen.uncertainSelf.empty() || !screen.uncertainObstacle.empty();
    }
    const auto& statistics = fast.statistics();
    EXPECT_EQ(
        statistics.provenFree + statistics.provenColliding + statistics.confirmedFree + statistics.confirmedColliding,
        fast.checkCount());
  }
  std::printf(
      "[ fast vs exact ] %zu configurations: %zu colliding; proven free %zu, proven colliding %zu, with a pair left "
      "to FCL %zu; %zu arm-only collisions\n",
      total, colliding, provenFree, provenColliding, uncertain, armColliding);
  ::testing::Test::RecordProperty("configurations", static_cast<int>(total));
  ::testing::Test::RecordProperty("colliding", static_cast<int>(colliding));
  ::testing::Test::RecordProperty("proven_free", static_cast<int>(provenFree));
  ::testing::Test::RecordProperty("left_to_fcl", static_cast<int>(uncertain));
  EXPECT_GE(total, 5u * kPerTask);
  // The mix must exercise both answers, not only trivially free configurations.
  EXPECT_GT(colliding, total / 10);
  EXPECT_GT(total - colliding, total / 10);
  // FCL is the exception: almost every configuration is decided by the geometric stages (under 1 %
  // of all; the sanitizer build's first 2000 of each task left 1.06 % to FCL, so 2 % there).
  EXPECT_LT(uncertain, total / (test::kSanitizerBuild ? 50 : 100));
}

// A mesh obstacle stands in the broad phase as its enclosure, which proves "apart" only: near
// it, FCL on the triangles decides. Here a tetrahedron 8 cm across beside the goal can.
TEST(FastCollisionChecker, NearAMeshItGivesFclsAnswerToo) {
  test::TempDir dir;
  dir.write("tetra.stl",
            "solid t\n"
            "facet normal 0 0 -1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 0 1 0\n endloop\nendfacet\n"
            "facet normal 0 -1 0\n outer loop\n vertex 0 0 0\n vertex 0 0 1\n vertex 1 0 0\n endloop\nendfacet\n"
            "facet normal -1 0 0\n outer loop\n vertex 0 0 0\n vertex 0 1 0\n vertex 0 0 1\n endloop\nendfacet\n"
            "facet normal 1 1 1\n outer loop\n vertex 1 0 0\n vertex 0 0 1\n vertex 0 1 0\n endloop\nendfacet\n"
            "endsolid t\n");
  std::string text = readTextFile(dataDirectory() / "scenes" / "can_on_table.yaml");
  const std::string marker = "obstacles:\n";
  text.insert(text.find(marker) + marker.size(),
              "  - {name: tetra, mesh: {file: tetra.stl, scale: [0.08, 0.08, 0.08]}, xyz: [-0.44, 1.04, 0.50]}\n");
  const Task task = loadTask(dir.write("with_mesh.yaml", text));
  ExactCollisionChecker exact(task), reference(task);
  FastCollisionChecker fast(task, exact);
  RandomSource random(5);
  std::size_t nearMesh = 0, colliding = 0;
  const std::size_t tetra = 0;  // listed first
  ASSERT_EQ(task.obstacles[tetra].name, "tetra");
  for (int s = 0; s < 4000; ++s) {
    const Configuration q = testing::taskConfiguration(task, random, 1 + s % 2, 0.03);
    const CollisionReport report = reference.check(q);
    ASSERT_EQ(fast.isValid(q), report.free()) << "sample " << s;
    const ScreenResult screen = fast.screen(q);
    for (const auto& [link, obstacle] : screen.overlappingObstacle)
      ASSERT_NE(obstacle, tetra) << "a mesh's enclosure proves nothing";
    for (const auto& [link, obstacle] : screen.uncertainObstacle) nearMesh += obstacle == tetra;
    colliding += !report.free();
  }
  EXPECT_GT(nearMesh, 20u) << "the test must bring the hand near the mesh";
  EXPECT_GT(colliding, 100u);
}

// checkBatch runs its own geometric stages over the lanes: its answers equal the exact checker's
// too, batch after batch (a spare lane repeats the last configuration), at every lane width the
// CPU runs.
TEST(FastCollisionChecker, BatchesGiveTheExactCheckersAnswers) {
  constexpr int kLanes = FastCollisionChecker::kLanes;
  constexpr int kBatches = test::trials(2000, 200);
  std::size_t total = 0, colliding = 0;
  for (const SimdLevel level : {SimdLevel::sse2, SimdLevel::avx2, SimdLevel::avx512}) {
    if (laneWidth(level) > laneWidth(widestSimdLevel())) continue;
    for (const auto& name : test::kPaperTasks) {
      SCOPED_TRACE(std::string("SIMD level ") + simdLevelName(level));
      const Task task = loadTaskByName(name);
      ExactCollisionChecker exact(task), reference(task);
      FastCollisionChecker fast(task, exact);
      fast.setSimdLevel(level);
      RandomSource random(7);
      for (int batchIndex = 0; batchIndex < kBatches; ++batchIndex) {
        const int count = 1 + batchIndex % kLanes;
        Configuration configurations[kLanes];
        const Configuration* pointers[kLanes];
        for (int k = 0; k < count; ++k) {
          configurations[k] = testing::taskConfiguration(task, random, (batchIndex + k) % 3);
          pointers[k] = &configurations[k];
        }
        bool valid[kLanes];
        double safe[kLanes];
        std::vector<double> gaps(static_cast<std::size_t>(count) * fast.pairCount());
        fast.checkBatch(pointers, count, valid, safe, gaps.data());
        for (int k = 0; k < count; ++k) {
          const bool expected = reference.isValid(configurations[k]);
          ASSERT_EQ(valid[k], expected) << name << " batch " << batchIndex << " lane " << k;
          if (expected) {
            for (std::size_t p = 0; p < fast.pairCount(); ++p)
              ASSERT_GE(gaps[static_cast<std::size_t>(k) * fast.pairCount() + p], 0.0);
          }
          ++total;
          colliding += !expected;
        }
      }
    }
  }
  EXPECT_GE(total, 5u * kBatches);
  EXPECT_GT(colliding, total / 10);
}

// firstWithValidity stops deciding lanes at the one it looks for: its index is the one the
// exact checker gives, for runs of 1 to 20 configurations (several batches) looking for a free one
// and for a colliding one.
TEST(FastCollisionChecker, FirstWithValidityFindsTheExactCheckersFirst) {
  const Task task = loadTaskByName("can_in_box");
  ExactCollisionChecker exact(task), reference(task);
  FastCollisionChecker fast(task, exact);
  RandomSource random(11);
  int foundFree = 0, foundColliding = 0;
  for (int trial = 0; trial < test::trials(600, 100); ++trial) {
    const int count = 1 + trial % 20;
    std::vector<Configuration> configurations;
    std::vector<const Configuration*> pointers;
    for (int k = 0; k < count; ++k) configurations.push_back(testing::taskConfiguration(task, random, (trial + k) % 3));
    for (const Configuration& q : configurations) pointers.push_back(&q);
    for (const bool wanted : {true, false}) {
      int expected = count;
      for (int k = 0; k < count && expected == count; ++k)
        if (reference.isValid(configurations[static_cast<std::size_t>(k)]) == wanted) expected = k;
      const std::size_t checksBefore = fast.checkCount();
      ASSERT_EQ(fast.firstWithValidity(pointers.data(), count, wanted), expected)
          << "trial " << trial << (wanted ? ": first free" : ": first colliding");
      EXPECT_GE(fast.checkCount() - checksBefore, static_cast<std::size_t>(std::min(expected + 1, count)));
      if (expected < count) (wanted ? foundFree : foundColliding) += 1;
    }
  }
  EXPECT_GT(foundFree, 50);
  EXPECT_GT(foundColliding, 50);
}

TEST(FastCollisionChecker, RefusesASimdLevelTheCpuCannotRun) {
  const Task task = loadTaskByName("can_on_table");
  ExactCollisionChecker exact(task);
  FastCollisionChecker fast(task, exact);
  EXPECT_EQ(fast.simdLevel(), widestSimdLevel());
  EXPECT_THROW(fast.setSimdLevel(static_cast<SimdLevel>(7)), std::invalid_argument);
  if (widestSimdLevel() != SimdLevel::avx512) {
    EXPECT_THROW(fast.setSimdLevel(SimdLevel::avx512), std::invalid_argument);
  }
  fast.setSimdLevel(SimdLevel::sse2);
  EXPECT_EQ(fast.simdLevel(), SimdLevel::sse2);
}

}  // namespace
}  // namespace pmdplan
