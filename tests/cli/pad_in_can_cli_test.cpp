// Issue 37, Done when 1 (the commands): a goal with the ring finger's pad box 2.2 mm inside the can
// (support/pad_in_can.hpp; FCL 0.7 alone calls it free) is colliding for `check`, refused by
// `plan --checker exact`, and a path through it fails `validate`, each naming the pair. The
// checkers and the reference on the same state: tests/collision/pad_in_can_test.cpp.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "pmdplan/core/data_directory.hpp"
#include "support/pad_in_can.hpp"
#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using test::quoted;
using test::runCli;

constexpr const char* kPair = "ring_distal_link - goal_can";

TEST(PadInCanCli, CheckCallsItCollidingAndPlanRefusesIt) {
  test::TempDir dir;
  const auto task = dir.write("pad_in_can.yaml", test::padInCanTaskText(dataDirectory() / "scenes"));
  const auto check = runCli(dir, "check " + quoted(task));
  EXPECT_EQ(check.exitCode, 1) << check.out << check.err;
  EXPECT_NE(check.out.find(kPair), std::string::npos) << check.out;
  const auto checkJson = runCli(dir, "check " + quoted(task) + " --json");
  const auto checked = nlohmann::json::parse(checkJson.out);
  EXPECT_FALSE(checked["goal"]["valid"].get<bool>()) << checkJson.out;
  EXPECT_LT(checked["goal"]["clearance_mm"].get<double>(), -1.0) << "a penetration depth";

  const auto plan =
      runCli(dir, "plan " + quoted(task) + " --checker exact --seed 1 -o " + quoted(dir.path() / "p.json"));
  EXPECT_EQ(plan.exitCode, 2) << plan.out << plan.err;
  EXPECT_NE(plan.err.find("goal"), std::string::npos) << plan.err;
  EXPECT_NE(plan.err.find(kPair), std::string::npos) << plan.err;
}

TEST(PadInCanCli, APathThroughItFailsValidate) {
  test::TempDir dir;
  const auto path = dir.path() / "plan.path.json";
  const auto plan = runCli(dir, "plan can_on_table --seed 1 -o " + quoted(path));
  ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
  const auto valid = runCli(dir, "validate can_on_table " + quoted(path));
  ASSERT_EQ(valid.exitCode, 0) << valid.out << valid.err;

  // The same path with the pad-in-can state just before the goal.
  auto file = nlohmann::json::parse(test::contents(path));
  auto& points = file["points"];
  nlohmann::json through;
  through["positions"] = test::kPadInCan;
  points.insert(points.end() - 1, through);
  file.erase("phases");
  const auto detour = dir.write("detour.path.json", file.dump());
  const auto validate = runCli(dir, "validate can_on_table " + quoted(detour));
  EXPECT_EQ(validate.exitCode, 1) << validate.out << validate.err;
  EXPECT_NE(validate.out.find(kPair), std::string::npos) << validate.out;
}

}  // namespace
}  // namespace pmdplan
