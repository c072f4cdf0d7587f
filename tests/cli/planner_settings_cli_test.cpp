// `pmdplan plan` and `pmdplan bench` declare the planner's settings from one table: the same
// flags in both helps, the same values applied, the same errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "pmdplan/planning/planner_setting_table.hpp"
#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using test::runCli;

TEST(PlannerSettingsCli, BothHelpsListEverySettingOfTheTable) {
  const auto plan = runCli("plan --help");
  const auto bench = runCli("bench --help");
  ASSERT_EQ(plan.exitCode, 0);
  ASSERT_EQ(bench.exitCode, 0);
  const PlannerSettings defaults = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  for (const PlannerSetting& s : plannerSettingTable()) {
    // "--rho-a NUMBER   rho_a: initial half-size ... (default 0.001)": the flag, its value's form,
    // its help and its default, on the option's lines.
    const std::string option = "--" + s.flag + " " + s.valueName();
    for (const auto* help : {&plan.out, &bench.out}) {
      const std::size_t at = help->find(option);
      ASSERT_NE(at, std::string::npos) << "--help lacks " << option;
      const std::string lines = help->substr(at, help->find("\n  -", at + 1) - at);
      if (help == &plan.out) {  // bench's --seed has its own help
        EXPECT_NE(lines.find(s.help.substr(1)), std::string::npos) << lines;
      }
      EXPECT_NE(lines.find("(default " + s.get(defaults)), std::string::npos) << lines;
    }
  }
  EXPECT_NE(plan.out.find("--preset"), std::string::npos);
  EXPECT_NE(bench.out.find("--preset"), std::string::npos);
}

TEST(PlannerSettingsCli, BadValuesGiveTheSameErrorInPlanAndBench) {
  const std::string cases[] = {"--rho-a nan",      "--neighbours 0",    "--kappa -2",    "--rho-a-growth fast",
                               "--preset fastest", "--time-limit 1e10", "--max-pmds 1.5"};
  for (const std::string& arguments : cases) {
    const test::TempDir dir;
    const auto plan = runCli(dir, "plan can_on_table " + arguments + " -o " + test::quoted(dir.path() / "p.json"));
    const auto bench = runCli(dir, "bench can_on_table --runs 1 " + arguments);
    EXPECT_EQ(plan.exitCode, 2) << arguments << ": " << plan.err;
    EXPECT_EQ(bench.exitCode, 2) << arguments << ": " << bench.err;
    EXPECT_FALSE(plan.err.empty()) << arguments;
    EXPECT_EQ(plan.err, bench.err) << arguments;
    EXPECT_NE(plan.err.find(arguments.substr(0, arguments.find(' '))), std::string::npos) << plan.err;
  }
}

// A setting given on the command line reaches the planner: a smaller K and a one-pass sweep
// change the run; the same flags give the same statistics again.
TEST(PlannerSettingsCli, SettingsChangeTheRunAndAreDeterministic) {
  const test::TempDir dir;
  const auto run = [&](const std::string& settings) {
    const auto r =
        runCli(dir, "plan can_on_table --seed 3 --json " + settings + " -o " + test::quoted(dir.path() / "p.json"));
    EXPECT_EQ(r.exitCode, 0) << settings << ": " << r.err;
    auto json = nlohmann::json::parse(r.out);
    json.erase("planning_time_s");
    json.erase("smoothing_time_s");
    return json.dump();
  };
  const std::string paper = run("");
  EXPECT_EQ(paper, run("--preset paper --neighbour-threshold 1"));
  EXPECT_NE(paper, run("--preset wide"));
  EXPECT_NE(paper, run("--rho-a 0.02 --hand-trials 3"));
}

}  // namespace
}  // namespace pmdplan
