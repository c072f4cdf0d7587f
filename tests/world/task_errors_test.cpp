// Bad task files: each is one InputError naming the file, the field path, the YAML line where
// there is one, and what was expected.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "toy_task_files.hpp"

namespace pmdplan {
namespace {

using test::kValidToyTask;
using test::lineOf;
using test::replaceOnce;
using test::ToyTaskFolder;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class TaskErrors : public ::testing::Test {
 protected:
  ToyTaskFolder folder;
  std::string text;
  std::filesystem::path path;

  /// Writes `taskText` and returns the error loading it raises (a failure if none).
  InputError errorFor(const std::string& taskText) {
    text = taskText;
    path = folder.write("task.yaml", taskText);
    try {
      loadTask(path);
    } catch (const InputError& error) {
      return error;
    }
    ADD_FAILURE() << "no InputError for:\n" << taskText;
    return InputError("", "", "");
  }

  /// The error names this file, the field path, and the line where `lineText` first appears.
  void expectField(const InputError& error, const std::string& field, const std::string& lineText) {
    EXPECT_EQ(error.file(), path.string());
    const int line = lineOf(text, lineText);
    ASSERT_GT(line, 0) << "'" << lineText << "' not in the task text";
    EXPECT_EQ(error.field(), field + " (line " + std::to_string(line) + ")") << error.what();
    EXPECT_THAT(std::string(error.what()), HasSubstr(path.string()));
  }
};

TEST_F(TaskErrors, UnknownTopLevelKey) {
  const auto error = errorFor(std::string(kValidToyTask) + "colour: red\n");
  expectField(error, "colour", "colour: red");
  EXPECT_THAT(error.message(), HasSubstr("unknown key 'colour'"));
  EXPECT_THAT(error.message(), HasSubstr("obstacles"));  // lists the allowed keys
}

TEST_F(TaskErrors, APregraspNeedsATarget) {
  const std::string withPregrasp =
      std::string(kValidToyTask) + "pregrasp:\n  joints: {wrist: 0.2, shoulder: -0.5, elbow: 1.0}\n";
  const auto error = errorFor(replaceOnce(withPregrasp, "target: can\n", ""));
  expectField(error, "pregrasp", "  joints: {wrist: 0.2, shoulder");
  EXPECT_THAT(error.message(), HasSubstr("target"));
}

TEST_F(TaskErrors, APregraspIsAConfigurationLikeTheGoal) {
  const auto error = errorFor(std::string(kValidToyTask) + "pregrasp:\n  joints: {wrist: 0.2, shoulder: -0.5}\n");
  EXPECT_THAT(error.field(), StartsWith("pregrasp"));
  EXPECT_THAT(error.message(), HasSubstr("elbow"));
}

TEST_F(TaskErrors, UnknownKeyInBase) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "rpy_deg: [0, 0, 90]}", "rpy: [0, 0, 90]}"));
  expectField(error, "base.rpy", "base:");
  EXPECT_THAT(error.message(), HasSubstr("rpy_deg"));
}

TEST_F(TaskErrors, UnknownKeyInCylinder) {
  const auto error =
      errorFor(replaceOnce(kValidToyTask, "      length: 0.12\n", "      length: 0.12\n      height: 0.12\n"));
  expectField(error, "obstacles[1].cylinder.height", "height:");
}

TEST_F(TaskErrors, UnknownKeyInStart) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "start:\n  joints_deg:", "start:\n  joint_deg:"));
  expectField(error, "start.joint_deg", "joint_deg:");
  EXPECT_THAT(error.message(), HasSubstr("joints_deg"));
}

TEST_F(TaskErrors, RepeatedTopLevelKey) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "target: can\n", "target: can\ntarget: ball\n"));
  expectField(error, "target", "target: ball");
  EXPECT_THAT(error.message(), HasSubstr("first on line " + std::to_string(lineOf(text, "target: can"))));
}

TEST_F(TaskErrors, UnknownObstacleType) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "sphere: 0.05", "cone: 0.05"));
  expectField(error, "obstacles[2].cone", "cone:");
  EXPECT_THAT(error.message(), HasSubstr("unknown obstacle type or key 'cone'"));
  EXPECT_THAT(error.message(), HasSubstr("box"));
  EXPECT_THAT(error.message(), HasSubstr("cylinder"));
}

TEST_F(TaskErrors, ObstacleWithoutShape) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "sphere: 0.05, ", ""));
  expectField(error, "obstacles[2]", "{name: ball");
  EXPECT_THAT(error.message(), HasSubstr("no shape"));
}

TEST_F(TaskErrors, ObstacleWithTwoShapes) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "sphere: 0.05,", "sphere: 0.05, box: [1, 1, 1],"));
  EXPECT_EQ(error.file(), path.string());
  EXPECT_THAT(error.field(), StartsWith("obstacles[2]."));
  EXPECT_THAT(error.message(), HasSubstr("exactly one shape"));
}

TEST_F(TaskErrors, MissingJoint) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "    wrist: -30\n", ""));
  expectField(error, "start.joints_deg", "    shoulder: 10");
  EXPECT_THAT(error.message(), HasSubstr("missing joint wrist"));
}

TEST_F(TaskErrors, DuplicatedJoint) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "    wrist: -30\n", "    wrist: -30\n    elbow: 25\n"));
  expectField(error, "start.joints_deg.elbow", "    elbow: 25");
  EXPECT_THAT(error.message(), HasSubstr("first on line " + std::to_string(lineOf(text, "    elbow: 20"))));
}

TEST_F(TaskErrors, DuplicatedJointInFlowMap) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "elbow: 1.0}", "elbow: 1.0, wrist: 0.1}"));
  EXPECT_EQ(error.file(), path.string());
  EXPECT_THAT(error.field(), StartsWith("goal.joints.wrist (line "));
}

TEST_F(TaskErrors, UnknownJointName) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "wrist: 0.25", "knee: 0.25"));
  expectField(error, "goal.joints.knee", "  joints: {");
  EXPECT_THAT(error.message(), HasSubstr("unknown joint 'knee'"));
  EXPECT_THAT(error.message(), HasSubstr("shoulder, elbow, wrist"));
}

TEST_F(TaskErrors, MimicJointIsNotAConfigurationValue) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "    wrist: -30\n", "    wrist: -30\n    tip: -30\n"));
  expectField(error, "start.joints_deg.tip", "    tip: -30");
  EXPECT_THAT(error.message(), HasSubstr("mimic"));
}

TEST_F(TaskErrors, FixedJointIsNotAConfigurationValue) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "    wrist: -30\n", "    wrist: -30\n    mount: 0\n"));
  expectField(error, "start.joints_deg.mount", "    mount: 0");
  EXPECT_THAT(error.message(), HasSubstr("fixed"));
}

TEST_F(TaskErrors, ValueAboveTheLimitInDegrees) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "elbow: 20", "elbow: 120.001"));
  expectField(error, "start.joints_deg.elbow", "elbow: 120.001");
  EXPECT_THAT(error.message(), HasSubstr("outside the joint limits -30 .. 120 deg"));
}

TEST_F(TaskErrors, ValueBelowTheLimitInRadians) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "shoulder: -0.5", "shoulder: -1.6"));
  expectField(error, "goal.joints.shoulder", "  joints: {");
  EXPECT_THAT(error.message(), HasSubstr("rad"));
}

TEST_F(TaskErrors, NotANumber) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "elbow: 20", "elbow: .nan"));
  expectField(error, "start.joints_deg.elbow", "elbow: .nan");
  EXPECT_THAT(error.message(), HasSubstr("not a finite number"));
}

TEST_F(TaskErrors, Infinity) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "xyz: [1.0, 0.0, 0.15]", "xyz: [1.0, -.inf, 0.15]"));
  expectField(error, "obstacles[0].xyz[1]", "{name: table");
  EXPECT_THAT(error.message(), HasSubstr("not a finite number"));
}

TEST_F(TaskErrors, NumberTooLargeForADouble) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "sphere: 0.05", "sphere: 1e999"));
  expectField(error, "obstacles[2].sphere", "{name: ball");
  EXPECT_THAT(error.message(), HasSubstr("out of range"));
}

TEST_F(TaskErrors, WordWhereANumberBelongs) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "wrist: -30", "wrist: left"));
  expectField(error, "start.joints_deg.wrist", "wrist: left");
  EXPECT_THAT(error.message(), HasSubstr("'left'"));
}

TEST_F(TaskErrors, QuotedNumberIsAString) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "radius: 0.03", "radius: \"0.03\""));
  expectField(error, "obstacles[1].cylinder.radius", "radius:");
  EXPECT_THAT(error.message(), HasSubstr("quoted string"));
}

TEST_F(TaskErrors, ListWhereANumberBelongs) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "shoulder: 10", "shoulder: [10]"));
  expectField(error, "start.joints_deg.shoulder", "shoulder: [10]");
  EXPECT_THAT(error.message(), HasSubstr("a list"));
}

TEST_F(TaskErrors, MissingMeshFile) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "meshes/part.stl", "meshes/missing.stl"));
  expectField(error, "obstacles[3].mesh.file", "mesh: {file");
  EXPECT_THAT(error.message(), HasSubstr((folder.directory() / "meshes/missing.stl").string()));
}

TEST_F(TaskErrors, DuplicateObstacleNames) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "name: ball", "name: table"));
  expectField(error, "obstacles[2].name", "{name: table, sphere");
  EXPECT_THAT(error.message(), HasSubstr("obstacles[0]"));
}

TEST_F(TaskErrors, TargetNamesNoObstacle) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "target: can", "target: mug"));
  expectField(error, "target", "target: mug");
  EXPECT_THAT(error.message(), HasSubstr("table, can, ball, part"));
}

TEST_F(TaskErrors, PositionWithTwoValues) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "xyz: [0, 0, 1]", "xyz: [0, 0]"));
  expectField(error, "obstacles[2].xyz", "{name: ball");
  EXPECT_THAT(error.message(), HasSubstr("need exactly 3"));
}

TEST_F(TaskErrors, BoxWithFourValues) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "box: [0.5, 0.4, 0.3]", "box: [0.5, 0.4, 0.3, 0.2]"));
  expectField(error, "obstacles[0].box", "{name: table");
  EXPECT_THAT(error.message(), HasSubstr("list of 4 values"));
}

TEST_F(TaskErrors, RollPitchYawWithTwoValues) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "rpy_deg: [0, 0, 90]", "rpy_deg: [0, 90]"));
  expectField(error, "base.rpy_deg", "base:");
}

TEST_F(TaskErrors, NegativeCylinderRadius) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "radius: 0.03", "radius: -0.03"));
  expectField(error, "obstacles[1].cylinder.radius", "radius: -0.03");
  EXPECT_THAT(error.message(), HasSubstr("greater than 0"));
}

TEST_F(TaskErrors, ZeroBoxSide) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "box: [0.5, 0.4, 0.3]", "box: [0.5, 0, 0.3]"));
  expectField(error, "obstacles[0].box[1]", "{name: table");
}

TEST_F(TaskErrors, ZeroSphereRadius) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "sphere: 0.05", "sphere: 0"));
  expectField(error, "obstacles[2].sphere", "{name: ball");
}

TEST_F(TaskErrors, NegativeMeshScale) {
  const auto error =
      errorFor(replaceOnce(kValidToyTask, "scale: [0.001, 0.002, 0.003]", "scale: [0.001, -0.002, 0.003]"));
  expectField(error, "obstacles[3].mesh.scale[1]", "mesh: {file");
}

TEST_F(TaskErrors, MissingCylinderLength) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "      length: 0.12\n", ""));
  expectField(error, "obstacles[1].cylinder.length", "radius: 0.03");
  EXPECT_THAT(error.message(), HasSubstr("missing"));
}

TEST_F(TaskErrors, MissingRequiredTopLevelKey) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "name: toy_task\n", ""));
  expectField(error, "name", "description:");
  EXPECT_THAT(error.message(), HasSubstr("missing"));
}

TEST_F(TaskErrors, BothJointsAndJointsDeg) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "goal:\n  joints: {",
                                          "goal:\n  joints_deg: {shoulder: 1, elbow: 1, wrist: 1}\n  joints: {"));
  expectField(error, "goal.joints", "  joints: {");
  EXPECT_THAT(error.message(), HasSubstr("either"));
}

TEST_F(TaskErrors, PrismaticJointInDegrees) {
  folder.write("slider.urdf", R"(<?xml version="1.0"?>
<robot name="slider">
  <link name="rail"/><link name="carriage"/>
  <joint name="slide" type="prismatic"><parent link="rail"/><child link="carriage"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
</robot>
)");
  const auto error = errorFor(
      "name: slide\nrobot: slider.urdf\nbase: {xyz: [0, 0, 0]}\nobstacles: []\n"
      "start: {joints: {slide: 0.1}}\ngoal: {joints_deg: {slide: 10}}\n");
  expectField(error, "goal.joints_deg.slide", "goal:");
  EXPECT_THAT(error.message(), HasSubstr("metres"));
}

TEST_F(TaskErrors, YamlSyntaxError) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "xyz: [0, 0, 1]}", "xyz: [0, 0, 1}"));
  EXPECT_EQ(error.file(), path.string());
  EXPECT_THAT(error.field(), StartsWith("line "));
  EXPECT_THAT(error.message(), HasSubstr("YAML syntax error"));
}

TEST_F(TaskErrors, DocumentIsNotAMap) {
  const auto error = errorFor("- just\n- a list\n");
  expectField(error, "document", "- just");
}

TEST_F(TaskErrors, UnknownBuiltInRobot) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "robot: toy.urdf", "robot: no_such_robot"));
  expectField(error, "robot", "robot:");
  EXPECT_THAT(error.message(), HasSubstr("unknown built-in robot 'no_such_robot'"));
}

TEST_F(TaskErrors, MissingUrdfFile) {
  const auto error = errorFor(replaceOnce(kValidToyTask, "robot: toy.urdf", "robot: robots/gone.urdf"));
  expectField(error, "robot", "robot:");
  EXPECT_THAT(error.message(), HasSubstr("URDF file not found"));
}

TEST_F(TaskErrors, MalformedUrdfIsReportedAgainstTheUrdf) {
  const auto urdf = folder.write("broken.urdf", "<robot name=\"broken\"><link name=\"a\"></robot>");
  try {
    loadTask(folder.write("task.yaml", replaceOnce(kValidToyTask, "robot: toy.urdf", "robot: broken.urdf")));
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::filesystem::path(error.file()), urdf);
  }
}

TEST_F(TaskErrors, MissingTaskFile) {
  const auto missing = folder.directory() / "absent.yaml";
  try {
    loadTask(missing);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr(missing.string()));
  }
}

TEST_F(TaskErrors, UnknownTaskName) { EXPECT_THROW(loadTaskByName("no_such_task"), InputError); }

}  // namespace
}  // namespace pmdplan
