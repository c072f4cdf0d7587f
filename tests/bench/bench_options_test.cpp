#include "pmdplan/bench/bench_options.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

using test::expectInputError;

TEST(BenchOptions, DefaultsAreValidAndCoverThePaperTasks) {
  const BenchOptions o;
  EXPECT_NO_THROW(checkBenchOptions(o));
  EXPECT_EQ(o.tasks.size(), 5u);
  EXPECT_EQ(o.planners, std::vector<std::string>{"pmd"});
  EXPECT_EQ(o.runs, 10);
  EXPECT_EQ(o.timeLimit, 60.0);
}

TEST(BenchOptions, AnUnknownPlannerNamesTheKnownOnes) {
  BenchOptions o;
  o.planners = {"pmd", "ompl:RRTstar"};
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "ompl:RRTConnect");
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "'ompl:RRTstar' is not a planner");
}

TEST(BenchOptions, RejectsEmptyAndRepeatedLists) {
  BenchOptions o;
  o.planners = splitList("pmd,,full");
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "'' is not a planner");
  o.planners = {"pmd", "pmd"};
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "twice");
  o.planners = {};
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "no planner");
  o = BenchOptions{};
  o.tasks = {};
  expectInputError([&] { checkBenchOptions(o); }, "", "TASK", "no task");
  o.tasks = {"can_on_table", "can_on_table"};
  expectInputError([&] { checkBenchOptions(o); }, "", "TASK", "twice");
}

TEST(BenchOptions, RejectsZeroOrNegativeRuns) {
  BenchOptions o;
  o.runs = 0;
  expectInputError([&] { checkBenchOptions(o); }, "", "--runs", ">= 1");
  o.runs = -3;
  expectInputError([&] { checkBenchOptions(o); }, "", "--runs", "got -3");
}

TEST(BenchOptions, RejectsTimeLimitsThatAreNotPositiveFiniteSeconds) {
  for (const double limit :
       {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    BenchOptions o;
    o.timeLimit = limit;
    expectInputError([&] { checkBenchOptions(o); }, "", "--time-limit", "positive");
  }
}

TEST(BenchOptions, RejectsANonPositiveTolerance) {
  BenchOptions o;
  o.toleranceMetres = 0.0;
  expectInputError([&] { checkBenchOptions(o); }, "", "--tolerance-mm", "0.01 to 100");
}

TEST(BenchOptions, SplitListKeepsEmptyItems) {
  EXPECT_EQ(splitList("a,b"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(splitList("a,"), (std::vector<std::string>{"a", ""}));
  EXPECT_EQ(splitList(""), (std::vector<std::string>{""}));
}

}  // namespace
}  // namespace pmdplan
