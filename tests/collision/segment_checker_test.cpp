#include "pmdplan/collision/segment_checker.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/random_source.hpp"

namespace pmdplan {
namespace {

Task handArmTask() {
  Task task;
  task.name = "plate";
  task.robot = std::make_shared<RobotModel>(RobotModel::loadBuiltIn("sah_tx90"));
  return task;
}

Configuration restPose(const RobotModel& model) {
  Configuration q = Configuration::Zero(model.dof());
  q[1] = -0.3;  // arm bent so the hand points forward and down
  q[2] = 1.8;
  q[4] = 0.6;
  for (int i : model.group("hand")) q[i] = model.activeJoints()[static_cast<std::size_t>(i)].lower + 0.1;
  return q;
}

Eigen::Vector3d indexTip(const ExactCollisionChecker& checker, const Configuration& q) {
  const auto& model = checker.model();
  return checker.kinematics().linkPoses(q)[static_cast<std::size_t>(model.linkIndex("index_distal_link"))] *
         Eigen::Vector3d(0, 0.0295, 0);
}

TEST(SegmentChecker, CatchesATwoMillimetrePlateThatTheSweptHandPassesThrough) {
  Task task = handArmTask();
  const auto& model = *task.robot;
  const Configuration from = restPose(model);
  Configuration to = from;
  to[4] += 0.3;  // flex the wrist: the fingertips sweep side by side
  {
    ExactCollisionChecker probe(task);
    // A 2 mm plate across the fingertip's path, halfway, small enough to miss everything else.
    const Eigen::Vector3d a = indexTip(probe, from), b = indexTip(probe, to);
    const Eigen::Vector3d middle = indexTip(probe, from + 0.5 * (to - from));
    Obstacle plate{"plate", BoxShape{Eigen::Vector3d(0.002, 0.03, 0.03)}, Eigen::Isometry3d::Identity()};
    const Eigen::Vector3d normal = (b - a).normalized();
    plate.pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), normal).toRotationMatrix();
    plate.pose.translation() = middle;
    task.obstacles.push_back(plate);
  }
  ExactCollisionChecker checker(task);
  ASSERT_TRUE(checker.isValid(from));
  ASSERT_TRUE(checker.isValid(to)) << checker.check(to).pairs.front().first << " "
                                   << checker.check(to).pairs.front().second;

  SegmentChecker fine(checker, model, 0.001);
  EXPECT_FALSE(fine.isValid(from, to));
  const auto inspection = fine.inspect(checker, from, to);
  ASSERT_FALSE(inspection.free);
  // The fingertip's 10 mm pad reaches the plate a little before its centre point does.
  EXPECT_GT(*inspection.firstCollision, 0.3);
  EXPECT_LE(*inspection.firstCollision, 0.5);
  ASSERT_FALSE(inspection.collisions.pairs.empty());
  EXPECT_EQ(inspection.collisions.pairs.front().second, "plate");

  // The same segment checked at a resolution that steps over the plate is (wrongly) free: the
  // tolerance is what makes the answer trustworthy.
  const double coarse = fine.bound().bound(from, to) / 3.0;
  SegmentChecker coarseChecker(checker, model, coarse);
  EXPECT_TRUE(coarseChecker.isValid(from, to));
}

TEST(SegmentChecker, ChecksExactlyTheStatesTheBoundNeeds) {
  Task task = handArmTask();
  ExactCollisionChecker checker(task);
  const auto& model = *task.robot;
  SegmentChecker segments(checker, model, 0.001);
  const Configuration from = restPose(model);
  Configuration to = from;
  to[3] += 0.1;
  to[model.activeIndex("index_medium")] += 0.3;
  const double bound = segments.bound().bound(from, to);
  const long intervals = static_cast<long>(std::ceil(bound / 0.001));
  EXPECT_EQ(segments.bound().intervals(from, to, 0.001), intervals);
  ASSERT_TRUE(segments.isValid(from, to));
  EXPECT_EQ(segments.statesChecked(), static_cast<std::size_t>(intervals - 1));  // interior states
  const auto inspection = segments.inspect(checker, from, to);
  EXPECT_TRUE(inspection.free);
  EXPECT_EQ(inspection.statesChecked, intervals + 1);
  EXPECT_EQ(inspection.statesNeeded, intervals + 1);
}

TEST(SweptDistanceBound, BoundsTheRealDisplacementOfEveryLinkShape) {
  Task task = handArmTask();
  const auto& model = *task.robot;
  ForwardKinematics fk(model);
  SweptDistanceBound bound(model);
  RandomSource random(7);
  for (int trial = 0; trial < 200; ++trial) {
    Configuration a(model.dof()), b(model.dof());
    for (int i = 0; i < model.dof(); ++i) {
      const auto& j = model.activeJoints()[static_cast<std::size_t>(i)];
      a[i] = random.uniform(j.lower, j.upper);
      b[i] = a[i] + random.uniform(-0.05, 0.05);
    }
    const double limit = bound.bound(a, b);
    const auto pa = fk.linkPoses(a), pb = fk.linkPoses(b);
    double moved = 0.0;
    for (std::size_t l = 0; l < model.links().size(); ++l)
      for (const auto& shape : model.links()[l].collisionShapes) {
        // The shape's centre and the farthest points along its frame axes.
        const double r = boundingRadius(shape.shape);
        for (const Eigen::Vector3d& offset : {Eigen::Vector3d::Zero().eval(), Eigen::Vector3d(r, 0, 0),
                                              Eigen::Vector3d(0, r, 0), Eigen::Vector3d(0, 0, r)})
          moved = std::max(moved, ((pa[l] * shape.pose * offset) - (pb[l] * shape.pose * offset)).norm());
      }
    EXPECT_LE(moved, limit + 1e-12) << "trial " << trial;
  }
}

}  // namespace
}  // namespace pmdplan
