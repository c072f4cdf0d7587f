#pragma once
// Forward kinematics of several configurations at once, structure-of-arrays: every number of the
// computation is a short array over the configurations (lanes), so the compiler turns each step
// into one SIMD instruction over all lanes. The kernels see plain double arrays only (no Eigen
// types: Eigen built with other vector flags than Debian's FCL and OMPL misaligns across them);
// AVX-512 and AVX2 builds of them run on CPUs that have them (widestSimdLevel, simd_level.hpp), the
// SSE2 baseline on any x86-64. Mimic joints follow their source joint as in
// ForwardKinematics::jointValues; results equal ForwardKinematics's to rounding (the fast checker's
// sphere margin absorbs the difference).
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "pmdplan/model/robot_model.hpp"

namespace pmdplan {

class BatchedForwardKinematics {
 public:
  static constexpr int kLanes = 8;        ///< configurations per batch: one AVX-512 register of doubles
  static constexpr int kPoseValues = 12;  ///< row-major rotation (9) then translation (3)

  BatchedForwardKinematics(const RobotModel& model, const Eigen::Isometry3d& base = Eigen::Isometry3d::Identity());

  int dof() const { return dof_; }
  int linkCount() const { return linkCount_; }
  /// Doubles needed for the poses of a batch (links x 12 x kLanes) and of one configuration.
  std::size_t batchPoseSize() const { return static_cast<std::size_t>(linkCount_) * kPoseValues * kLanes; }
  std::size_t singlePoseSize() const { return static_cast<std::size_t>(linkCount_) * kPoseValues; }

  /// jointsByLane[i * kLanes + lane] = active joint i of configuration `lane`;
  /// poses[(link * 12 + value) * kLanes + lane] = world pose of the link.
  void computeBatch(const double* jointsByLane, double* poses) const;
  /// One configuration (dof values); poses[link * 12 + value].
  void computeOne(const double* q, double* poses) const;

  /// A set of links, a bit per link index.
  using LinkSet = std::vector<std::uint64_t>;
  LinkSet emptyLinkSet() const { return LinkSet(static_cast<std::size_t>(linkCount_ + 63) / 64, 0); }
  /// Adds the link and every link between it and the root (what its pose is computed from).
  void addWithAncestors(LinkSet& set, int link) const;
  /// As computeOne, for the links of `links` only (a set closed under ancestors, as
  /// addWithAncestors makes); the other poses are left as they were. With a `frame` link, the
  /// poses are relative to that link instead of the world (its pose is the identity, `links`
  /// holds links below it only): enough for distances between links below it, at less cost.
  void computeSome(const double* q, double* poses, const LinkSet& links, int frame = -1) const;
  /// The link of which both are descendants (or one is the other), deepest first.
  int commonAncestor(int a, int b) const;

  /// One joint of the tree walk, in plain numbers (parents before children).
  struct Step {
    int parentLink = 0, childLink = 0;
    int motion = 0;  ///< 0 fixed, 1 revolute, 2 prismatic
    int axisZ = 0;   ///< +1 / -1 when the axis is +z / -z (the common, cheaper case), else 0
    int joint = 0;   ///< index into RobotModel::joints()
    double origin[kPoseValues] = {};
    double axis[3] = {0, 0, 1};
    /// The origin's rotation is a signed permutation (rpy in multiples of 90 degrees, as most URDF
    /// joints): column k of the child is sign[k] times column column[k] of the parent, no products.
    bool permutes = false;
    int column[3] = {0, 1, 2};
    double sign[3] = {1, 1, 1};
    bool translates = true;  ///< false when the origin has no translation
  };
  /// Where each joint's value comes from.
  struct ValueSource {
    int activeIndex = -1;  ///< >= 0: the configuration's value
    int mimicSource = -1;  ///< >= 0: multiplier * value of that joint + offset
    double multiplier = 1.0, offset = 0.0;
  };
  struct Plan {
    int linkCount = 0, jointCount = 0, rootLink = 0;
    double base[kPoseValues] = {};
    std::vector<Step> steps;
    std::vector<ValueSource> values;
  };

 private:
  int dof_ = 0;
  int linkCount_ = 0;
  Plan plan_;
  std::vector<int> parentLink_;  ///< per link, -1 for the root
};

}  // namespace pmdplan
