// Done-when 1 of issue 6 (segments): the fast motion checks equal SegmentChecker's on the exact checker on
// 10,000 random segments over the five tasks (mostly short, some planner-long), about half blocked.
#include "pmdplan/collision/fast_segment_checker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "collision/task_configurations.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "support/paper_tasks.hpp"
#include "support/sanitizer_build.hpp"

namespace pmdplan {
namespace {

TEST(BisectionOrder, VisitsEveryInteriorIndexOnceCoarseToFine) {
  std::vector<long> order;
  bisectionOrder(8, order);
  EXPECT_EQ(order, (std::vector<long>{4, 2, 6, 1, 3, 5, 7}));
  bisectionOrder(1, order);
  EXPECT_TRUE(order.empty());
  bisectionOrder(1000, order);
  std::vector<long> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(sorted.size(), 999u);
  for (long i = 0; i < 999; ++i) EXPECT_EQ(sorted[static_cast<std::size_t>(i)], i + 1);
}

TEST(FastSegmentChecker, EqualsSegmentCheckerOnRandomSegmentsOfEveryTask) {
  constexpr int kPerTask = test::trials(2000, 40);
  std::size_t total = 0, blocked = 0, exactStates = 0, fastStates = 0, skipped = 0;
  for (const auto& name : test::kPaperTasks) {
    const Task task = loadTaskByName(name);
    const auto& model = *task.robot;
    ExactCollisionChecker exact(task);
    ExactCollisionChecker reference(task);
    FastCollisionChecker fast(task, exact);
    SegmentChecker slow(reference, model, 0.001);
    FastSegmentChecker batched(fast, model, 0.001);
    RandomSource random(77);
    int made = 0;
    while (made < kPerTask) {
      // Planner-like neighbours: a valid configuration and a random direction, moving every
      // point at most 2 to 60 mm (up to 60 checked states), or 0.3 to 3 m now and then. Every other segment is laid
      // across the boundary of the free space instead (toward a colliding configuration, around the first colliding
      // point found in 5 mm steps), so that many are blocked part way.
      Configuration from = testing::taskConfiguration(task, random, 1 + made % 2, 0.08);
      if (!reference.isValid(from)) continue;
      Configuration to;
      if (made % 2 == 0) {
        Configuration direction(model.dof());
        for (int i = 0; i < model.dof(); ++i) direction[i] = testing::normal(random);
        // One in twenty is planner-long (up to 3000 states), where the sweep's certificates matter.
        const double length = made % 40 == 0 ? random.uniform(0.3, 3.0) : random.uniform(0.002, 0.06);
        to = from + direction * (length / slow.bound().bound(from, from + direction));
        if (!model.withinLimits(to, 0.0) || !reference.isValid(to)) continue;
      } else {
        const Configuration target = testing::taskConfiguration(task, random, 1, 0.08);
        const double length = slow.bound().bound(from, target);
        const int steps = std::min(40, static_cast<int>(std::ceil(length / 0.005)));
        int hit = 1;
        while (hit <= steps && reference.isValid(from + (target - from) * (hit / static_cast<double>(steps)))) ++hit;
        if (hit > steps) continue;
        const double at = hit / static_cast<double>(steps);
        const double before = random.uniform(0.0, 0.03) / length, after = random.uniform(0.0, 0.03) / length;
        const Configuration start = from + (target - from) * std::max(0.0, at - 1.0 / steps - before);
        to = from + (target - from) * std::min(1.0, at + after);
        from = start;
      }
      ++made;
      const std::size_t slowBefore = slow.statesChecked();
      const std::size_t fastBefore = batched.statesChecked() + batched.statesSkipped();
      const bool expected = slow.isValid(from, to);
      ASSERT_EQ(batched.isValid(from, to), expected) << name << " segment " << made;
      // A free segment: every interior state was either evaluated or skipped as provably free.
      if (expected) {
        ASSERT_EQ(batched.statesChecked() + batched.statesSkipped() - fastBefore, slow.statesChecked() - slowBefore);
      }
      ++total;
      blocked += !expected;
    }
    exactStates += slow.statesChecked();
    fastStates += batched.statesChecked();
    skipped += batched.statesSkipped();
  }
  std::printf(
      "[ segments ] %zu segments, %zu blocked; states evaluated: exact %zu, fast %zu (%zu skipped by clearance)\n",
      total, blocked, exactStates, fastStates, skipped);
  ::testing::Test::RecordProperty("segments", static_cast<int>(total));
  ::testing::Test::RecordProperty("blocked", static_cast<int>(blocked));
  EXPECT_GE(total, 5u * kPerTask);
  EXPECT_GT(blocked, total / 20);
  EXPECT_GT(total - blocked, total / 20);
}

}  // namespace
}  // namespace pmdplan
