#include "pmdplan/model/robot_model.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

std::string toyUrdf(const std::string& extraJoints = "", const std::string& mimic = "") {
  return R"(<?xml version="1.0"?>
<robot name="toy">
  <link name="base"/>
  <link name="upper"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <link name="lower"/>
  <link name="tip"/>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.5" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="2" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="lower"/>
    <origin xyz="1 0 0" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="wrist" type="revolute"><parent link="lower"/><child link="tip"/>
    <origin xyz="0.5 0 0" rpy="0 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/>)" +
         mimic + R"(</joint>)" + extraJoints + R"(
</robot>
)";
}

TEST(RobotModel, LoadsTheBuiltInHandArmWithArmFirstThenHand) {
  const auto model = RobotModel::loadBuiltIn("sah_tx90");
  ASSERT_EQ(model.dof(), 19);
  const auto names = model.activeJointNames();
  EXPECT_EQ(names.front(), "tx90_joint_1");
  EXPECT_EQ(names[5], "tx90_joint_6");
  EXPECT_EQ(names[6], "thumb_base");
  EXPECT_EQ(names.back(), "ring_medium");
  EXPECT_EQ(model.group("arm").size(), 6u);
  EXPECT_EQ(model.group("hand").size(), 13u);
  EXPECT_EQ(model.links()[static_cast<std::size_t>(model.palmLink())].name, "palm");
  // The four distal joints are mimic joints of their medium joints, 1:1.
  for (const std::string finger : {"thumb", "index", "middle", "ring"}) {
    const auto& distal = model.joints()[static_cast<std::size_t>(model.jointIndex(finger + "_distal"))];
    EXPECT_EQ(distal.activeIndex, -1);
    EXPECT_EQ(model.joints()[static_cast<std::size_t>(distal.mimicSource)].name, finger + "_medium");
    EXPECT_DOUBLE_EQ(distal.mimicMultiplier, 1.0);
  }
  // Limits as published, positive = flexion.
  const auto& thumbBase = model.activeJoints()[static_cast<std::size_t>(model.activeIndex("thumb_base"))];
  EXPECT_NEAR(thumbBase.lower, 0.0, 1e-12);
  EXPECT_NEAR(thumbBase.upper, M_PI / 2, 1e-9);
  EXPECT_FALSE(model.disabledCollisionPairs().empty());
}

TEST(RobotModel, NormalisesJointsToTheUnitIntervalAndBack) {
  const auto model = RobotModel::loadBuiltIn("sah_tx90");
  Configuration q(model.dof());
  for (int i = 0; i < model.dof(); ++i) q[i] = model.activeJoints()[static_cast<std::size_t>(i)].lower;
  EXPECT_NEAR(model.normalise(q).maxCoeff(), 0.0, 1e-12);
  for (int i = 0; i < model.dof(); ++i)
    q[i] = 0.25 * model.activeJoints()[static_cast<std::size_t>(i)].lower +
           0.75 * model.activeJoints()[static_cast<std::size_t>(i)].upper;
  EXPECT_NEAR((model.normalise(q).array() - 0.75).abs().maxCoeff(), 0.0, 1e-12);
  EXPECT_NEAR((model.denormalise(model.normalise(q)) - q).norm(), 0.0, 1e-12);
  EXPECT_TRUE(model.withinLimits(q));
  q[3] = model.activeJoints()[3].upper + 0.01;
  EXPECT_FALSE(model.withinLimits(q));
}

TEST(RobotModel, ReadsMimicMultiplierAndOffsetAndFlattensChains) {
  test::TempDir dir;
  const auto file = dir.write("toy.urdf", toyUrdf("", R"(<mimic joint="elbow" multiplier="2" offset="0.1"/>)"));
  const auto model = RobotModel::load(file);
  EXPECT_EQ(model.dof(), 2);
  const auto& wrist = model.joints()[static_cast<std::size_t>(model.jointIndex("wrist"))];
  EXPECT_EQ(model.joints()[static_cast<std::size_t>(wrist.mimicSource)].name, "elbow");
  EXPECT_DOUBLE_EQ(wrist.mimicMultiplier, 2.0);
  EXPECT_DOUBLE_EQ(wrist.mimicOffset, 0.1);
}

template <typename F>
InputError expectInputError(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("", "", "");
}

TEST(RobotModelErrors, MalformedXmlNamesTheFileAndLine) {
  test::TempDir dir;
  const auto file = dir.write("broken.urdf", "<robot name=\"x\">\n  <link name=\"a\">\n</robot>\n");
  const auto e = expectInputError([&] { RobotModel::load(file); });
  EXPECT_EQ(e.file(), file.string());
  EXPECT_NE(e.field().find("line"), std::string::npos);
}

TEST(RobotModelErrors, ADanglingJointIsRejectedWithUrdfdomsReason) {
  test::TempDir dir;
  const auto file =
      dir.write("dangling.urdf",
                toyUrdf(R"(<joint name="ghost" type="fixed"><parent link="nowhere"/><child link="tip"/></joint>)"));
  const auto e = expectInputError([&] { RobotModel::load(file); });
  EXPECT_EQ(e.file(), file.string());
  EXPECT_NE(e.message().find("not a valid URDF"), std::string::npos);
}

TEST(RobotModelErrors, AMimicCycleIsRejectedNamingTheJoint) {
  test::TempDir dir;
  std::string urdf = toyUrdf("", R"(<mimic joint="elbow"/>)");
  // elbow mimics wrist, wrist mimics elbow.
  urdf.replace(urdf.find("<limit lower=\"-2\""), 0, R"(<mimic joint="wrist"/>)");
  const auto file = dir.write("cycle.urdf", urdf);
  const auto e = expectInputError([&] { RobotModel::load(file); });
  EXPECT_EQ(e.file(), file.string());
  EXPECT_NE(e.field().find("].mimic"), std::string::npos);
  EXPECT_NE(e.message().find("cycle"), std::string::npos);
}

TEST(RobotModelErrors, AMimicOfAnUnknownJointIsRejected) {
  test::TempDir dir;
  const auto file = dir.write("unknown.urdf", toyUrdf("", R"(<mimic joint="knee"/>)"));
  const auto e = expectInputError([&] { RobotModel::load(file); });
  EXPECT_EQ(e.field(), "joint[wrist].mimic");
  EXPECT_NE(e.message().find("knee"), std::string::npos);
}

TEST(RobotModelErrors, AMissingFileOrCompanionIsReported) {
  test::TempDir dir;
  EXPECT_THROW(RobotModel::load(dir.path() / "none.urdf"), InputError);
  const auto file = dir.write("toy.urdf", toyUrdf());
  const auto srdf = dir.write("toy.srdf", R"(<robot name="toy"><group name="arm"><joint name="hip"/></group></robot>)");
  const auto e = expectInputError([&] { RobotModel::load(file, srdf); });
  EXPECT_EQ(e.file(), srdf.string());
  EXPECT_NE(e.message().find("hip"), std::string::npos);
}

}  // namespace
}  // namespace pmdplan
