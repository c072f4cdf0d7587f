#include "pmdplan/bench/planner_roster.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "planning/toy_problem.hpp"
#include "pmdplan/bench/ompl_planning.hpp"

namespace pmdplan {
namespace {

TEST(PlannerRoster, HoldsOursAndTheSevenOmplPlannersOnceEachWithAndWithoutPmdSampling) {
  std::set<std::string> names;
  int ompl = 0;
  for (const PlannerEntry& entry : plannerRoster().entries()) {
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
    EXPECT_FALSE(entry.description.empty()) << entry.name;
    if (entry.family == PlannerFamily::Ompl) {
      ++ompl;
      const bool pmd = entry.name.size() > 4 && entry.name.substr(entry.name.size() - 4) == "@pmd";
      const std::string omplName = entry.name.substr(5, entry.name.size() - 5 - (pmd ? 4 : 0));
      EXPECT_EQ(entry.name.rfind("ompl:", 0), 0u) << entry.name;
      EXPECT_TRUE(isOmplPlannerName(omplName)) << entry.name;
      EXPECT_EQ(entry.usesSynergies, pmd) << entry.name << ": only PMD sampling needs the model";
    }
  }
  EXPECT_EQ(ompl, 14);  // each of the seven with OMPL's sampling and with PMD sampling
  for (const PlannerEntry& entry : plannerRoster().entries())
    EXPECT_EQ(entry.repeatable, entry.name != "ompl:PRM" && entry.name != "ompl:PRM@pmd")
        << entry.name << ": only PRM's runs depend on its threads";
  for (const char* name :
       {"pmd", "full", "pmd-lazy", "pmd-connect", "ompl:RRTConnect", "ompl:PRM", "ompl:LazyPRM", "ompl:KPIECE1",
        "ompl:BKPIECE1", "ompl:EST", "ompl:RRT", "ompl:RRTConnect@pmd", "ompl:PRM@pmd", "ompl:RRT@pmd"})
    EXPECT_NE(findPlanner(name), nullptr) << name;
  // Ours are the planning layer's registry, first and in its order.
  ASSERT_GE(plannerRoster().entries().size(), ourPlanners().entries().size());
  for (std::size_t i = 0; i < ourPlanners().entries().size(); ++i)
    EXPECT_EQ(plannerRoster().entries()[i].name, ourPlanners().entries()[i].name);
}

TEST(PlannerRoster, EveryEntryMakesThePlannerOfItsName) {
  toy::WallStateValidator states;
  toy::WallMotionValidator motions;
  const SynergyModel model = toy::synergyModel();
  for (const PlannerEntry& entry : plannerRoster().entries()) {
    const std::unique_ptr<Planner> planner =
        entry.allocate({toy::space(), states, motions, PlannerSettings::defaultsFor(entry.mode), &model});
    ASSERT_NE(planner, nullptr) << entry.name;
    EXPECT_EQ(planner->name(), entry.name);
    EXPECT_TRUE(planner->path().empty()) << entry.name;
    EXPECT_EQ(planner->statistics().status, PlannerStatus::NotRun) << entry.name;
  }
}

TEST(PlannerRoster, OursMapToTheirHandSamplingModesAndTheModelTheyNeed) {
  EXPECT_EQ(findPlanner("pmd")->mode, HandSamplingMode::Synergy);
  EXPECT_EQ(findPlanner("full")->mode, HandSamplingMode::FullSpace);
  EXPECT_FALSE(findPlanner("full")->usesSynergies);
  for (const char* name : {"pmd", "pmd-lazy", "pmd-connect"}) {
    EXPECT_EQ(findPlanner(name)->mode, HandSamplingMode::Synergy) << name;
    EXPECT_EQ(findPlanner(name)->family, PlannerFamily::PmdRoadmap) << name;
    EXPECT_TRUE(findPlanner(name)->usesSynergies) << name;
  }
  // A planner that samples PMDs cannot be made without a model.
  toy::WallStateValidator states;
  toy::WallMotionValidator motions;
  for (const char* name : {"pmd", "ompl:RRTConnect@pmd"})
    EXPECT_THROW(findPlanner(name)->allocate({toy::space(), states, motions, PlannerSettings{}, nullptr}),
                 std::invalid_argument)
        << name;
}

TEST(PlannerRoster, UnknownNamesAreNotFound) {
  EXPECT_EQ(findPlanner("RRTConnect"), nullptr);
  EXPECT_EQ(findPlanner("ompl:RRTstar"), nullptr);
  EXPECT_FALSE(isOmplPlannerName("RRTstar"));
  EXPECT_NE(knownPlannerNames().find("pmd, full, pmd-lazy, pmd-connect, ompl:RRTConnect"), std::string::npos);
  EXPECT_THROW(plannerRoster().at("astar"), std::invalid_argument);
}

TEST(PlannerRegistry, RefusesANameGivenTwiceAndAnEntryThatMakesNothing) {
  std::vector<PlannerEntry> twice = {ourPlanners().at("pmd"), ourPlanners().at("pmd")};
  EXPECT_THROW(PlannerRegistry{twice}, std::invalid_argument);
  PlannerEntry empty = ourPlanners().at("full");
  empty.name = "nothing";
  empty.allocate = nullptr;
  EXPECT_THROW(PlannerRegistry{{empty}}, std::invalid_argument);
}

}  // namespace
}  // namespace pmdplan
