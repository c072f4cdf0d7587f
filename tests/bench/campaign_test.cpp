#include "pmdplan/bench/campaign.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "pmdplan/bench/campaign_ranks.hpp"

namespace pmdplan {
namespace {

TEST(Campaign, JobsAreTaskMajorThenPlannerThenRun) {
  BenchSettings o;
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

TEST(Campaign, OneProcessTakesEveryJobInOrder) {
  CampaignRanks ranks;  // not launched by mpirun: one rank
  ASSERT_EQ(ranks.size(), 1);
  for (std::size_t expected = 0; expected < 5; ++expected) EXPECT_EQ(ranks.takeJob(), expected);
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
