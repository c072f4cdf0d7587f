#include "pmdplan/planning/planner_settings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"
#include "pmdplan/planning/planning_statistics.hpp"

namespace pmdplan {
namespace {

TEST(PlannerSettings, DefaultsAreTable3) {
  const PlannerSettings pmd = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  EXPECT_EQ(pmd.rhoA, 0.001);
  EXPECT_EQ(pmd.neighbours, 10u);
  EXPECT_EQ(pmd.neighbourThreshold, 1.0) << "Sect. 5.2: the radius is d(c_ini, c_goal)";
  EXPECT_EQ(pmd.rhoAGrowth, ArmBoxGrowth::Factorial) << "Algorithm 4: rho_a = k·rho_a";
  EXPECT_EQ(pmd.pmdBox.kappa, 2.0);
  EXPECT_EQ(pmd.pmdBox.maxPmds, 4) << "Sect. 6.2: thumb base + up to 4 PMDs";
  EXPECT_EQ(pmd.armTrials, 10);
  EXPECT_EQ(pmd.handTrials, 10);
  EXPECT_EQ(pmd.sweepVisits, 10u) << "n_A: see planner_settings.hpp";
  EXPECT_GE(pmd.maxSamples, 1'000'000u) << "N large: the time limit is the real bound";
  EXPECT_NO_THROW(pmd.check());

  const PlannerSettings full = PlannerSettings::defaultsFor(HandSamplingMode::FullSpace);
  EXPECT_EQ(full.rhoA, 0.001);
  EXPECT_EQ(full.armTrials, 20);
  EXPECT_EQ(full.handTrials, 20);
  EXPECT_EQ(full.neighbourThreshold, 1.0);
}

TEST(PlannerSettings, PresetsDifferFromThePaperOnlyWhereTheySay) {
  const PlannerSettings paper = PlannerSettings::preset(PlannerPreset::Paper, HandSamplingMode::Synergy);
  const PlannerSettings kautham = PlannerSettings::preset(PlannerPreset::Kautham, HandSamplingMode::Synergy);
  const PlannerSettings wide = PlannerSettings::preset(PlannerPreset::Wide, HandSamplingMode::FullSpace);
  EXPECT_EQ(kautham.neighbourThreshold, 4.0);
  EXPECT_EQ(kautham.rhoAGrowth, ArmBoxGrowth::Linear);
  EXPECT_EQ(kautham.armTrials, paper.armTrials);
  EXPECT_EQ(wide.neighbourThreshold, 2.0);
  EXPECT_EQ(wide.armTrials, 20) << "a preset keeps Table 3's per-mode values";
  for (const PlannerPreset preset : {PlannerPreset::Paper, PlannerPreset::Kautham, PlannerPreset::Wide})
    EXPECT_EQ(parsePlannerPreset(plannerPresetName(preset)), preset);
  EXPECT_FALSE(parsePlannerPreset("Paper").has_value());
}

void expectRejected(const PlannerSettings& parameters, const std::string& field) {
  try {
    parameters.check();
    ADD_FAILURE() << "accepted bad " << field;
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), field);
    EXPECT_NE(findPlannerSetting(error.field()), nullptr) << "a check names a setting the table lacks: " << field;
    EXPECT_TRUE(error.file().empty());
  }
}

TEST(PlannerSettings, OutOfRangeValuesNameTheirOption) {
  PlannerSettings p;
  p.rhoA = 0.0;
  expectRejected(p, "rho-a");
  p = {};
  p.rhoA = std::nan("");
  expectRejected(p, "rho-a");
  p = {};
  p.neighbours = 0;
  expectRejected(p, "neighbours");
  p = {};
  p.neighbourThreshold = 0.0;
  expectRejected(p, "neighbour-threshold");
  p = {};
  p.armTrials = 0;
  expectRejected(p, "arm-trials");
  p = {};
  p.handTrials = -1;
  expectRejected(p, "hand-trials");
  p = {};
  p.sweepVisits = 0;
  expectRejected(p, "sweep-visits");
  p = {};
  p.maxSamples = 0;
  expectRejected(p, "max-samples");
  p = {};
  p.pmdBox.kappa = -1.0;
  expectRejected(p, "kappa");
  p = {};
  p.pmdBox.maxPmds = 0;
  expectRejected(p, "max-pmds");
  p = {};
  p.rhoA = 1.5;
  expectRejected(p, "rho-a");
  p = {};
  p.timeLimit = 0.0;
  expectRejected(p, "time-limit");
  p = {};
  p.timeLimit = 1e10;
  expectRejected(p, "time-limit");
  p = {};
  p.timeLimit = std::numeric_limits<double>::infinity();
  EXPECT_NO_THROW(p.check()) << "no time limit is allowed";
}

TEST(HandSamplingMode, NamesRoundTrip) {
  for (const HandSamplingMode mode : {HandSamplingMode::Synergy, HandSamplingMode::FullSpace})
    EXPECT_EQ(parseHandSamplingMode(handSamplingModeName(mode)), mode);
  EXPECT_EQ(handSamplingModeName(HandSamplingMode::Synergy), "pmd");
  EXPECT_EQ(handSamplingModeName(HandSamplingMode::FullSpace), "full");
  EXPECT_FALSE(parseHandSamplingMode("PMD").has_value());
}

TEST(PlannerStatus, HasStableNames) {
  EXPECT_EQ(plannerStatusName(PlannerStatus::Solved), "solved");
  EXPECT_EQ(plannerStatusName(PlannerStatus::TimeLimit), "time_limit");
  EXPECT_EQ(plannerStatusName(PlannerStatus::SampleLimit), "sample_limit");
  EXPECT_EQ(plannerStatusName(PlannerStatus::InvalidStart), "invalid_start");
  EXPECT_EQ(plannerStatusName(PlannerStatus::InvalidGoal), "invalid_goal");
}

}  // namespace
}  // namespace pmdplan
