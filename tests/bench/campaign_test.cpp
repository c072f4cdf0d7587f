#include "pmdplan/bench/campaign.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>

#include "pmdplan/bench/campaign_ranks.hpp"

namespace pmdplan {
namespace {

TEST(Campaign, JobsAreTaskMajorThenPlannerThenRun) {
  BenchOptions o;
  o.tasks = {"a", "b"};
  o.planners = {"pmd", "full", "ompl:RRT"};
  o.runs = 4;
  const auto jobs = campaignJobs(o);
  ASSERT_EQ(jobs.size(), 24u);
  EXPECT_EQ(jobs[0].task, 0u);
  EXPECT_EQ(jobs[0].planner, 0u);
  EXPECT_EQ(jobs[3].run, 3);
  EXPECT_EQ(jobs[4].planner, 1u);
  EXPECT_EQ(jobs[4].run, 0);
  EXPECT_EQ(jobs[12].task, 1u);
  EXPECT_EQ(jobs[23].planner, 2u);
}

TEST(Campaign, RanksSplitTheJobsIntoDisjointSetsThatCoverThemAll) {
  for (const int ranks : {1, 2, 3, 7, 30}) {
    std::set<std::size_t> seen;
    std::size_t total = 0;
    for (int r = 0; r < ranks; ++r) {
      const auto mine = jobsOfRank(25, r, ranks);
      total += mine.size();
      seen.insert(mine.begin(), mine.end());
      for (const std::size_t j : mine) EXPECT_EQ(j % static_cast<std::size_t>(ranks), static_cast<std::size_t>(r));
    }
    EXPECT_EQ(total, 25u) << ranks;
    EXPECT_EQ(seen.size(), 25u) << ranks;
  }
  EXPECT_THROW(jobsOfRank(5, 2, 2), std::invalid_argument);
}

TEST(Campaign, ReadsTheLaunchersRankCount) {
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::unsetenv("PMI_SIZE");
  ::unsetenv("PMIX_SIZE");
  EXPECT_EQ(launcherRankCount(), 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
  EXPECT_EQ(launcherRankCount(), 4);
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::setenv("PMI_SIZE", "3", 1);
  EXPECT_EQ(launcherRankCount(), 3);
  ::unsetenv("PMI_SIZE");
}

}  // namespace
}  // namespace pmdplan
