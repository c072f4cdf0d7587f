// The viewer draws a robot whose visuals are meshes (the toy hand of docs/examples, its STL files
// written by the generator, referenced as package://): chromium through
// viewer/test/mesh_robot_browser_test.mjs, screenshots in build/test-output/mesh-viewer/.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using test::quoted;
using test::runCli;

const std::filesystem::path kMeshViewerSourceTree = std::filesystem::path(PMDPLAN_TEST_DATA_DIR).parent_path();
const std::filesystem::path kMeshViewerBuildDirectory = std::filesystem::path(PMDPLAN_CLI_PATH).parent_path();

int run(const std::string& command) {
  std::cout << "$ " << command << std::endl;
  const int status = std::system((command + " 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(ViewerBrowser, ShowsARobotMadeOfMeshesAndFallsBackToItsCollisionGeometry) {
  ASSERT_TRUE(std::filesystem::exists(kMeshViewerSourceTree / "viewer" / "node_modules" / "playwright-core"))
      << "viewer/node_modules is missing: run scripts/install-deps (npm ci in viewer/)";
  const auto work = kMeshViewerBuildDirectory / "test-output" / "mesh-viewer";
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  ASSERT_EQ(
      run("python3 " + quoted(kMeshViewerSourceTree / "docs" / "examples" / "make_toy_hand.py") + " " + quoted(work)),
      0);
  const std::string packages = " --package-path " + quoted(work);
  ASSERT_EQ(runCli("robot init package://toy_hand/urdf/toy_hand.urdf" + packages +
                   " --arm arm_yaw,arm_shoulder,arm_elbow,arm_wrist --palm palm --samples 1000")
                .exitCode,
            0);
  std::ofstream(work / "task.yaml")
      << "name: toy_reach\nrobot: package://toy_hand/urdf/toy_hand.urdf\nbase: {xyz: [0, 0, 0], rpy_deg: [0, 0, 0]}\n"
         "obstacles:\n  - {name: table, box: [0.3, 0.5, 0.3], xyz: [0.55, 0, 0.15]}\n"
         "start: {joints_deg: {arm_yaw: 0, arm_shoulder: 0, arm_elbow: 0, arm_wrist: 0, thumb_rotate: 0, thumb_flex: "
         "0, "
         "finger1_spread: 0, finger1_flex: 0, finger2_spread: 0, finger2_flex: 0}}\n"
         "goal: {joints_deg: {arm_yaw: 30, arm_shoulder: 35, arm_elbow: 70, arm_wrist: 90, thumb_rotate: 0, "
         "thumb_flex: 20, "
         "finger1_spread: 0, finger1_flex: 20, finger2_spread: 0, finger2_flex: 20}}\n";
  const auto path = work / "toy_reach.path.json";
  const auto planned =
      runCli("plan " + quoted(work / "task.yaml") + packages + " --planner full --time-limit 30 -o " + quoted(path));
  ASSERT_EQ(planned.exitCode, 0) << planned.out << planned.err;
  EXPECT_EQ(run("node " + quoted(kMeshViewerSourceTree / "viewer" / "test" / "mesh_robot_browser_test.mjs") +
                " --cli " + quoted(PMDPLAN_CLI_PATH) + " --path " + quoted(path) + " --task " +
                quoted(work / "task.yaml") + packages + " --work " + quoted(work)),
            0);
  EXPECT_TRUE(std::filesystem::is_regular_file(work / "mesh-robot.png"));
}

}  // namespace
}  // namespace pmdplan
