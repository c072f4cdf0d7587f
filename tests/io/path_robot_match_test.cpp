#include "pmdplan/io/viewer/path_robot_match.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"

namespace pmdplan {
namespace {

class PathRobotMatchTest : public ::testing::Test {
 protected:
  RobotModel robot_ = RobotModel::loadBuiltIn("sah_tx90");

  PathFile pathOf(const std::vector<Configuration>& points) const {
    PathFile path;
    path.jointNames = robot_.activeJointNames();
    path.points = points;
    path.mimic = mimicRelations(robot_);
    return path;
  }
  Configuration middle() const { return robot_.denormalise(Configuration::Constant(robot_.dof(), 0.5)); }

  static InputError errorOf(const PathFile& path, const RobotModel& robot) {
    try {
      pathConfigurations(path, robot, "p.json");
    } catch (const InputError& error) {
      return error;
    }
    ADD_FAILURE() << "expected an InputError";
    return InputError("", "", "");
  }
};

TEST_F(PathRobotMatchTest, AMatchingPathComesBackInTheRobotsOrderEvenIfTheFileListsItsJointsOtherwise) {
  const Configuration q = middle();
  EXPECT_EQ(pathConfigurations(pathOf({q, q}), robot_, "p.json").front(), q);

  PathFile reversed = pathOf({q});
  std::reverse(reversed.jointNames.begin(), reversed.jointNames.end());
  reversed.points = {Configuration(q.reverse())};
  std::reverse(reversed.mimic.begin(), reversed.mimic.end());
  EXPECT_EQ(pathConfigurations(reversed, robot_, "p.json").front(), q);
}

TEST_F(PathRobotMatchTest, AValueJustPastALimitIsTolerableButNotOneClearlyPast) {
  Configuration q = middle();
  q[5] = robot_.activeJoints()[5].upper + 5e-10;
  EXPECT_NO_THROW(pathConfigurations(pathOf({q}), robot_, "p.json"));
  q[5] = robot_.activeJoints()[5].upper + 1e-6;
  const InputError error = errorOf(pathOf({middle(), q}), robot_);
  EXPECT_EQ(error.file(), "p.json");
  EXPECT_EQ(error.field(), "points[1].positions[5]");
  EXPECT_NE(error.message().find("tx90_joint_6"), std::string::npos);
}

TEST_F(PathRobotMatchTest, ADuplicateNameCannotHideAMissingJoint) {
  PathFile path = pathOf({middle()});
  path.jointNames[1] = path.jointNames[0];
  const InputError error = errorOf(path, robot_);
  EXPECT_EQ(error.field(), "joint_names");
  EXPECT_NE(error.message().find("missing: tx90_joint_2"), std::string::npos);
}

}  // namespace
}  // namespace pmdplan
