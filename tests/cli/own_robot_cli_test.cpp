// A user's own robot through the real binary: the toy hand of docs/examples/make_toy_hand.py as a
// ROS-style package (package:// paths), its SRDF from `pmdplan robot init`, a hand alone and a robot
// whose second arm and head the task holds still.
#include <gtest/gtest.h>

#include <cstdlib>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::contents;
using test::quoted;
using test::runCli;
using test::TempDir;

const std::filesystem::path kSourceDir = std::filesystem::path(PMDPLAN_TEST_DATA_DIR).parent_path();

void makeToyHand(const TempDir& dir, const std::string& options) {
  const std::string command = "python3 " + quoted(kSourceDir / "docs" / "examples" / "make_toy_hand.py") + " " +
                              quoted(dir.path()) + " " + options;
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
}

constexpr const char* kArmJoints = "arm_yaw,arm_shoulder,arm_elbow,arm_wrist";
constexpr const char* kHandZero =
    "thumb_rotate: 0, thumb_flex: 0, finger1_spread: 0, finger1_flex: 0, finger2_spread: 0, finger2_flex: 0";

std::string armTask(const std::string& robot, const std::string& fixed) {
  return "name: toy_can\nrobot: " + robot + "\nbase: {xyz: [0, 0, 0], rpy_deg: [0, 0, 0]}\n" + fixed +
         "target: can\nobstacles:\n"
         "  - {name: table, box: [0.3, 0.5, 0.3], xyz: [0.55, 0, 0.15]}\n"
         "  - {name: lamp, sphere: 0.05, xyz: [0.3, 0.0, 0.74]}\n"
         "  - {name: can, cylinder: {radius: 0.02, length: 0.1}, xyz: [0.5, -0.005, 0.35]}\n"
         "start: {joints_deg: {arm_yaw: 0, arm_shoulder: 0, arm_elbow: 0, arm_wrist: 0, " +
         kHandZero +
         "}}\n"
         "goal: {joints_deg: {arm_yaw: 0, arm_shoulder: 35, arm_elbow: 70, arm_wrist: 90, thumb_rotate: 0, "
         "thumb_flex: 20, finger1_spread: 0, finger1_flex: 20, finger2_spread: 0, finger2_flex: 20}}\n";
}

/// robot init, synergies from postures, plan (the straight segment is blocked by the lamp), validate.
void planAndValidate(const TempDir& dir, const std::filesystem::path& task, const std::string& packagePath) {
  const auto synergies = runCli(dir, "synergies --postures " + quoted(dir.path() / "toy_hand_postures.csv") +
                                         " --robot " + quoted(dir.path() / "toy_hand/urdf/toy_hand.urdf") +
                                         " --own-axis thumb_rotate -o " + quoted(dir.path() / "toy.yaml"));
  ASSERT_EQ(synergies.exitCode, 0) << synergies.err;
  const auto check = runCli(dir, "check " + quoted(task) + packagePath);
  ASSERT_EQ(check.exitCode, 0) << check.err;
  EXPECT_NE(check.out.find("straight segment start -> goal: in collision"), std::string::npos) << check.out;
  const auto path = dir.path() / "toy.path.json";
  const auto plan = runCli(dir, "plan " + quoted(task) + packagePath + " --synergies " +
                                    quoted(dir.path() / "toy.yaml") + " --time-limit 60 -o " + quoted(path));
  ASSERT_EQ(plan.exitCode, 0) << plan.out << plan.err;
  const auto validate = runCli(dir, "validate " + quoted(task) + " " + quoted(path) + packagePath);
  EXPECT_EQ(validate.exitCode, 0) << validate.out << validate.err;
}

TEST(OwnRobotCli, RobotInitWritesWellFormedSrdfWithTheHomePoseFree) {
  const TempDir dir;
  makeToyHand(dir, "--relative-meshes");
  const auto urdf = dir.path() / "toy_hand/urdf/toy_hand.urdf";
  const auto srdf = dir.path() / "toy.srdf";
  const auto init = runCli(
      dir, "robot init " + quoted(urdf) + " --arm " + kArmJoints + " --palm palm --samples 3000 -o " + quoted(srdf));
  ASSERT_EQ(init.exitCode, 0) << init.err;
  EXPECT_NE(init.out.find("home pose free"), std::string::npos) << init.out;
  // Python's ElementTree must parse it; the wrist camera touches the palm at home only: Default.
  const std::string python =
      "python3 -c \"import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); "
      "print(sorted(g.get('name') for g in r.iter('group'))); "
      "print([(d.get('link1'), d.get('link2')) for d in r.iter('disable_collisions') if d.get('reason') == "
      "'Default'])\" " +
      quoted(srdf) + " > " + quoted(dir.path() / "parsed.txt");
  ASSERT_EQ(std::system(python.c_str()), 0) << contents(srdf);
  const std::string parsed = contents(dir.path() / "parsed.txt");
  EXPECT_NE(parsed.find("['arm', 'hand']"), std::string::npos) << parsed;
  EXPECT_NE(parsed.find("('arm_camera', 'palm')"), std::string::npos) << parsed;
  // With the SRDF beside the URDF the home pose checks free (the camera-palm contact is skipped).
  std::filesystem::copy_file(srdf, dir.path() / "toy_hand/urdf/toy_hand.srdf");
  const auto task = dir.write("home.yaml", armTask("toy_hand/urdf/toy_hand.urdf", ""));
  const auto check = runCli(dir, "check " + quoted(task) + " --json");
  ASSERT_EQ(check.exitCode, 0) << check.err;
  EXPECT_NE(check.out.find("\"valid\": true"), std::string::npos) << check.out;
}

TEST(OwnRobotCli, CollisionPairsOutputIsWellFormedXml) {
  const TempDir dir;
  makeToyHand(dir, "--relative-meshes");
  const auto urdf = dir.path() / "toy_hand/urdf/toy_hand.urdf";
  ASSERT_EQ(runCli(dir, "robot init " + quoted(urdf) + " --arm " + kArmJoints + " --palm palm --samples 500").exitCode,
            0);
  const auto pairs = runCli(dir, "collision-pairs " + quoted(urdf) + " --samples 500 --seed 2");
  ASSERT_EQ(pairs.exitCode, 0) << pairs.err;
  const std::string python = "python3 -c \"import sys, xml.etree.ElementTree as E; E.parse(sys.argv[1])\" " +
                             quoted(dir.path() / "toy_hand/urdf/toy_hand.srdf");
  EXPECT_EQ(std::system(python.c_str()), 0) << contents(dir.path() / "toy_hand/urdf/toy_hand.srdf");
}

TEST(OwnRobotCli, WithoutAnSrdfTheErrorNamesRobotInit) {
  const TempDir dir;
  makeToyHand(dir, "--relative-meshes");
  const auto task = dir.write("task.yaml", armTask("toy_hand/urdf/toy_hand.urdf", ""));
  const auto plan = runCli(dir, "plan " + quoted(task) + " --planner full --time-limit 5");
  EXPECT_EQ(plan.exitCode, 2);
  EXPECT_NE(plan.err.find("pmdplan robot init"), std::string::npos) << plan.err;
  const auto pairs = runCli(dir, "collision-pairs " + quoted(dir.path() / "toy_hand/urdf/toy_hand.urdf"));
  EXPECT_EQ(pairs.exitCode, 2);
  EXPECT_NE(pairs.err.find("pmdplan robot init"), std::string::npos) << pairs.err;
}

TEST(OwnRobotCli, PackageUrdfPlansThroughTheSearchPathAndItsEnvironmentVariable) {
  const TempDir dir;
  makeToyHand(dir, "--postures 300");
  const auto init = runCli(dir, "robot init package://toy_hand/urdf/toy_hand.urdf --package-path " +
                                    quoted(dir.path()) + " --arm " + kArmJoints + " --palm palm --samples 3000");
  ASSERT_EQ(init.exitCode, 0) << init.err;
  const auto task = dir.write("task.yaml", armTask("package://toy_hand/urdf/toy_hand.urdf", ""));
  // Without a search path: the error names the task, the field and the (empty) path tried.
  const auto missing = runCli(dir, "check " + quoted(task));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find("no package 'toy_hand' in the package search path"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("--package-path"), std::string::npos) << missing.err;
  planAndValidate(dir, task, " --package-path /nonexistent:" + quoted(dir.path()));
  ::setenv("PMDPLAN_PACKAGE_PATH", dir.path().c_str(), 1);
  const auto viaEnvironment = runCli(dir, "check " + quoted(task));
  ::unsetenv("PMDPLAN_PACKAGE_PATH");
  EXPECT_EQ(viaEnvironment.exitCode, 0) << viaEnvironment.err;
}

TEST(OwnRobotCli, AHandAlonePlansAroundAnObstacle) {
  const TempDir dir;
  makeToyHand(dir, "--hand-only --relative-meshes --postures 300");
  const auto urdf = dir.path() / "toy_hand/urdf/toy_hand.urdf";
  const auto init = runCli(dir, "robot init " + quoted(urdf) + " --palm palm --samples 3000");
  ASSERT_EQ(init.exitCode, 0) << init.err;
  EXPECT_NE(init.out.find("groups hand (9 joints)"), std::string::npos) << init.out;
  const auto task = dir.write(
      "task.yaml",
      std::string(
          "name: toy_hand_alone\nrobot: toy_hand/urdf/toy_hand.urdf\nbase: {xyz: [0, 0, 0.5], rpy_deg: [0, 0, 0]}\n"
          "obstacles:\n  - {name: ball, sphere: 0.004, xyz: [0.0166, 0.0263, 0.612]}\n"
          "start: {joints_deg: {") +
          kHandZero +
          "}}\n"
          "goal: {joints_deg: {thumb_rotate: 30, thumb_flex: 5, finger1_spread: -10, finger1_flex: 15, "
          "finger2_spread: 10, finger2_flex: 15}}\n");
  planAndValidate(dir, task, "");
}

TEST(OwnRobotCli, HeldJointsStayWhereTheTaskPutsThem) {
  const TempDir dir;
  makeToyHand(dir, "--extra-arm --relative-meshes --postures 300");
  const auto urdf = dir.path() / "toy_hand/urdf/toy_hand.urdf";
  const auto init = runCli(dir, "robot init " + quoted(urdf) + " --arm " + kArmJoints + " --palm palm --samples 3000");
  ASSERT_EQ(init.exitCode, 0) << init.err;
  EXPECT_NE(init.out.find("joints in no group"), std::string::npos) << init.out;
  const std::string robot = "toy_hand/urdf/toy_hand.urdf";
  // Without `fixed:` the spare arm's joints are in no group: the error says how to hold them.
  const auto unheld =
      runCli(dir, "plan " + quoted(dir.write("unheld.yaml", armTask(robot, ""))) + " --planner full --time-limit 5");
  EXPECT_EQ(unheld.exitCode, 2);
  EXPECT_NE(unheld.err.find("fixed:"), std::string::npos) << unheld.err;
  // Held reaching into the planned arm: the start is in collision with the spare arm.
  const auto blocking = dir.write("blocking.yaml", armTask(robot,
                                                           "fixed: {joints_deg: {spare_yaw: 90, spare_shoulder: 60, "
                                                           "spare_elbow: 30, spare_wrist: 0, head_pan: 0}}\n"));
  const auto blocked = runCli(dir, "check " + quoted(blocking));
  ASSERT_EQ(blocked.exitCode, 1) << blocked.err << "check says plan will refuse the task";
  EXPECT_NE(blocked.out.find("start  IN COLLISION"), std::string::npos) << blocked.out;
  EXPECT_NE(blocked.out.find("spare_"), std::string::npos) << blocked.out;
  EXPECT_NE(blocked.out.find("plan will refuse the task's start: the start configuration is in collision"),
            std::string::npos)
      << blocked.out;
  const auto held = dir.write("held.yaml", armTask(robot,
                                                   "fixed: {joints_deg: {spare_yaw: 0, spare_shoulder: 30, "
                                                   "spare_elbow: 45, spare_wrist: 0, head_pan: 20}}\n"));
  planAndValidate(dir, held, "");
  EXPECT_EQ(contents(dir.path() / "toy.path.json").find("spare_"), std::string::npos);
  // The viewer poses the held joints where the task holds them and gets the robot's meshes.
  const auto view = runCli(dir, "view " + quoted(dir.path() / "toy.path.json") + " --task " + quoted(held) + " --out " +
                                    quoted(dir.path() / "viewer"));
  ASSERT_EQ(view.exitCode, 0) << view.err;
  const std::string data = contents(dir.path() / "viewer" / "viewer-data.js");
  const auto heldAt = data.find("\"held_joints\"");
  ASSERT_NE(heldAt, std::string::npos);
  EXPECT_NE(data.find("\"spare_shoulder\": 0.5235987755982", heldAt), std::string::npos);
  EXPECT_NE(data.find("\"../meshes/spare_link2.stl\": \"robot-meshes/"), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_directory(dir.path() / "viewer" / "robot-meshes"));
}

TEST(OwnRobotCli, PostureCsvErrorsNameTheFileTheLineAndTheFix) {
  const TempDir dir;
  makeToyHand(dir, "--hand-only --relative-meshes --postures 50");
  const auto urdf = dir.path() / "toy_hand/urdf/toy_hand.urdf";
  ASSERT_EQ(runCli(dir, "robot init " + quoted(urdf) + " --palm palm --samples 200").exitCode, 0);
  const std::string robot = " --robot " + quoted(urdf);
  const auto noColumn =
      runCli(dir, "synergies --postures " + quoted(dir.write("a.csv", "thumb_rotate,thumb_flex\n1,2\n")) + robot);
  EXPECT_EQ(noColumn.exitCode, 2);
  EXPECT_NE(noColumn.err.find("a.csv: line 1: no column for hand joint 'finger1_spread'"), std::string::npos)
      << noColumn.err;
  const std::string header = "thumb_rotate,thumb_flex,finger1_spread,finger1_flex,finger2_spread,finger2_flex\n";
  const auto outside = runCli(
      dir, "synergies --postures " + quoted(dir.write("b.csv", header + "0,0,0,0,0,0\n0,120,0,0,0,0\n")) + robot);
  EXPECT_EQ(outside.exitCode, 2);
  EXPECT_NE(outside.err.find("b.csv: line 3, column thumb_flex: 120 deg is outside the joint limits 0 .. 90 deg"),
            std::string::npos)
      << outside.err;
  // No own-axis joint named: the output says which option picks one.
  const auto fitted = runCli(dir, "synergies --postures " + quoted(dir.path() / "toy_hand_postures.csv") + robot);
  ASSERT_EQ(fitted.exitCode, 0) << fitted.err;
  EXPECT_NE(fitted.out.find("--own-axis JOINT"), std::string::npos) << fitted.out;
}

}  // namespace
}  // namespace pmdplan
