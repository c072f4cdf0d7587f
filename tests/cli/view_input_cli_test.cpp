// `pmdplan view`'s input checks beyond the robot match: a path shown against another task than its
// own whose ends are not that task's is an error (exit 2); a path whose ends are not its task's
// start and goal gets a warning on the page; a number no double holds (1e999) is bad input, not an
// internal error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/viewer_document.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/world/task.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::contents;
using test::quoted;
using test::runCli;
using ::testing::HasSubstr;

PathFile endsOnly(const Task& task) {
  return PathFile{task.name,
                  "test",
                  1,
                  task.robot->activeJointNames(),
                  {task.start, task.goal},
                  std::nullopt,
                  mimicRelations(*task.robot),
                  {}};
}

TEST(ViewInputCli, AnotherTaskWhoseEndsAreNotThePathsIsAnError) {
  test::TempDir dir;
  const auto file = dir.path() / "clutter.json";
  writePathFile(file, endsOnly(loadTaskByName("t_in_clutter")));
  const auto result = runCli("view " + quoted(file) + " --task can_in_box --out " + quoted(dir.path() / "v"));
  EXPECT_EQ(result.exitCode, 2) << result.out << result.err;
  EXPECT_THAT(result.err, HasSubstr(file.string() + ": task: the path was planned for task 't_in_clutter'"));
  EXPECT_THAT(result.err, HasSubstr("can_in_box's start"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "v"));
  // Its own task given explicitly is fine, and the page has no warning.
  const auto own = runCli("view " + quoted(file) + " --task t_in_clutter --out " + quoted(dir.path() / "w"));
  ASSERT_EQ(own.exitCode, 0) << own.err;
  EXPECT_TRUE(test::viewerDocument(dir.path() / "w")["warnings"].empty());
}

TEST(ViewInputCli, EndsThatAreNotTheTasksGiveAWarningOnThePage) {
  test::TempDir dir;
  const Task task = loadTaskByName("can_on_table");
  PathFile path = endsOnly(task);
  path.points.back()[0] += 0.01;
  const auto file = dir.path() / "shifted.json";
  writePathFile(file, path);
  const auto result = runCli("view " + quoted(file) + " --out " + quoted(dir.path() / "v"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto warnings = test::viewerDocument(dir.path() / "v")["warnings"];
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0].get<std::string>(), HasSubstr("last point is not task can_on_table's goal"));
}

TEST(ViewInputCli, EveryStateHasItsClearanceAndItsCollidingLinks) {
  // The straight segment from can_on_table's start to its goal passes through the can.
  test::TempDir dir;
  const auto file = dir.path() / "straight.json";
  writePathFile(file, endsOnly(loadTaskByName("can_on_table")));
  ASSERT_EQ(runCli("view " + quoted(file) + " --out " + quoted(dir.path() / "v")).exitCode, 0);
  const auto path = test::viewerDocument(dir.path() / "v")["path"];
  ASSERT_EQ(path["clearance"].size(), path["states"].size());
  ASSERT_EQ(path["colliding_links"].size(), path["states"].size());
  EXPECT_GT(path["clearance"].front().get<double>(), 0.0);
  EXPECT_TRUE(path["colliding_links"].front().empty());
  std::size_t colliding = 0;
  for (std::size_t i = 0; i < path["states"].size(); ++i) {
    if (path["colliding_links"][i].empty()) continue;
    ++colliding;
    EXPECT_LE(path["clearance"][i].get<double>(), 1e-9) << "state " << i << " collides but has clearance";
  }
  EXPECT_GT(colliding, 0u);
}

TEST(ViewInputCli, AnOverflowingNumberIsBadInput) {
  test::TempDir dir;
  const auto file = dir.path() / "big.json";
  writePathFile(file, endsOnly(loadTaskByName("can_on_table")));
  std::string text = contents(file);
  const auto at = text.find("\"positions\": [") + 14;
  text.replace(at, text.find(',', at) - at, "1e999");
  dir.write("big.json", text);
  for (const std::string command : {"view ", "validate can_on_table ", "time "}) {
    const auto result =
        runCli(command + quoted(file) + (command == "view " ? " --out " + quoted(dir.path() / "v") : ""));
    EXPECT_EQ(result.exitCode, 2) << command << result.err;
    EXPECT_THAT(result.err, HasSubstr(file.string() + ": a number is out of range")) << command;
  }
}

}  // namespace
}  // namespace pmdplan
