#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::runCli;

using test::contents;

using test::quoted;

TEST(PlanCli, SolvesTheDefaultTaskWithAPathThatValidates) {
  test::TempDir dir;
  const auto path = dir.path() / "p.json";
  const auto csv = dir.path() / "p.csv";
  const auto plan = runCli("plan can_on_table --seed 2 --time-limit 60 -o " + quoted(path) + " --csv " + quoted(csv));
  ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
  EXPECT_NE(plan.out.find("path written to"), std::string::npos);
  const auto file = nlohmann::json::parse(contents(path));
  EXPECT_EQ(file["task"], "can_on_table");
  EXPECT_EQ(file["planner"], "pmd");
  EXPECT_EQ(file["seed"], 2);
  EXPECT_EQ(file["joint_names"].size(), 19u);
  EXPECT_GE(file["points"].size(), 2u);
  EXPECT_EQ(file["mimic"]["index_distal"][0], "index_medium");
  EXPECT_EQ(contents(csv).substr(0, 13), "tx90_joint_1,");

  const auto validate = runCli("validate can_on_table " + quoted(path) + " --json");
  ASSERT_EQ(validate.exitCode, 0) << validate.out << validate.err;
  const auto report = nlohmann::json::parse(validate.out);
  EXPECT_TRUE(report["valid"].get<bool>());
  EXPECT_GT(report["states_checked"].get<long>(), 100);
  EXPECT_TRUE(report["collisions"].empty());
}

TEST(PlanCli, TheSameTaskAndSeedGiveAByteIdenticalPathFile) {
  test::TempDir dir;
  const auto a = dir.path() / "a.json", b = dir.path() / "b.json";
  ASSERT_EQ(runCli("plan can_on_table --seed 3 -o " + quoted(a)).exitCode, 0);
  ASSERT_EQ(runCli("plan can_on_table --seed 3 -o " + quoted(b)).exitCode, 0);
  EXPECT_EQ(contents(a), contents(b));
  EXPECT_FALSE(contents(a).empty());
}

TEST(PlanCli, OurLazyAndBidirectionalPlannersWriteByteIdenticalPathsThatValidate) {
  for (const std::string planner : {"pmd-lazy", "pmd-connect"}) {
    test::TempDir dir;
    const auto a = dir.path() / "a.json", b = dir.path() / "b.json";
    const auto plan = runCli("plan can_in_box --planner " + planner + " --seed 4 -o " + quoted(a));
    ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
    ASSERT_EQ(runCli("plan can_in_box --planner " + planner + " --seed 4 -o " + quoted(b)).exitCode, 0);
    EXPECT_EQ(contents(a), contents(b)) << planner;
    EXPECT_EQ(nlohmann::json::parse(contents(a))["planner"], planner);
    const auto validate = runCli("validate can_in_box " + quoted(a) + " --json");
    ASSERT_EQ(validate.exitCode, 0) << validate.out << validate.err;
    EXPECT_TRUE(nlohmann::json::parse(validate.out)["valid"].get<bool>()) << planner;
  }
}

// `plan` takes every planner `bench` and Python take (one service: planning/task_planning.hpp).
// OMPL's seed holds once per process, and a `plan` is one process: the same seed, the same file.
TEST(PlanCli, OmplPlannersWriteByteIdenticalPathsThatValidate) {
  for (const std::string planner : {"ompl:RRTConnect", "ompl:RRTConnect@pmd"}) {
    test::TempDir dir;
    const auto a = dir.path() / "a.json", b = dir.path() / "b.json";
    const auto plan = runCli("plan can_on_table --planner " + planner + " --seed 2 --time-limit 60 -o " + quoted(a));
    ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
    EXPECT_NE(plan.out.find("solved with the " + planner + " planner"), std::string::npos) << plan.out;
    ASSERT_EQ(runCli("plan can_on_table --planner " + planner + " --seed 2 --time-limit 60 -o " + quoted(b)).exitCode,
              0);
    EXPECT_EQ(contents(a), contents(b)) << planner;
    const auto file = nlohmann::json::parse(contents(a));
    EXPECT_EQ(file["planner"], planner);
    EXPECT_GT(file["statistics"]["samples"].get<long>(), 0) << "OMPL's states checked";
    const auto validate = runCli("validate can_on_table " + quoted(a) + " --json");
    ASSERT_EQ(validate.exitCode, 0) << validate.out << validate.err;
    EXPECT_TRUE(nlohmann::json::parse(validate.out)["valid"].get<bool>()) << planner;
  }
}

TEST(PlanCli, ValidateRejectsAPathThroughTheCan) {
  test::TempDir dir;
  const auto path = dir.path() / "p.json";
  ASSERT_EQ(runCli("plan can_on_table --seed 2 -o " + quoted(path)).exitCode, 0);
  // The straight start-goal segment hits the can: a two-point path along it must fail validation.
  auto file = nlohmann::json::parse(contents(path));
  file["points"] = nlohmann::json::array({file["points"].front(), file["points"].back()});
  std::ofstream(path) << file.dump();
  const auto validate = runCli("validate can_on_table " + quoted(path) + " --json");
  EXPECT_EQ(validate.exitCode, 1);
  const auto report = nlohmann::json::parse(validate.out);
  EXPECT_FALSE(report["valid"].get<bool>());
  EXPECT_FALSE(report["collisions"].empty());
}

// A two-joint slider carrying a ball ("arm") with a spinning knob ("hand"): its goal lies inside a
// closed box, so no path exists.
const char* kSlider = R"(<?xml version="1.0"?>
<robot name="slider">
  <link name="base"/><link name="carriage"/>
  <link name="ball"><collision><geometry><sphere radius="0.02"/></geometry></collision></link>
  <link name="knob"><collision><origin xyz="0.03 0 0"/><geometry><sphere radius="0.005"/></geometry></collision></link>
  <joint name="x" type="prismatic"><parent link="base"/><child link="carriage"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="y" type="prismatic"><parent link="carriage"/><child link="ball"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="spin" type="revolute"><parent link="ball"/><child link="knob"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
</robot>
)";
const char* kSliderGroups = R"(<robot name="slider"><group name="arm"><joint name="x"/><joint name="y"/></group>
<group name="hand"><joint name="spin"/></group></robot>)";

TEST(PlanCli, AnInfeasibleTaskEndsWithExitOneWithinItsTimeLimit) {
  test::TempDir dir;
  dir.write("slider.urdf", kSlider);
  dir.write("slider.srdf", kSliderGroups);
  const auto task = dir.write("boxed.yaml", R"(name: boxed
robot: slider.urdf
base: {xyz: [0, 0, 0]}
obstacles:
  - {name: wall_low_x, box: [0.02, 0.4, 0.2], xyz: [0.3, 0.5, 0]}
  - {name: wall_high_x, box: [0.02, 0.4, 0.2], xyz: [0.7, 0.5, 0]}
  - {name: wall_low_y, box: [0.4, 0.02, 0.2], xyz: [0.5, 0.3, 0]}
  - {name: wall_high_y, box: [0.4, 0.02, 0.2], xyz: [0.5, 0.7, 0]}
  - {name: lid, box: [0.42, 0.42, 0.02], xyz: [0.5, 0.5, 0.11]}
  - {name: bottom, box: [0.42, 0.42, 0.02], xyz: [0.5, 0.5, -0.11]}
start: {joints: {x: -0.5, y: -0.5, spin: 0}}
goal: {joints: {x: 0.5, y: 0.5, spin: 1}}
)");
  const auto started = std::chrono::steady_clock::now();
  const auto result =
      runCli("plan " + quoted(task) + " --planner full --time-limit 2 -o " + quoted(dir.path() / "p.json"));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(result.exitCode, 1) << result.out << result.err;
  EXPECT_NE(result.out.find("not solved (time_limit)"), std::string::npos) << result.out;
  EXPECT_LT(seconds, 30.0);  // the limit is 2 s; generous for a loaded machine
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "p.json"));
}

TEST(PlanCli, AStartInCollisionIsABadInputNamingThePair) {
  test::TempDir dir;
  std::string text = contents(std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "scenes" / "can_on_table.yaml");
  // A ball where the start palm is.
  text.replace(text.find("start:"), 0, "  - {name: ball, sphere: 0.03, xyz: [-0.26, 0.537, 0.731]}\n");
  const auto task = dir.write("bad_start.yaml", text);
  const auto result = runCli("plan " + quoted(task) + " -o " + quoted(dir.path() / "p.json"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("start"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("ball"), std::string::npos) << result.err;
}

TEST(PlanCli, AnUnknownPlannerIsABadInput) {
  const auto result = runCli("plan can_on_table --planner rrt");
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.err.find("--planner"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("expected pmd, full, pmd-lazy, pmd-connect"), std::string::npos) << result.err;
  const auto ompl = runCli("plan can_on_table --planner ompl:RRTstar");
  EXPECT_EQ(ompl.exitCode, 2);
  EXPECT_NE(ompl.err.find("'ompl:RRTstar' is not a planner"), std::string::npos) << ompl.err;
  EXPECT_NE(ompl.err.find("ompl:RRTConnect@pmd"), std::string::npos) << "the message lists OMPL's too: " << ompl.err;
  const auto setting = runCli("plan can_on_table --planner pmd-lazy --lazy-radius 0");
  EXPECT_EQ(setting.exitCode, 2);
  EXPECT_NE(setting.err.find("--lazy-radius"), std::string::npos) << setting.err;
  const auto connect = runCli("plan can_on_table --planner pmd-connect --connect-arm-growth 0.5");
  EXPECT_EQ(connect.exitCode, 2);
  EXPECT_NE(connect.err.find("--connect-arm-growth"), std::string::npos) << connect.err;
}

}  // namespace
}  // namespace pmdplan
