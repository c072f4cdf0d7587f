// Batched forward kinematics equals ForwardKinematics (Eigen) to rounding, for single
// configurations and every lane of a batch, with mimic joints following their sources and the
// task's base pose applied; its sin/cos agree with the library's over many turns.
#include "pmdplan/collision/batched_forward_kinematics.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/random_source.hpp"
#include "pmdplan/model/forward_kinematics.hpp"

namespace pmdplan {
namespace {

constexpr int kValues = BatchedForwardKinematics::kPoseValues;

void expectPose(const Eigen::Isometry3d& expected, const double* values, int stride, const std::string& where) {
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(values[(r * 3 + c) * stride], expected.linear()(r, c), 1e-12) << where;
    EXPECT_NEAR(values[(9 + r) * stride], expected.translation()(r), 1e-12) << where;
  }
}

TEST(BatchedForwardKinematics, EqualsTheEigenKinematicsForOneAndForEveryLane) {
  const RobotModel model = RobotModel::loadBuiltIn("sah_tx90");
  Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
  base.linear() = Eigen::AngleAxisd(3.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  base.translation() = Eigen::Vector3d(-0.2, 0.23, 0.0);
  const ForwardKinematics reference(model, base);
  const BatchedForwardKinematics batched(model, base);
  constexpr int kLanes = BatchedForwardKinematics::kLanes;
  RandomSource random(5);
  std::vector<double> one(batched.singlePoseSize()), many(batched.batchPoseSize()),
      lanes(static_cast<std::size_t>(model.dof()) * kLanes);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Configuration> qs;
    for (int lane = 0; lane < kLanes; ++lane) {
      Configuration q(model.dof());
      for (int i = 0; i < model.dof(); ++i) {
        const auto& j = model.activeJoints()[static_cast<std::size_t>(i)];
        q[i] = random.uniform(j.lower, j.upper);
        lanes[static_cast<std::size_t>(i * kLanes + lane)] = q[i];
      }
      qs.push_back(q);
    }
    batched.computeBatch(lanes.data(), many.data());
    for (int lane = 0; lane < kLanes; ++lane) {
      const auto expected = reference.linkPoses(qs[static_cast<std::size_t>(lane)]);
      batched.computeOne(qs[static_cast<std::size_t>(lane)].data(), one.data());
      for (std::size_t l = 0; l < expected.size(); ++l) {
        expectPose(expected[l], one.data() + l * kValues, 1, model.links()[l].name);
        expectPose(expected[l], many.data() + l * kValues * kLanes + lane, kLanes, model.links()[l].name + " lane");
      }
    }
  }
}

TEST(BatchedForwardKinematics, MimicJointsFollowTheirSource) {
  const RobotModel model = RobotModel::loadBuiltIn("sah_tx90");
  const BatchedForwardKinematics batched(model);
  Configuration q = Configuration::Zero(model.dof());
  std::vector<double> before(batched.singlePoseSize()), after(batched.singlePoseSize());
  batched.computeOne(q.data(), before.data());
  q[model.activeIndex("index_medium")] = 0.5;
  batched.computeOne(q.data(), after.data());
  // The distal link turns by twice the medium joint's angle relative to the proximal link
  // (medium + its mimic), so its frame differs from the medium link's by 0.5 rad more.
  const auto rotation = [&](const std::vector<double>& p, const std::string& link) {
    const double* v = p.data() + model.linkIndex(link) * kValues;
    Eigen::Matrix3d m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m(r, c) = v[r * 3 + c];
    return m;
  };
  const Eigen::AngleAxisd medium(rotation(before, "index_medium_link").transpose() *
                                 rotation(after, "index_medium_link"));
  const Eigen::AngleAxisd distal(rotation(before, "index_distal_link").transpose() *
                                 rotation(after, "index_distal_link"));
  EXPECT_NEAR(medium.angle(), 0.5, 1e-12);
  EXPECT_NEAR(distal.angle(), 1.0, 1e-12);
}

}  // namespace
}  // namespace pmdplan
