#include "pmdplan/bench/run_summary.hpp"

#include <gtest/gtest.h>

#include "record_samples.hpp"

namespace pmdplan {
namespace {

TEST(RunSummary, MeanAndMedianOverSuccessesOnlyAndSuccessRateOverAllRuns) {
  std::vector<RunRecord> records = {
      test::successfulRun("t", "pmd", 0, 1.0),       test::successfulRun("t", "pmd", 1, 2.0),
      test::successfulRun("t", "pmd", 2, 6.0),       test::failedRun("t", "pmd", 3, "not solved: time_limit"),
      test::successfulRun("other", "pmd", 0, 100.0), test::successfulRun("t", "full", 0, 50.0)};
  RunRecord invalid = test::successfulRun("t", "pmd", 4, 1000.0);
  invalid.valid = false;
  records.push_back(invalid);
  const RunSummary s = summariseRuns(records, "t", "pmd");
  EXPECT_EQ(s.runs, 5u);
  EXPECT_EQ(s.solved, 4u);
  EXPECT_EQ(s.succeeded, 3u);
  EXPECT_DOUBLE_EQ(s.successRate(), 0.6);
  EXPECT_EQ(s.planningTime.count, 3u);
  EXPECT_DOUBLE_EQ(s.planningTime.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.planningTime.median, 2.0);
  EXPECT_DOUBLE_EQ(s.samples.mean, 101.0);
  EXPECT_DOUBLE_EQ(s.mahalanobisMean.mean, 2.0);
  EXPECT_DOUBLE_EQ(s.authorsSubspaceDistanceMean.mean, 0.125);
  EXPECT_DOUBLE_EQ(s.authorsSubspaceDistanceMax.median, 0.375);
  EXPECT_DOUBLE_EQ(s.jointCoupling.mean, 0.75);
}

TEST(RunSummary, TheIndependentMeasuresCountOnlyTheRunsThatHaveThem) {
  RunRecord other = test::successfulRun("t", "pmd", 1, 1.0);
  other.humanLikeness->independent->jointCoupling = -0.25;
  RunRecord without = test::successfulRun("t", "pmd", 2, 1.0);
  without.humanLikeness->independent.reset();
  const RunSummary s = summariseRuns({test::successfulRun("t", "pmd", 0, 1.0), other, without}, "t", "pmd");
  EXPECT_EQ(s.mahalanobisMean.count, 3u);
  EXPECT_EQ(s.jointCoupling.count, 2u);
  EXPECT_DOUBLE_EQ(s.jointCoupling.mean, 0.25);
}

TEST(RunSummary, MedianOfAnEvenCountIsTheMiddlePairsMean) {
  const MetricSummary m = summariseValues({4.0, 1.0, 3.0, 2.0});
  EXPECT_DOUBLE_EQ(m.median, 2.5);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_EQ(summariseValues({}).count, 0u);
}

}  // namespace
}  // namespace pmdplan
