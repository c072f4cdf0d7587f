// Every row of plannerSettingTable() is an OMPL parameter of OmplPmdPlanner under the row's name
// ("rho_a"): set through OMPL's text, it reaches that field of the planner's settings and no other,
// and reads back through OMPL; a value the row rejects is refused. (The command line's and
// Python's reach of every row: tests/cli/planner_settings_cli_test.cpp,
// python/tests/test_planner_settings.py.)
#include <gtest/gtest.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <string>

#include "pmdplan/bench/ompl_pmd_planner.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {
namespace {

namespace ob = ompl::base;

/// A value of the row other than `current`, as the row's text.
std::string otherValueText(const PlannerSetting& row, const std::string& current) {
  switch (row.kind) {
    case SettingKind::Number:
      return current == "0.5" ? "0.25" : "0.5";
    case SettingKind::Count:
      return current == "3" ? "4" : "3";
    case SettingKind::Choice:
    case SettingKind::Switch:
      return row.choices.front() == current ? row.choices.back() : row.choices.front();
  }
  return current;
}

/// The text of a value no row of the kind accepts.
std::string badValueText(const PlannerSetting& row) { return row.kind == SettingKind::Number ? "nan" : "0.5x"; }

class OmplSettingReach : public ::testing::Test {
 protected:
  OmplSettingReach() : previousLogLevel_(ompl::msg::getLogLevel()) { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
  ~OmplSettingReach() override { ompl::msg::setLogLevel(previousLogLevel_); }

  Task task_ = loadTaskByName("can_on_table");
  PlanningSpace space_ = planningSpaceFromRobot(*task_.robot);
  ob::SpaceInformationPtr si_ = std::make_shared<ob::SpaceInformation>(
      std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned>(space_.dof())));
  OmplPmdPlanner planner_{si_, space_, HandSamplingMode::FullSpace, nullptr};

 private:
  ompl::msg::LogLevel previousLogLevel_;
};

TEST_F(OmplSettingReach, EveryRowIsAParameterThatReachesItsField) {
  for (const PlannerSetting& row : plannerSettingTable()) {
    ASSERT_TRUE(planner_.params().hasParam(row.name())) << "no OMPL parameter " << row.name();
    const PlannerSettings before = planner_.parameters();
    const std::string value = otherValueText(row, row.get(before));
    ASSERT_NE(value, row.get(before)) << row.flag;
    EXPECT_TRUE(planner_.params().setParam(row.name(), value)) << row.name() << " = " << value;
    EXPECT_EQ(row.get(planner_.parameters()), value) << row.name() << " did not reach its field";
    std::string read;
    ASSERT_TRUE(planner_.params().getParam(row.name(), read));
    EXPECT_EQ(read, value) << row.name();
    for (const PlannerSetting& other : plannerSettingTable())
      if (&other != &row) {
        EXPECT_EQ(other.get(planner_.parameters()), other.get(before)) << row.name() << " changed " << other.name();
      }

    EXPECT_FALSE(planner_.params().setParam(row.name(), badValueText(row))) << row.name();
    EXPECT_EQ(row.get(planner_.parameters()), value) << row.name() << ": a refused value changed the field";
  }
}

// One name per idea: the planner has no parameter besides the table's rows.
TEST_F(OmplSettingReach, EveryParameterIsARow) {
  std::vector<std::string> names;
  planner_.params().getParamNames(names);
  EXPECT_EQ(names.size(), plannerSettingTable().size());
  for (const std::string& name : names) {
    const PlannerSetting* row = findPlannerSetting(name);
    ASSERT_NE(row, nullptr) << "parameter " << name << " is not a row of the table";
    EXPECT_EQ(row->name(), name) << "parameter named by the flag, not the name";
  }
  const ob::GenericParam& growth = *planner_.params().getParam("rho_a_growth");
  EXPECT_EQ(growth.getRangeSuggestion(), "factorial,linear");
}

}  // namespace
}  // namespace pmdplan
