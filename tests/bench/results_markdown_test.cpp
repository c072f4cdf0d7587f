#include "pmdplan/bench/results_markdown.hpp"

#include <gtest/gtest.h>

#include "record_samples.hpp"

namespace pmdplan {
namespace {

TEST(ResultsMarkdown, OneTablePerTaskWithPlannersAsColumnsAndMetricsAsRows) {
  const std::vector<RunRecord> records = {test::successfulRun("can_on_table", "pmd", 0, 1.0),
                                          test::successfulRun("can_on_table", "pmd", 1, 3.0),
                                          test::failedRun("can_on_table", "ompl:RRT", 0, "not solved: Timeout"),
                                          test::successfulRun("can_in_box", "pmd", 0, 0.25)};
  const std::string md = benchMarkdown(records, {"can_on_table", "can_in_box"}, {"pmd", "ompl:RRT"});
  EXPECT_NE(md.find("### can_on_table\n\n| metric | pmd | ompl:RRT |\n|---|---|---|\n"), std::string::npos) << md;
  EXPECT_NE(md.find("| success (solved and valid) | 2/2 (100 %) | 0/1 (0 %) |"), std::string::npos) << md;
  // mean (median) over the successes; a planner without any shows a dash.
  EXPECT_NE(md.find("| planning time [s] | 2.00 (2.00) | – |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Mahalanobis distance, mean | 2.00 (2.00) | – |"), std::string::npos) << md;
  EXPECT_NE(md.find("| authors' PMD-subspace distance, mean |"), std::string::npos) << md;
  EXPECT_NE(md.find("| Fig. 7 joint coupling |"), std::string::npos) << md;
  EXPECT_NE(md.find("### can_in_box"), std::string::npos);
  EXPECT_NE(md.find("| success (solved and valid) | 1/1 (100 %) | no runs |"), std::string::npos) << md;
  EXPECT_LT(md.find("### can_on_table"), md.find("### can_in_box"));
  // In the summary, a task whose OMPL runs all failed differs from one with none yet (a partial report).
  EXPECT_NE(md.find("| can_on_table | 2000 ms (2/2) | – (0/1) | none solved | – |"), std::string::npos) << md;
  EXPECT_NE(md.find("| can_in_box | 250 ms (1/1) | – (0/0) | no runs | – |"), std::string::npos) << md;
}

TEST(ResultsMarkdown, TheSummaryComparesEveryPlannerWithPmd) {
  const std::vector<RunRecord> records = {test::successfulRun("can_on_table", "pmd", 0, 0.002),
                                          test::successfulRun("can_on_table", "pmd", 1, 0.004),
                                          test::successfulRun("can_on_table", "full", 0, 0.009),
                                          test::successfulRun("can_on_table", "ompl:RRT", 0, 0.5),
                                          test::failedRun("can_on_table", "ompl:RRT", 1, "not solved: Timeout"),
                                          test::successfulRun("can_on_table", "ompl:EST", 0, 0.03),
                                          test::successfulRun("can_on_table", "ompl:EST", 1, 0.09)};
  const std::string md = benchMarkdown(records, {"can_on_table"}, {"pmd", "full", "ompl:RRT", "ompl:EST"});
  EXPECT_NE(md.find("| task | pmd | full | ompl:RRT | ompl:EST | full / pmd | best OMPL planner | best OMPL / pmd |"),
            std::string::npos)
      << md;
  // Medians in ms with the successes; EST (2 of 2) beats the faster-looking RRT (1 of 2).
  EXPECT_NE(
      md.find("| can_on_table | 3.00 ms (2/2) | 9.00 ms (1/1) | 500 ms (1/2) | 60.0 ms (2/2) | 3.00 | EST | 20.00 |"),
      std::string::npos)
      << md;
  EXPECT_LT(md.find("### Summary"), md.find("### can_on_table"));
  EXPECT_EQ(benchMarkdown(records, {"can_on_table"}, {"ompl:RRT"}).find("### Summary"), std::string::npos)
      << "only with pmd";
}

// With OMPL's planners beside ours: each of ours against the best OMPL planner, with the time to
// certify its path and its distance from the synergy subspace against pmd's and RRTConnect's.
TEST(ResultsMarkdown, OurPlannersFaceTheBestOmplPlanner) {
  std::vector<RunRecord> records = {test::successfulRun("can_on_table", "pmd", 0, 0.004),
                                    test::successfulRun("can_on_table", "pmd-connect", 0, 0.002),
                                    test::successfulRun("can_on_table", "ompl:RRTConnect", 0, 0.003),
                                    test::successfulRun("can_on_table", "ompl:EST", 0, 0.008),
                                    test::successfulRun("can_on_table", "ompl:RRTConnect@pmd", 0, 0.001)};
  records[1].certificationTimeSeconds = 0.001;
  records[0].humanLikeness->subspaceDistanceMean = 0.01;
  records[1].humanLikeness->subspaceDistanceMean = 0.015;
  records[2].humanLikeness->subspaceDistanceMean = 0.3;
  const std::string md = benchMarkdown(records, {"can_on_table"},
                                       {"pmd", "pmd-connect", "ompl:RRTConnect", "ompl:EST", "ompl:RRTConnect@pmd"});
  EXPECT_NE(md.find("### Our planners against the best OMPL planner"), std::string::npos) << md;
  EXPECT_NE(md.find("| can_on_table | pmd-connect | 1/1 | 2.00 ms | RRTConnect (3.00 ms) | 1.50 | 1.00 ms | 2.00 | "
                    "0.0150 | 1.50 | 20.00 |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| can_on_table | pmd | 1/1 | 4.00 ms | RRTConnect (3.00 ms) | 0.75 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| can_on_table | ompl:EST |"), std::string::npos) << "OMPL's planners are the reference";
  // Our PMD sampling inside OMPL's RRTConnect is ours, not the peer a user would pick instead.
  EXPECT_NE(md.find("| RRTConnect | 0.75 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| certification time [s] |"), std::string::npos) << md;
  EXPECT_EQ(benchMarkdown(records, {"can_on_table"}, {"pmd", "pmd-connect"}).find("### Our planners against"),
            std::string::npos)
      << "only with an OMPL planner";
}

}  // namespace
}  // namespace pmdplan
