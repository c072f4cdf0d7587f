// The fast checker's model of a task is built once and never changed (src/collision/fast/
// checker_model.hpp): checkers that share it, each with its own scratch and exact checker, answer
// exactly as a checker of its own does, keep their own statistics and motion, and may run in
// parallel threads.
#include <gtest/gtest.h>

#include <memory>
#include <thread>
#include <vector>

#include "collision/task_configurations.hpp"
#include "pmdplan/collision/fast/fast_collision_checker.hpp"
#include "support/paper_tasks.hpp"
#include "support/sanitizer_build.hpp"

namespace pmdplan {
namespace {

TEST(SharedCheckerModel, CheckersOnOneModelAnswerAsACheckerOfItsOwn) {
  constexpr int kLanes = FastCollisionChecker::kLanes;
  for (const auto& name : test::kPaperTasks) {
    const Task task = loadTaskByName(name);
    ExactCollisionChecker exactOwn(task), exactFirst(task), exactSecond(task);
    FastCollisionChecker own(task, exactOwn), first(task, exactFirst);
    FastCollisionChecker second(first.model(), exactSecond);
    EXPECT_EQ(second.model(), first.model());
    EXPECT_EQ(&second.exact(), &exactSecond);
    RandomSource random(31);
    for (int batch = 0; batch < test::trials(300, 40); ++batch) {
      Configuration configurations[kLanes];
      const Configuration* pointers[kLanes];
      for (int k = 0; k < kLanes; ++k) {
        configurations[k] = testing::taskConfiguration(task, random, (batch + k) % 3);
        pointers[k] = &configurations[k];
      }
      bool validOwn[kLanes], validShared[kLanes];
      double safeOwn[kLanes], safeShared[kLanes];
      std::vector<double> gapsOwn(kLanes * own.pairCount()), gapsShared(kLanes * own.pairCount());
      own.checkBatch(pointers, kLanes, validOwn, safeOwn, gapsOwn.data());
      second.checkBatch(pointers, kLanes, validShared, safeShared, gapsShared.data());
      for (int k = 0; k < kLanes; ++k) {
        ASSERT_EQ(validShared[k], validOwn[k]) << name << " batch " << batch << " lane " << k;
        ASSERT_EQ(safeShared[k], safeOwn[k]) << name << " batch " << batch << " lane " << k;
        ASSERT_EQ(second.isValid(configurations[k]), own.isValid(configurations[k])) << name << " batch " << batch;
        if (!validOwn[k]) continue;
        for (std::size_t p = 0; p < own.pairCount(); ++p)
          ASSERT_EQ(gapsShared[k * own.pairCount() + p], gapsOwn[k * own.pairCount() + p]);
      }
    }
    // The statistics are each checker's own: the first checked nothing.
    EXPECT_EQ(first.checkCount(), 0u);
    EXPECT_EQ(first.statistics().provenFree + first.statistics().provenColliding, 0u);
    EXPECT_EQ(second.checkCount(), own.checkCount());
    // So is the motion: setting one on the second leaves the first's shares at their defaults.
    second.setMotion(task.start, task.goal);
    own.setMotion(task.start, task.goal);
    for (std::size_t p = 0; p < own.pairCount(); ++p) {
      ASSERT_EQ(second.pairs().share(p), own.pairs().share(p)) << name << " pair " << p;
      ASSERT_NE(first.pairs().share(p), second.pairs().share(p)) << name << " pair " << p;
    }
  }
}

TEST(SharedCheckerModel, CheckersOnOneModelRunInParallelThreads) {
  const Task task = loadTaskByName("cans_in_shelf");
  ExactCollisionChecker exact(task), reference(task);
  const FastCollisionChecker owner(task, exact);
  constexpr int kThreads = 2;
  const int perThread = test::trials(3000, 300);
  std::vector<std::vector<Configuration>> states(kThreads);
  std::vector<std::vector<char>> expected(kThreads), answers(kThreads);
  RandomSource random(5);
  for (int t = 0; t < kThreads; ++t)
    for (int s = 0; s < perThread; ++s) {
      states[static_cast<std::size_t>(t)].push_back(testing::taskConfiguration(task, random, s % 3));
      expected[static_cast<std::size_t>(t)].push_back(reference.isValid(states[static_cast<std::size_t>(t)].back()));
    }
  std::vector<std::unique_ptr<ExactCollisionChecker>> exacts;
  for (int t = 0; t < kThreads; ++t) exacts.push_back(std::make_unique<ExactCollisionChecker>(task));
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      FastCollisionChecker checker(owner.model(), *exacts[static_cast<std::size_t>(t)]);
      for (const Configuration& q : states[static_cast<std::size_t>(t)])
        answers[static_cast<std::size_t>(t)].push_back(checker.isValid(q));
    });
  for (auto& thread : threads) thread.join();
  std::size_t colliding = 0;
  for (int t = 0; t < kThreads; ++t) {
    ASSERT_EQ(answers[static_cast<std::size_t>(t)], expected[static_cast<std::size_t>(t)]) << "thread " << t;
    for (const char free : expected[static_cast<std::size_t>(t)]) colliding += !free;
  }
  EXPECT_GT(colliding, static_cast<std::size_t>(kThreads * perThread / 10));
}

TEST(SharedCheckerModel, RefusesAnExactCheckerOfAnotherTask) {
  const Task task = loadTaskByName("can_on_table"), other = loadTaskByName("can_on_table");
  ExactCollisionChecker exact(task), otherExact(other);
  const FastCollisionChecker fast(task, exact);
  EXPECT_THROW(FastCollisionChecker(fast.model(), otherExact), std::invalid_argument);
  EXPECT_THROW(FastCollisionChecker(nullptr, exact), std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
