#pragma once
// PCA of mapped hand postures (the paper's Sect. 4.2): joints normalised to [0, 1] by their limits,
// own-axis joints (SAH: thumb_base) and constant joints (SAH: middle_abduction) left out, Eigen's
// symmetric eigensolver on the covariance. Directions are ordered by variance, each with its
// largest component positive so the result does not depend on the solver's sign choice.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

struct SynergyFitSettings {
  /// Joints kept as axes of their own and left out of the PCA (default: none).
  std::vector<std::string> ownAxisJoints;
  /// A joint whose normalised values span no more than this over all frames is constant.
  double constantTolerance = 1e-12;
};

/// Where the postures came from, for messages and for the model's provenance.
struct PostureSource {
  std::string file;        ///< recording file (messages)
  std::string location;    ///< where the frames are in it, e.g. "lines 3-13502" (messages)
  std::string provenance;  ///< copied into the model
};

struct SynergyFit {
  SynergyModel model;
  int frames = 0;
  std::vector<std::string> pcaJoints;       ///< the joints the PCA ran over
  std::vector<std::string> constantJoints;  ///< left out: they never moved
  /// Joints that move (own-axis and PCA joints, in joint order): the rows of `correlation`.
  std::vector<std::string> varyingJoints;
  Eigen::MatrixXd correlation;
  /// Fraction of the PCA joints' total variance held by the first 1, 2, … directions.
  Eigen::VectorXd cumulativeVariance;
};

/// `postures`: one row per frame, one column per joint of `joints` (rad). Throws InputError naming
/// the source for an own-axis joint the robot lacks, fewer frames than PCA joints + 1, a posture
/// outside the limits, and data in which every PCA joint is constant.
SynergyFit fitSynergyModel(const Eigen::MatrixXd& postures, const JointLimits& joints,
                           const SynergyFitSettings& options, const PostureSource& source);

}  // namespace pmdplan
