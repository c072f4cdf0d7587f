#include "pmdplan/bench/planner_roster.hpp"

#include <gtest/gtest.h>

#include <set>

#include "pmdplan/bench/ompl_planning.hpp"

namespace pmdplan {
namespace {

TEST(PlannerRoster, HoldsOursAndTheSevenOmplPlannersOnceEach) {
  std::set<std::string> names;
  int ompl = 0;
  for (const auto& entry : plannerRoster()) {
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
    if (entry.family == PlannerFamily::Ompl) {
      ++ompl;
      EXPECT_EQ(entry.name, "ompl:" + entry.omplName + (entry.pmdSampling ? "@pmd" : ""));
      EXPECT_TRUE(isOmplPlannerName(entry.omplName)) << entry.omplName;
    }
  }
  EXPECT_EQ(ompl, 14);  // each of the seven with OMPL's sampling and with PMD sampling
  for (const char* name :
       {"pmd", "full", "ompl:RRTConnect", "ompl:PRM", "ompl:LazyPRM", "ompl:KPIECE1", "ompl:BKPIECE1", "ompl:EST",
        "ompl:RRT", "ompl:RRTConnect@pmd", "ompl:PRM@pmd", "ompl:RRT@pmd"})
    EXPECT_TRUE(findPlanner(name).has_value()) << name;
}

TEST(PlannerRoster, OursMapToTheirHandSamplingModes) {
  EXPECT_EQ(findPlanner("pmd")->mode, HandSamplingMode::Synergy);
  EXPECT_EQ(findPlanner("full")->mode, HandSamplingMode::FullSpace);
  EXPECT_EQ(findPlanner("pmd")->family, PlannerFamily::PmdRoadmap);
  EXPECT_EQ(findPlanner("pmd")->algorithm, RoadmapAlgorithm::Paper);
  EXPECT_EQ(findPlanner("full")->algorithm, RoadmapAlgorithm::Paper);
  EXPECT_EQ(findPlanner("pmd-lazy")->mode, HandSamplingMode::Synergy);
  EXPECT_EQ(findPlanner("pmd-lazy")->family, PlannerFamily::PmdRoadmap);
  EXPECT_EQ(findPlanner("pmd-lazy")->algorithm, RoadmapAlgorithm::Lazy);
  EXPECT_EQ(findPlanner("pmd-connect")->mode, HandSamplingMode::Synergy);
  EXPECT_EQ(findPlanner("pmd-connect")->family, PlannerFamily::PmdRoadmap);
  EXPECT_EQ(findPlanner("pmd-connect")->algorithm, RoadmapAlgorithm::Connect);
}

TEST(PlannerRoster, UnknownNamesAreNotFound) {
  EXPECT_FALSE(findPlanner("RRTConnect").has_value());
  EXPECT_FALSE(findPlanner("ompl:RRTstar").has_value());
  EXPECT_FALSE(isOmplPlannerName("RRTstar"));
  EXPECT_NE(knownPlannerNames().find("pmd, full, pmd-lazy, pmd-connect, ompl:RRTConnect"), std::string::npos);
}

}  // namespace
}  // namespace pmdplan
