#include "pmdplan/bench/results_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "record_samples.hpp"

namespace pmdplan {
namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

TEST(ResultsCsv, ColumnsStartAsTheIssueAsksAndOneRowPerRun) {
  const auto csv = runRecordsCsv({test::successfulRun("can_on_table", "pmd", 0, 0.5),
                                  test::failedRun("can_on_table", "ompl:RRT", 1, "not solved: Timeout")});
  const auto rows = lines(csv);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].rfind("task,planner,run,seed,solved,planning_time_s,smoothing_time_s,certification_time_s,", 0),
            0u);
  EXPECT_EQ(rows[1], "can_on_table,pmd,0,1,1,0.5,0.05,0.02,1,100,0,0,0,,20,4,1.5,5000,0.25,0.5,2,0.125,0.375,0.75,");
  // Not solved: the path metrics are empty, the reason is the last column.
  EXPECT_EQ(rows[2], "can_on_table,ompl:RRT,1,2,0,60,0,0,0,9999,0,0,0,,0,,,0,,,,,,,not solved: Timeout");
}

TEST(ResultsCsv, TheIndependentMeasuresAreEmptyForARobotWithoutTheSahHand) {
  RunRecord r = test::successfulRun("own_robot", "pmd", 0, 0.5);
  r.humanLikeness->independent.reset();
  const auto rows = lines(runRecordsCsv({r}));
  EXPECT_NE(rows[0].find(",mahalanobis_mean,authors_pmd_distance_mean,authors_pmd_distance_max,joint_coupling,failure"),
            std::string::npos);
  EXPECT_EQ(rows[1], "own_robot,pmd,0,1,1,0.5,0.05,0.02,1,100,0,0,0,,20,4,1.5,5000,0.25,0.5,2,,,,");
}

TEST(ResultsCsv, QuotesTextWithCommasAndQuotes) {
  const auto csv = runRecordsCsv({test::failedRun("can_on_table", "pmd", 0, "invalid path: a, b \"c\"")});
  EXPECT_NE(csv.find(",\"invalid path: a, b \"\"c\"\"\"\n"), std::string::npos) << csv;
}

TEST(ResultsCsv, NamesTheTimingColumns) {
  const auto header = lines(runRecordsCsv({}))[0];
  for (const auto& column : timingCsvColumns()) EXPECT_NE(header.find(column), std::string::npos) << column;
  EXPECT_EQ(timingCsvColumns().size(), 3u);
}

}  // namespace
}  // namespace pmdplan
