// `pmdplan view` of several paths at once: files of one task side by side in the viewer data (the
// first as `path`, the others as `overlay_paths`, each named, warnings prefixed with their file),
// paths of different tasks or robots refused (exit 2 naming the file), and a bench folder's paths of one
// seed, written by `pmdplan bench --paths`, opened with `view DIR --seed N`.
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
using ::testing::StartsWith;

/// `waypoints` evenly spaced points from the task's start to its goal, "planned" by `planner`.
PathFile straightPath(const Task& task, int waypoints, const std::string& planner, std::uint64_t seed = 1) {
  PathFile path{task.name, planner, seed, task.robot->activeJointNames(), {}, std::nullopt, mimicRelations(*task.robot),
                {}};
  for (int i = 0; i < waypoints; ++i)
    path.points.push_back(task.start + (task.goal - task.start) * (static_cast<double>(i) / (waypoints - 1)));
  return path;
}

Configuration stateOf(const nlohmann::json& state) {
  Configuration q(static_cast<Eigen::Index>(state.size()));
  for (std::size_t j = 0; j < state.size(); ++j) q[static_cast<Eigen::Index>(j)] = state[j].get<double>();
  return q;
}

/// The fields of the CSV line that starts with `prefix` (quoted fields may hold commas).
std::vector<std::string> csvRow(const std::string& csv, const std::string& prefix) {
  const auto at = csv.find("\n" + prefix);
  if (at == std::string::npos) return {};
  const std::string line = csv.substr(at + 1, csv.find('\n', at + 1) - at - 1);
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

class ViewPathsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { task_ = new Task(loadTaskByName("can_on_table")); }
  static void TearDownTestSuite() { delete task_; }
  static const Task& task() { return *task_; }
  test::TempDir dir_;

 private:
  static Task* task_;
};
Task* ViewPathsCli::task_ = nullptr;

TEST_F(ViewPathsCli, TwoPathsOfOneTaskAreBothInTheViewerData) {
  const auto a = dir_.path() / "a.json", b = dir_.path() / "b.json";
  writePathFile(a, straightPath(task(), 5, "pmd"));
  PathFile other = straightPath(task(), 2, "full", 7);
  other.points.back()[0] += 0.01;  // ends beside the goal: a warning, named by its file
  writePathFile(b, other);
  const auto out = dir_.path() / "v";
  const auto result = runCli("view " + quoted(a) + " " + quoted(b) + " --out " + quoted(out));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("2 paths"));

  const auto data = test::viewerDocument(out);
  EXPECT_EQ(data["title"], "can_on_table - 2 paths: pmd, full");
  EXPECT_EQ(data["path"]["name"], "pmd, seed 1 (a.json)");
  EXPECT_EQ(data["path"]["waypoint_states"].size(), 5u);
  ASSERT_EQ(data["overlay_paths"].size(), 1u);
  const auto& second = data["overlay_paths"][0];
  EXPECT_EQ(second["name"], "full, seed 7 (b.json)");
  EXPECT_EQ(second["file"], "b.json");
  EXPECT_EQ(second["planner"], "full");
  EXPECT_EQ(second["waypoint_states"].size(), 2u);
  const auto& states = second["states"];
  ASSERT_GE(states.size(), 2u);
  EXPECT_EQ(stateOf(states.front()), task().start);
  EXPECT_TRUE(stateOf(states.back()).isApprox(other.points.back(), 1e-15));
  EXPECT_EQ(second["clearance"].size(), states.size());
  EXPECT_EQ(second["colliding_links"].size(), states.size());
  ASSERT_EQ(data["warnings"].size(), 1u);
  EXPECT_THAT(data["warnings"][0].get<std::string>(),
              StartsWith("b.json: the path's last point is not task can_on_table's goal"));

  // One path alone keeps the single-path document: no overlays, no names.
  ASSERT_EQ(runCli("view " + quoted(a) + " --out " + quoted(dir_.path() / "one")).exitCode, 0);
  const auto one = test::viewerDocument(dir_.path() / "one");
  EXPECT_FALSE(one.contains("overlay_paths"));
  EXPECT_FALSE(one["path"].contains("name"));
}

TEST_F(ViewPathsCli, PathsOfDifferentTasksOrRobotsAreRefusedNamingTheFile) {
  const auto a = dir_.path() / "table.json", b = dir_.path() / "clutter.json";
  writePathFile(a, straightPath(task(), 3, "pmd"));
  writePathFile(b, straightPath(loadTaskByName("t_in_clutter"), 3, "pmd"));
  const auto out = dir_.path() / "v";
  const auto result = runCli("view " + quoted(a) + " " + quoted(b) + " --out " + quoted(out));
  EXPECT_EQ(result.exitCode, 2) << result.out << result.err;
  EXPECT_THAT(result.err,
              HasSubstr("pmdplan: error: " + b.string() + ": task: the path was planned for task 't_in_clutter', but " +
                        a.string() + " for task 'can_on_table'; expected paths of one task"));
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing is written";
  // --task does not make them one task either.
  EXPECT_EQ(runCli("view " + quoted(a) + " " + quoted(b) + " --task can_on_table --out " + quoted(out)).exitCode, 2);

  // Of the task's name but not of its robot (other joints): refused, naming that file.
  PathFile otherRobot = straightPath(task(), 3, "pmd");
  otherRobot.jointNames[2] = "elbow";
  const auto c = dir_.path() / "other-robot.json";
  writePathFile(c, otherRobot);
  const auto robot = runCli("view " + quoted(a) + " " + quoted(c) + " --out " + quoted(out));
  EXPECT_EQ(robot.exitCode, 2);
  EXPECT_THAT(robot.err, HasSubstr("pmdplan: error: " + c.string() +
                                   ": joint_names: expected the 19 active joints of robot 'sah_tx90'"));
  EXPECT_THAT(robot.err, HasSubstr("not joints of the robot: elbow"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST_F(ViewPathsCli, ABenchFoldersPathsOfOneSeedOpenTogetherPmdFirst) {
  const auto bench = dir_.path() / "bench";
  std::filesystem::create_directories(bench);
  writePathFile(bench / "can_on_table.ompl-RRTConnect.seed2.path.json", straightPath(task(), 4, "ompl:RRTConnect", 2));
  writePathFile(bench / "can_on_table.full.seed2.path.json", straightPath(task(), 3, "full", 2));
  writePathFile(bench / "can_on_table.pmd.seed2.path.json", straightPath(task(), 2, "pmd", 2));
  writePathFile(bench / "can_on_table.pmd.seed3.path.json", straightPath(task(), 2, "pmd", 3));
  const auto result = runCli("view " + quoted(bench) + " --seed 2");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto data = test::viewerDocument(bench / "seed2-viewer");
  EXPECT_EQ(data["path"]["planner"], "pmd");
  ASSERT_EQ(data["overlay_paths"].size(), 2u);
  EXPECT_EQ(data["overlay_paths"][0]["planner"], "full");
  EXPECT_EQ(data["overlay_paths"][1]["planner"], "ompl:RRTConnect");
  EXPECT_EQ(data["overlay_paths"][1]["file"], "can_on_table.ompl-RRTConnect.seed2.path.json");

  const auto missing = runCli("view " + quoted(bench) + " --seed 9 --out " + quoted(dir_.path() / "v"));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_THAT(missing.err, HasSubstr(bench.string() + ": --seed: no path file of seed 9"));
  EXPECT_THAT(missing.err, HasSubstr("seeds there: 2, 3"));
  const auto noSeed = runCli("view " + quoted(bench));
  EXPECT_EQ(noSeed.exitCode, 2);
  EXPECT_THAT(noSeed.err, HasSubstr(bench.string() + ": --seed: is a folder: give --seed N"));
  const auto seedOfAFile = runCli("view " + quoted(bench / "can_on_table.pmd.seed3.path.json") + " --seed 3");
  EXPECT_EQ(seedOfAFile.exitCode, 2);
  EXPECT_THAT(seedOfAFile.err, HasSubstr("--seed: picks the paths of a bench folder"));
}

// The real thing end to end: a bench campaign writes its solved runs' paths, and the viewer
// opens a seed's pmd and RRTConnect paths together.
TEST(ViewPathsBench, BenchPathsAreTheRunsPathsAndOpenInTheViewer) {
  test::TempDir dir;
  const auto paths = dir.path() / "paths";
  const auto csv = dir.path() / "runs.csv";
  const auto bench =
      runCli(dir, "bench can_on_table --planners pmd,ompl:RRTConnect --runs 1 --seed 4 --time-limit 20 --csv " +
                      quoted(csv) + " --paths " + quoted(paths));
  ASSERT_EQ(bench.exitCode, 0) << bench.out << bench.err;
  for (const char* planner : {"pmd", "ompl-RRTConnect"}) {
    const auto file = paths / ("can_on_table." + std::string(planner) + ".seed4.path.json");
    ASSERT_TRUE(std::filesystem::is_regular_file(file)) << file;
    const PathFile path = readPathFile(file);
    EXPECT_EQ(path.task, "can_on_table");
    EXPECT_EQ(path.seed, 4u);
    EXPECT_GE(path.points.size(), 2u);
    // The path the CSV measured: its row's path_nodes.
    const auto row = csvRow(contents(csv), "can_on_table," + path.planner + ",0,4,");
    ASSERT_EQ(row.size(), 25u) << path.planner;
    EXPECT_EQ(row[4], "1") << "solved";
    EXPECT_EQ(row[15], std::to_string(path.points.size())) << path.planner;
  }
  const auto view = runCli(dir, "view " + quoted(paths) + " --seed 4 --out " + quoted(dir.path() / "v"));
  ASSERT_EQ(view.exitCode, 0) << view.err;
  const auto data = test::viewerDocument(dir.path() / "v");
  EXPECT_EQ(data["path"]["planner"], "pmd");
  ASSERT_EQ(data["overlay_paths"].size(), 1u);
  EXPECT_EQ(data["overlay_paths"][0]["planner"], "ompl:RRTConnect");
  EXPECT_TRUE(data["warnings"].empty()) << data["warnings"];
}

}  // namespace
}  // namespace pmdplan
