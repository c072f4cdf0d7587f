// Inputs a hostile user might give: each ends in exit 2 with one message naming the problem, in
// bounded time, never a crash, a hang, exit 3 or a wrong answer.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::quoted;
using test::runCli;

/// Runs `arguments` and expects exit 2, one line on stderr naming every `expected` text, quickly.
void expectBadInput(const test::TempDir& dir, const std::string& arguments, std::vector<std::string> expected) {
  const auto began = std::chrono::steady_clock::now();
  const auto result = runCli(dir, arguments);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.err;
  EXPECT_EQ(result.err.rfind("pmdplan: error: ", 0), 0u) << arguments << "\n" << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << arguments << "\n" << result.err;
  for (const auto& text : expected)
    EXPECT_NE(result.err.find(text), std::string::npos) << arguments << "\n" << result.err;
  EXPECT_LT(seconds, 10.0) << arguments;
}

/// A two-joint robot; `extraLinks` and `extraJoints` are appended to it.
std::string robotUrdf(const std::string& extraLinks = "", const std::string& extraJoints = "",
                      const std::string& tipGeometry = "<sphere radius=\"0.02\"/>") {
  return "<robot name=\"r\">\n"
         "<link name=\"base\"><collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry></collision></link>\n"
         "<link name=\"upper\"><collision><origin xyz=\"0 0 0.1\"/><geometry><cylinder radius=\"0.02\" "
         "length=\"0.2\"/></geometry></collision></link>\n"
         "<link name=\"tip\"><collision><geometry>" +
         tipGeometry + "</geometry></collision></link>\n" + extraLinks +
         "<joint name=\"a\" type=\"revolute\"><parent link=\"base\"/><child link=\"upper\"/><origin xyz=\"0 0 0.05\"/>"
         "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n"
         "<joint name=\"b\" type=\"revolute\"><parent link=\"upper\"/><child link=\"tip\"/><origin xyz=\"0 0 0.2\"/>"
         "<axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n" +
         extraJoints + "</robot>\n";
}

std::filesystem::path writeTask(const test::TempDir& dir, const std::string& urdf,
                                const std::string& obstacles = "[]") {
  dir.write("robot.urdf", urdf);
  dir.write("robot.srdf",
            "<robot name=\"r\"><group name=\"arm\"><joint name=\"a\"/></group><group name=\"hand\"><joint "
            "name=\"b\"/></group>"
            "<end_effector name=\"e\" parent_link=\"upper\" group=\"hand\"/></robot>\n");
  return dir.write("task.yaml", "name: t\nrobot: robot.urdf\nbase: {xyz: [0, 0, 0], rpy_deg: [0, 0, 0]}\nobstacles: " +
                                    obstacles + "\nstart: {joints: {a: 0, b: 0}}\ngoal: {joints: {a: 0.5, b: 0.5}}\n");
}

TEST(HostileInput, TheTwoJointRobotOfTheseTestsLoads) {
  test::TempDir dir;
  const auto task = writeTask(dir, robotUrdf());
  const auto result = runCli(dir, "check " + quoted(task));
  // It loads: no bad input. (Its adjacent links touch and the SRDF exempts none, so check says
  // plan would refuse its start and goal: exit 1.)
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  EXPECT_NE(result.out.find("plan will refuse the task's start"), std::string::npos) << result.out;
}

TEST(HostileInput, AUrdfThatIsNotATreeIsRefusedNamingTheJoint) {
  test::TempDir dir;
  // A link with two parents (a kinematic loop back to the base's child).
  auto task = writeTask(
      dir,
      robotUrdf("", "<joint name=\"loop\" type=\"fixed\"><parent link=\"tip\"/><child link=\"upper\"/></joint>\n"));
  expectBadInput(dir, "check " + quoted(task),
                 {"robot.urdf", "link 'upper' already has the parent joint", "kinematic loops"});
  // A joint whose parent is its child.
  task = writeTask(
      dir, robotUrdf("", "<joint name=\"self\" type=\"fixed\"><parent link=\"tip\"/><child link=\"tip\"/></joint>\n"));
  expectBadInput(dir, "check " + quoted(task), {"robot.urdf", "joint[self]", "same link"});
}

TEST(HostileInput, AChainOfTwentyThousandLinksIsRefusedAtOnce) {
  test::TempDir dir;
  std::string links, joints;
  for (int i = 0; i < 20000; ++i) {
    links += "<link name=\"c" + std::to_string(i) + "\"/>\n";
    joints += "<joint name=\"j" + std::to_string(i) + "\" type=\"fixed\"><parent link=\"" +
              (i == 0 ? std::string("tip") : "c" + std::to_string(i - 1)) + "\"/><child link=\"c" + std::to_string(i) +
              "\"/></joint>\n";
  }
  const auto task = writeTask(dir, robotUrdf(links, joints));
  expectBadInput(dir, "check " + quoted(task), {"robot.urdf", "more than 500 links"});
}

TEST(HostileInput, UrdfShapesNeedFinitePositiveSizes) {
  for (const std::string geometry : {"<sphere radius=\"nan\"/>", "<sphere radius=\"-0.1\"/>", "<sphere radius=\"0\"/>",
                                     "<box size=\"0.1 -0.1 0.1\"/>", "<box size=\"nan 0.1 0.1\"/>",
                                     "<cylinder radius=\"inf\" length=\"0.1\"/>", "<sphere radius=\"1e400\"/>"}) {
    test::TempDir dir;
    const auto task = writeTask(dir, robotUrdf("", "", geometry));
    expectBadInput(dir, "check " + quoted(task), {"robot.urdf", "link[tip].collision", "finite"});
  }
}

TEST(HostileInput, UrdfJointNumbersBeyondTheirRangeAreRefused) {
  test::TempDir dir;
  std::string urdf = robotUrdf();
  urdf.replace(urdf.find("upper=\"1\""), 9, "upper=\"1e308\"");
  auto task = writeTask(dir, urdf);
  expectBadInput(dir, "check " + quoted(task), {"robot.urdf", "joint[a].limit"});
  urdf = robotUrdf("<link name=\"m\"/>\n",
                   "<joint name=\"mm\" type=\"revolute\"><parent link=\"tip\"/><child link=\"m\"/><axis xyz=\"1 0 0\"/>"
                   "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/><mimic joint=\"b\" "
                   "multiplier=\"1e300\"/></joint>\n");
  task = writeTask(dir, urdf);
  expectBadInput(dir, "check " + quoted(task), {"robot.urdf", "joint[mm].mimic"});
}

TEST(HostileInput, ToleranceOutsideItsRangeIsRefusedBeforeAnyWork) {
  test::TempDir dir;
  for (const std::string value : {"1e-20", "inf", "1e-12", "1e-300", "nan", "0", "1e6"}) {
    expectBadInput(dir, "check can_on_table --tolerance-mm " + value, {"--tolerance-mm", "0.01 to 100"});
    expectBadInput(dir, "plan can_on_table --time-limit 1 --tolerance-mm " + value, {"--tolerance-mm"});
    expectBadInput(dir, "validate can_on_table never-read.path.json --tolerance-mm " + value, {"--tolerance-mm"});
  }
}

TEST(HostileInput, TimeLimitsAndSeedsOutOfRangeAreRefused) {
  test::TempDir dir;
  for (const std::string value : {"1e10", "1e308", "-1", "nan"})
    expectBadInput(dir, "plan can_on_table --time-limit " + value, {"time-limit"});
  expectBadInput(dir, "bench can_on_table --runs 1 --time-limit 1e308", {"--time-limit"});
  {
    const auto result = runCli(dir, "glove synth --frames 10 --seed -1 -o x.csv");  // CLI11's message and --help hint
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.err.find("--seed: expected a whole number >= 0, got '-1'"), std::string::npos) << result.err;
  }
  // The planner's seed is read by the settings table (planner_setting_table.hpp), in plan and bench alike.
  expectBadInput(dir, "plan can_on_table --seed -1", {"--seed", "'-1' is not a whole number >= 0"});
}

TEST(HostileInput, HugeFrameCountsAndEndlessFilesAreRefused) {
  test::TempDir dir;
  for (const std::string frames : {"10000000", "2147483647"})
    expectBadInput(dir, "glove synth --frames " + frames + " -o " + quoted(dir.path() / "x.csv"),
                   {"--frames", "1000000"});
  expectBadInput(dir, "check /dev/zero", {"/dev/zero", "not a regular file"});  // a device (endless pipes: OutputRule)
  expectBadInput(dir, "synergies /dev/zero --format csv --calibration /dev/zero", {"/dev/zero"});
}

TEST(HostileInput, ATaskWithTwentyThousandObstaclesIsRefused) {
  test::TempDir dir;
  std::string obstacles = "\n";
  for (int i = 0; i < 20000; ++i)
    obstacles += "  - {name: o" + std::to_string(i) + ", sphere: 0.01, xyz: [5, 5, " + std::to_string(i) + "]}\n";
  const auto task = writeTask(dir, robotUrdf(), obstacles);
  expectBadInput(dir, "check " + quoted(task), {"task.yaml", "obstacles", "more than 1000"});
}

TEST(HostileInput, AMeshWithANanVertexIsRefused) {
  test::TempDir dir;
  dir.write("bad.stl",
            "solid s\nfacet normal 0 0 1\n outer loop\n  vertex nan 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n "
            "endloop\nendfacet\nendsolid s\n");
  const auto task = writeTask(dir, robotUrdf(), "[{name: m, mesh: {file: bad.stl}, xyz: [1, 1, 1]}]");
  expectBadInput(dir, "check " + quoted(task), {"bad.stl", "vertex 1", "finite"});
}

TEST(HostileInput, GraspItDimensionsMustBeAWholeNumber) {
  test::TempDir dir;
  const auto xml = dir.write("e.xml",
                             "<EigenGrasps dimensions=\"4.5\">\n<EG><EigenValue value=\"1\"/><DimVals d0=\"1\"/></EG>\n"
                             "<ORIGIN><EigenValue value=\"0\"/><DimVals d0=\"0\"/></ORIGIN>\n</EigenGrasps>\n");
  expectBadInput(dir, "synergies --from-graspit " + quoted(xml) + " --joints index_proximal",
                 {"e.xml", "dimensions", "whole number"});
}

/// The shipped file with its first line matching `key` repeated right after it.
std::filesystem::path withRepeatedKey(const test::TempDir& dir, const std::string& shipped, const std::string& key,
                                      const std::string& name) {
  std::string text = test::contents(std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / shipped);
  const auto at = text.find("\n" + key);
  const auto end = text.find('\n', at + 1);
  text.insert(end + 1, text.substr(at + 1, end - at));
  return dir.write(name, text);
}

TEST(HostileInput, RepeatedKeysInCalibrationMappingAndSynergyFilesAreRefused) {
  test::TempDir dir;
  const auto model = withRepeatedKey(dir, "synergies/sah_tx90_default.yaml", "provenance:", "model.yaml");
  expectBadInput(dir, "synergies --show " + quoted(model), {"model.yaml", "given twice"});
  const auto mapping = withRepeatedKey(dir, "glove/cyberglove22_to_sah.yaml", "description:", "mapping.yaml");
  expectBadInput(dir, "glove synth --frames 10 -o " + quoted(dir.path() / "x.csv") + " --mapping " + quoted(mapping),
                 {"mapping.yaml", "given twice"});
  const auto calibration =
      withRepeatedKey(dir, "glove/synthetic_operator_sample.calibration.yaml", "  ThumbMPJ:", "calibration.yaml");
  expectBadInput(dir,
                 "synergies " +
                     quoted(std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "glove/synthetic_operator_sample.csv") +
                     " --calibration " + quoted(calibration),
                 {"calibration.yaml", "ThumbMPJ", "given twice"});
}

TEST(HostileInput, CoefficientsThatOverflowNeverReachThePca) {
  // A gain and a cross term of opposite signs that both overflow: inf - inf is NaN.
  test::TempDir dir;
  const auto glove = std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "glove";
  std::string calibration = test::contents(glove / "synthetic_operator_sample.calibration.yaml");
  calibration = std::regex_replace(calibration, std::regex("ThumbMPJ: \\{gain: [^,]*,"), "ThumbMPJ: {gain: -1e307,");
  calibration = std::regex_replace(calibration, std::regex("- \\{sensor: ThumbRotate, from: ThumbAb, gain: [^}]*\\}"),
                                   "- {sensor: ThumbMPJ, from: ThumbAb, gain: 1e307}");
  const auto file = dir.write("calibration.yaml", calibration);
  expectBadInput(dir, "synergies " + quoted(glove / "synthetic_operator_sample.csv") + " --calibration " + quoted(file),
                 {"thumb_proximal", "not a finite number"});
}

using test::plannedPath;

TEST(HostileInput, PathFilesWithOverflowingNumbersOrForeignTasksAreBadInput) {
  test::TempDir dir;
  const std::string good = test::contents(plannedPath(dir, "good.path.json"));
  const auto overflow =
      dir.write("overflow.json", std::regex_replace(good, std::regex("\"seed\": *[0-9]+"), "\"seed\": 1e309"));
  expectBadInput(dir, "validate can_on_table " + quoted(overflow), {"overflow.json", "a number is out of range"});
  expectBadInput(dir, "view " + quoted(overflow) + " --out " + quoted(dir.path() / "v"), {"overflow.json"});
  // A path file naming another file as its task: the error never shows that file's contents.
  const auto secret =
      dir.write("secret.txt", "root:x:0:0:the secret line that must not be printed:/root:/bin/bash\nsecond line\n");
  const auto foreign = dir.write("foreign.json", std::regex_replace(good, std::regex("\"task\": *\"[^\"]*\""),
                                                                    "\"task\": \"" + secret.string() + "\""));
  const auto result = runCli(dir, "view " + quoted(foreign) + " --out " + quoted(dir.path() / "v"));
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_EQ(result.err.find("secret line"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("root:x"), std::string::npos) << result.err;
  // A viewer folder where a file is in the way.
  expectBadInput(dir, "view " + quoted(dir.path() / "good.path.json") + " --out " + quoted(secret / "viewer"),
                 {"--out", "cannot create the folder"});
}

}  // namespace
}  // namespace pmdplan
