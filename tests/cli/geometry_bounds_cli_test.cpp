// Hostile geometry through the real binary: obstacle and URDF shapes beyond the bounds, hostile mesh
// files (an instance_node cycle, a FIFO), xacro left in a URDF, task names that are not plain. Each
// ends in exit 2 with one line naming the file and the field, in bounded time; shapes at the
// largest allowed size are checked, planned and validated by both checkers without a signal,
// exit 3 or hang.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::contents;
using test::quoted;

/// Runs the binary under `timeout 30` (a hang fails the test instead of stalling it).
test::CliResult runGeometryCli(const test::TempDir& dir, const std::string& arguments) {
  const auto out = dir.path() / "stdout.txt";
  const auto err = dir.path() / "stderr.txt";
  const std::string command = "timeout -s KILL 30 " + quoted(PMDPLAN_CLI_PATH) + " " + arguments + " >" + quoted(out) +
                              " 2>" + quoted(err) + " </dev/null";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, contents(out), contents(err)};
}

void expectGeometryBadInput(const test::TempDir& dir, const std::string& arguments,
                            const std::vector<std::string>& expected) {
  const auto began = std::chrono::steady_clock::now();
  const auto result = runGeometryCli(dir, arguments);
  EXPECT_EQ(result.exitCode, 2) << arguments << "\n" << result.err;
  EXPECT_EQ(result.err.rfind("pmdplan: error: ", 0), 0u) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_EQ(result.err.find('\x1b'), std::string::npos) << result.err;
  for (const auto& text : expected) EXPECT_NE(result.err.find(text), std::string::npos) << text << "\n" << result.err;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count(), 10.0) << arguments;
}

const std::string kGeometryToySrdf =
    "<robot name=\"r\"><group name=\"arm\"><joint name=\"a\"/></group><group name=\"hand\"><joint name=\"b\"/></group>"
    "<end_effector name=\"e\" parent_link=\"upper\" group=\"hand\"/></robot>\n";

/// A two-joint robot whose tip holds `tipGeometry`.
std::string geometryRobotUrdf(const std::string& tipGeometry) {
  return "<robot name=\"r\">\n<link name=\"base\"><collision><geometry><box size=\"0.1 0.1 "
         "0.1\"/></geometry></collision>"
         "</link>\n<link name=\"upper\"><collision><origin xyz=\"0 0 0.1\"/><geometry><cylinder radius=\"0.02\" "
         "length=\"0.2\"/></geometry></collision></link>\n<link name=\"tip\"><collision><geometry>" +
         tipGeometry +
         "</geometry></collision></link>\n<joint name=\"a\" type=\"revolute\"><parent link=\"base\"/><child "
         "link=\"upper\"/><origin xyz=\"0 0 0.05\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
         "velocity=\"1\"/></joint>\n<joint name=\"b\" type=\"revolute\"><parent link=\"upper\"/><child link=\"tip\"/>"
         "<origin xyz=\"0 0 0.2\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
         "</joint>\n</robot>\n";
}

std::filesystem::path geometryToyTask(const test::TempDir& dir, const std::string& obstacles,
                                      const std::string& tip = "<sphere radius=\"0.02\"/>",
                                      const std::string& name = "t") {
  dir.write("robot.urdf", geometryRobotUrdf(tip));
  dir.write("robot.srdf", kGeometryToySrdf);
  return dir.write("task.yaml", "name: " + name +
                                    "\nrobot: robot.urdf\nbase: {xyz: [0, 0, 0], rpy_deg: [0, 0, 0]}\nobstacles: " +
                                    obstacles + "\nstart: {joints: {a: 0, b: 0}}\ngoal: {joints: {a: 0.5, b: 0.5}}\n");
}

TEST(GeometryBoundsCli, ObstacleSizesWithoutBoundAreBadInput) {
  test::TempDir dir;
  for (const std::string obstacle :
       {"box: [1e300, 1e300, 1e300], xyz: [0, 0, 0]", "sphere: 1e300, xyz: [0, 0, 0]",
        "sphere: 1e20, xyz: [1e20, 0, 0]", "box: [1e10, 1e10, 1e10], xyz: [5000000000.3, 0, 0]",
        "box: [0.1, 0.1, 0.1], xyz: [1e300, 0, 0]"}) {
    const auto task = geometryToyTask(dir, "[{name: o, " + obstacle + "}]");
    expectGeometryBadInput(dir, "check " + quoted(task), {"task.yaml: obstacles[0].", "(line 4)", "expected a"});
    expectGeometryBadInput(dir, "plan " + quoted(task) + " -o " + quoted(dir.path() / "p.json"), {"obstacles[0]."});
  }
}

TEST(GeometryBoundsCli, AUrdfBoxWithoutBoundIsBadInputNotABug) {
  test::TempDir dir;
  const auto task = geometryToyTask(dir, "[]", "<box size=\"1e300 1e300 1e300\"/>");
  // It ended in exit 3 ("a mesh whose triangles were not read").
  expectGeometryBadInput(dir, "check " + quoted(task),
                         {"robot.urdf: link[tip].collision[0].box[0]", "from 1e-06 to 100"});
}

TEST(GeometryBoundsCli, ShapesAtTheLargestAllowedSizeAreCheckedPlannedAndValidated) {
  test::TempDir dir;
  std::string text = contents(std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "scenes" / "can_on_table.yaml");
  const std::string big =
      "obstacles:\n"
      "  - {name: big_floor, box: [100, 100, 100], xyz: [0, 0, -50.03]}\n"
      "  - {name: big_ball, sphere: 100, xyz: [0, -101.2, 0.5]}\n"
      "  - {name: big_drum, cylinder: {radius: 100, length: 100}, xyz: [-101.0, 0, 0.5]}\n"
      "  - {name: far_box, box: [100, 100, 100], xyz: [1000, -1000, 1000]}\n"
      "  - {name: speck, sphere: 0.000001, xyz: [0.3, 0.3, 1.5]}\n";
  text.replace(text.find("obstacles:\n"), std::string("obstacles:\n").size(), big);
  const auto task = dir.write("big.yaml", text);
  auto result = runGeometryCli(dir, "check " + quoted(task));
  EXPECT_EQ(result.exitCode, 0) << result.err;
  for (const std::string checker : {"fast", "exact"}) {
    const auto path = dir.path() / (checker + ".json");
    result =
        runGeometryCli(dir, "plan " + quoted(task) + " --checker " + checker + " --time-limit 5 -o " + quoted(path));
    EXPECT_TRUE(result.exitCode == 0 || result.exitCode == 1) << checker << " " << result.exitCode << "\n"
                                                              << result.err;
    if (result.exitCode != 0) continue;
    result = runGeometryCli(dir, "validate " + quoted(task) + " " + quoted(path));
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
  }
  // The floor raised 4 cm into the robot's base: a collision with its true depth, not a crash.
  text.replace(text.find("-50.03"), 6, "-49.99");
  result = runGeometryCli(dir, "check " + quoted(dir.write("into.yaml", text)));
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_NE(result.out.find("penetration 10.00 mm (tx90_base_link - big_floor)"), std::string::npos) << result.out;
}

TEST(GeometryBoundsCli, AColladaInstanceCycleAndAFifoMeshAreBadInput) {
  test::TempDir dir;
  dir.write("cycle.dae",
            R"(<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 0.01 0 0 0 0.01 0</float_array>
<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries>
<library_nodes><node id="a"><instance_node url="#b"/><instance_geometry url="#g"/></node><node id="b"><instance_node url="#a"/></node></library_nodes>
<library_visual_scenes><visual_scene id="s"><node id="root"><instance_node url="#a"/></node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>
)");
  // It ended in SIGSEGV (assimp recursing through the cycle), as a robot's link and as an obstacle.
  auto task = geometryToyTask(dir, "[]", "<mesh filename=\"cycle.dae\"/>");
  expectGeometryBadInput(dir, "check " + quoted(task), {"cycle.dae: node 'a'", "cycle"});
  task = geometryToyTask(dir, "[{name: m, mesh: {file: cycle.dae}, xyz: [1, 1, 1]}]");
  expectGeometryBadInput(dir, "check " + quoted(task), {"cycle.dae: node 'a'", "cycle"});
  // A FIFO nobody writes to: refused at once, never waited on.
  ASSERT_EQ(::mkfifo((dir.path() / "pipe.stl").c_str(), 0600), 0);
  task = geometryToyTask(dir, "[{name: m, mesh: {file: pipe.stl}, xyz: [1, 1, 1]}]");
  expectGeometryBadInput(dir, "check " + quoted(task), {"pipe.stl: mesh", "not a regular file"});
}

TEST(GeometryBoundsCli, XacroInAUrdfIsBadInputNamingTheElement) {
  test::TempDir dir;
  const auto task = geometryToyTask(dir, "[]", "<sphere radius=\"${tip_radius}\"/>");
  expectGeometryBadInput(dir, "check " + quoted(task), {"robot.urdf: line 4, <sphere radius>", "run xacro first"});
}

TEST(GeometryBoundsCli, ATaskNameThatIsNotPlainIsBadInputShownEscaped) {
  test::TempDir dir;
  for (const std::string name : {"\"\\e]0;owned\\a\\e[2J\"", "../../../tmp/x", "/tmp/absolute"}) {
    const auto task = geometryToyTask(dir, "[]", "<sphere radius=\"0.02\"/>", name);
    expectGeometryBadInput(dir, "check " + quoted(task), {"task.yaml: name (line 1)", "expected a plain task name"});
    expectGeometryBadInput(dir, "plan " + quoted(task), {"task.yaml: name (line 1)"});
  }
}

}  // namespace
}  // namespace pmdplan
