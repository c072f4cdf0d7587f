#include "pmdplan/bench/planning_time_plot.hpp"

#include <gtest/gtest.h>

#include "record_samples.hpp"

namespace pmdplan {
namespace {

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(PlanningTimePlot, OneBoxPerPlannerAndTaskOnALogAxisWithTheLimit) {
  const std::vector<RunRecord> records = {
      test::successfulRun("a", "pmd", 0, 0.5),  test::successfulRun("a", "pmd", 1, 2.0),
      test::successfulRun("a", "pmd", 2, 1.0),  test::failedRun("a", "ompl:RRT", 0, "not solved: Timeout"),
      test::successfulRun("b", "pmd", 0, 0.02), test::failedRun("b", "ompl:RRT", 0, "crashed: signal 11")};
  const std::string svg = planningTimeBoxPlotSvg(records, {"a", "b"}, {"pmd", "ompl:RRT"}, 60.0);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  // Four boxes plus two legend swatches, and a label per task, per box (successes/runs) and per planner.
  EXPECT_EQ(count(svg, "fill-opacity=\"0.35\""), 6u);
  EXPECT_EQ(count(svg, ">a</text>"), 1u);
  EXPECT_EQ(count(svg, ">3/3</text>"), 1u);
  EXPECT_EQ(count(svg, ">0/1</text>"), 2u);
  EXPECT_EQ(count(svg, ">ompl:RRT</text>"), 1u);
  // Decades from 0.01 (the fastest run) to 100 (above the 60 s limit).
  EXPECT_NE(svg.find(">0.01</text>"), std::string::npos);
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);
  EXPECT_NE(svg.find("time limit"), std::string::npos);
  EXPECT_EQ(svg, planningTimeBoxPlotSvg(records, {"a", "b"}, {"pmd", "ompl:RRT"}, 60.0));
}

}  // namespace
}  // namespace pmdplan
