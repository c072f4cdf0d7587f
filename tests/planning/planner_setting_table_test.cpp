#include "pmdplan/planning/planner_setting_table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

const PlannerSetting& settingNamed(const std::string& flag) {
  for (const PlannerSetting& s : plannerSettingTable())
    if (s.flag == flag) return s;
  throw std::out_of_range("no setting " + flag);
}

TEST(PlannerSettingTable, FlagsAreUniqueAndEveryValueReadsBack) {
  std::set<std::string> flags;
  const PlannerSettings defaults = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  for (const PlannerSetting& s : plannerSettingTable()) {
    EXPECT_TRUE(flags.insert(s.flag).second) << s.flag;
    EXPECT_FALSE(s.help.empty()) << s.flag;
    PlannerSettings p;
    s.set(p, s.get(defaults));
    EXPECT_EQ(describePlannerSettings(p), describePlannerSettings(defaults)) << s.flag;
  }
}

// Every field of PlannerSettings is reachable: setting each one to a value other than the
// default changes the description, and changes only that setting's part of it.
TEST(PlannerSettingTable, EverySettingReachesItsOwnField) {
  const std::map<std::string, std::string> other = {{"rho-a", "0.05"},
                                                    {"rho-a-growth", "linear"},
                                                    {"neighbours", "7"},
                                                    {"neighbour-threshold", "2.5"},
                                                    {"arm-trials", "3"},
                                                    {"hand-trials", "4"},
                                                    {"max-samples", "99"},
                                                    {"sweep-visits", "1"},
                                                    {"kappa", "1.5"},
                                                    {"max-pmds", "2"},
                                                    {"smooth", "off"},
                                                    {"time-limit", "inf"},
                                                    {"seed", "18446744073709551615"},
                                                    {"lazy-batch", "3"},
                                                    {"lazy-neighbours", "5"},
                                                    {"lazy-radius", "1.5"},
                                                    {"lazy-probes", "3"},
                                                    {"lazy-arm-growth", "1.25"},
                                                    {"sequence", "sdk"},
                                                    {"connect-range", "0.5"},
                                                    {"connect-round", "9"},
                                                    {"connect-arm-growth", "1.5"},
                                                    {"connect-probes", "4"}};
  ASSERT_EQ(other.size(), plannerSettingTable().size()) << "a new setting needs a value here";
  for (const auto& [flag, value] : other) {
    PlannerSettings p;
    settingNamed(flag).set(p, value);
    EXPECT_EQ(settingNamed(flag).get(p), value);
    EXPECT_NO_THROW(p.check()) << flag;
    for (const PlannerSetting& s : plannerSettingTable())
      if (s.flag != flag) {
        EXPECT_EQ(s.get(p), s.get(PlannerSettings{})) << flag << " changed " << s.flag;
      }
  }
}

TEST(PlannerSettingTable, MalformedTextNamesTheSettingsKey) {
  const std::pair<const char*, const char*> bad[] = {{"rho-a", "nan"},       {"rho-a", "0.1x"},
                                                     {"rho-a", ""},          {"neighbours", "-1"},
                                                     {"neighbours", "2.5"},  {"seed", "-1"},
                                                     {"seed", "1e3"},        {"arm-trials", "4294967296"},
                                                     {"smooth", "yes"},      {"rho-a-growth", "Factorial"},
                                                     {"time-limit", "1e999"}};
  for (const auto& [flag, text] : bad) {
    PlannerSettings p;
    try {
      settingNamed(flag).set(p, text);
      ADD_FAILURE() << "--" << flag << " accepted '" << text << "'";
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), flag);
      EXPECT_NE(e.message().find(text), std::string::npos) << e.message();
    }
  }
}

}  // namespace
}  // namespace pmdplan

namespace pmdplan {
namespace {

// One name per idea: a row's Python/OMPL name is its key with '_' for '-', and both find the row.
TEST(PlannerSettingTable, NamesAreTheKeysWithUnderscores) {
  std::set<std::string> names;
  for (const PlannerSetting& s : plannerSettingTable()) {
    EXPECT_EQ(s.name().find('-'), std::string::npos) << s.flag;
    EXPECT_EQ(s.flag.find('_'), std::string::npos) << s.flag;
    std::string back = s.name();
    std::replace(back.begin(), back.end(), '_', '-');
    EXPECT_EQ(back, s.flag);
    EXPECT_TRUE(names.insert(s.name()).second) << s.name();
    EXPECT_EQ(findPlannerSetting(s.flag), &s);
    EXPECT_EQ(findPlannerSetting(s.name()), &s);
  }
  EXPECT_EQ(settingName("connect-arm-growth"), "connect_arm_growth");
  EXPECT_EQ(findPlannerSetting("rho_a")->flag, "rho-a");
  EXPECT_EQ(findPlannerSetting("initial_arm_half_size"), nullptr);
}

// The kind says what text a row takes: a Number reads "0.5", a Count "3" but not "0.5", a Choice
// each of its choices and nothing else, a Switch exactly "on" and "off".
TEST(PlannerSettingTable, EveryRowTakesTheTextsOfItsKind) {
  for (const PlannerSetting& s : plannerSettingTable()) {
    PlannerSettings p;
    const auto accepts = [&](const std::string& text) {
      try {
        s.set(p, text);
        return s.get(p) == text;
      } catch (const InputError& e) {
        EXPECT_EQ(e.field(), s.flag);
        return false;
      }
    };
    switch (s.kind) {
      case SettingKind::Number:
        EXPECT_TRUE(accepts("0.5")) << s.flag;
        EXPECT_TRUE(s.choices.empty()) << s.flag;
        EXPECT_EQ(s.valueName(), "NUMBER");
        break;
      case SettingKind::Count:
        EXPECT_TRUE(accepts("3")) << s.flag;
        EXPECT_FALSE(accepts("0.5")) << s.flag;
        EXPECT_TRUE(s.choices.empty()) << s.flag;
        EXPECT_EQ(s.valueName(), "COUNT");
        break;
      case SettingKind::Choice:
      case SettingKind::Switch:
        EXPECT_GE(s.choices.size(), 2u) << s.flag;
        for (const std::string& choice : s.choices) EXPECT_TRUE(accepts(choice)) << s.flag << " " << choice;
        EXPECT_FALSE(accepts("3")) << s.flag;
        EXPECT_NE(s.valueName().find(s.choices.front() + "|"), std::string::npos) << s.valueName();
        break;
    }
    EXPECT_EQ(s.kind == SettingKind::Switch, s.choices == std::vector<std::string>({"on", "off"})) << s.flag;
  }
  EXPECT_EQ(findPlannerSetting("smooth")->kind, SettingKind::Switch);
  EXPECT_EQ(findPlannerSetting("sequence")->kind, SettingKind::Choice);
  EXPECT_EQ(findPlannerSetting("sequence")->valueName(), "random|halton|sdk");
  EXPECT_EQ(findPlannerSetting("seed")->kind, SettingKind::Count);
  EXPECT_EQ(settingKindName(SettingKind::Switch), "switch");
}

}  // namespace
}  // namespace pmdplan
