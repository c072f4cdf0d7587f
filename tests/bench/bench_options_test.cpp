#include "pmdplan/bench/bench_options.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

using test::expectInputError;

TEST(BenchSettings, DefaultsAreValidAndCoverThePaperTasks) {
  const BenchSettings o;
  EXPECT_NO_THROW(checkBenchOptions(o));
  EXPECT_EQ(o.tasks.size(), 5u);
  EXPECT_EQ(o.planners, std::vector<std::string>{"pmd"});
  EXPECT_EQ(o.runs, 10);
  EXPECT_EQ(o.timeLimit, 60.0);
}

TEST(BenchSettings, AnUnknownPlannerNamesTheKnownOnes) {
  BenchSettings o;
  o.planners = {"pmd", "ompl:RRTstar"};
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "ompl:RRTConnect");
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "'ompl:RRTstar' is not a planner");
}

TEST(BenchSettings, RejectsEmptyAndRepeatedLists) {
  BenchSettings o;
  o.planners = splitList("pmd,,full");
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "'' is not a planner");
  o.planners = {"pmd", "pmd"};
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "twice");
  o.planners = {};
  expectInputError([&] { checkBenchOptions(o); }, "", "--planners", "no planner");
  o = BenchSettings{};
  o.tasks = {};
  expectInputError([&] { checkBenchOptions(o); }, "", "TASK", "no task");
  o.tasks = {"can_on_table", "can_on_table"};
  expectInputError([&] { checkBenchOptions(o); }, "", "TASK", "twice");
}

TEST(BenchSettings, RejectsZeroOrNegativeRuns) {
  BenchSettings o;
  o.runs = 0;
  expectInputError([&] { checkBenchOptions(o); }, "", "--runs", ">= 1");
  o.runs = -3;
  expectInputError([&] { checkBenchOptions(o); }, "", "--runs", "got -3");
}

TEST(BenchSettings, RejectsTimeLimitsThatAreNotPositiveFiniteSeconds) {
  for (const double limit :
       {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    BenchSettings o;
    o.timeLimit = limit;
    expectInputError([&] { checkBenchOptions(o); }, "", "--time-limit", "positive");
  }
}

TEST(BenchSettings, RejectsANonPositiveTolerance) {
  BenchSettings o;
  o.toleranceMetres = 0.0;
  expectInputError([&] { checkBenchOptions(o); }, "", "--tolerance-mm", "0.01 to 100");
}

TEST(BenchSettings, SplitListKeepsEmptyItems) {
  EXPECT_EQ(splitList("a,b"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(splitList("a,"), (std::vector<std::string>{"a", ""}));
  EXPECT_EQ(splitList(""), (std::vector<std::string>{""}));
}

}  // namespace
}  // namespace pmdplan
