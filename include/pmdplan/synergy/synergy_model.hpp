#pragma once
// Principal motion directions of a hand (the paper's Sect. 4.2): mean posture b, orthonormal
// directions ordered by variance, their standard deviations, and the joints kept as axes of their
// own (SAH: thumb_base). All in joint values normalised to [0, 1] by the joint limits.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"

namespace pmdplan {

struct SynergyModel {
  /// The robot joints the model covers (every hand joint), with the limits used to normalise.
  JointLimits joints;
  /// b: mean posture, normalised units, one entry per joint.
  Eigen::VectorXd mean;
  /// Joints that form an axis of their own, sampled over their whole range before PMD 1.
  std::vector<std::string> ownAxisJoints;
  /// Column i is PMD i+1 (unit length; zero on own-axis and constant joints).
  Eigen::MatrixXd directions;
  /// Standard deviation of the data along each PMD (normalised units).
  Eigen::VectorXd sigma;
  /// Share of the total variance (of the PCA's joints) carried by each PMD.
  Eigen::VectorXd varianceFraction;
  /// False for imported bases that are not orthonormal; coefficients then come from least squares.
  bool orthonormal = true;
  /// Where the model came from (recording, seed, import), written to and read from the file.
  std::string provenance;

  int jointCount() const { return static_cast<int>(joints.size()); }
  int directionCount() const { return static_cast<int>(directions.cols()); }
  /// Box half-widths lambda_i = kappa * sigma_i of the sampling box along the PMDs.
  Eigen::VectorXd boxHalfWidths(double kappa) const { return kappa * sigma; }
  /// Index of a joint by name, or -1.
  int jointIndex(const std::string& name) const {
    for (int i = 0; i < jointCount(); ++i)
      if (joints[static_cast<std::size_t>(i)].name == name) return i;
    return -1;
  }
};

}  // namespace pmdplan
