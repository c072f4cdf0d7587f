#pragma once
// The synthetic operator's latent directions (private to synergy/).
#include <Eigen/Core>
#include <vector>

namespace pmdplan {

struct LatentBasisSettings {
  /// Columns: PMD 1-4 over the latent joints (our convention), as published.
  Eigen::MatrixXd pmds;
  /// Variance of each latent direction, largest first (one per latent joint).
  Eigen::VectorXd variances;
  /// Row of the thumb-roll joint (thumb_abduction) and rows of the finger joints.
  int thumbRollRow = 0;
  std::vector<int> fingerRows;
};

/// An orthonormal basis of the latent joints whose first four columns are PMD 1-4 with the thumb
/// roll entry of PMD 1, 2 and 4 cleared (docs/reference_data.md §4; PMD 3, thumb opposition, keeps it), after
/// Gram-Schmidt. The table says nothing about the remaining directions; they are chosen so that
/// the thumb roll is as uncorrelated with the finger joints as the first four allow, as the paper
/// observes (Sect. 4.2: joint 0 "rather independent" of the finger joints).
Eigen::MatrixXd latentBasis(const LatentBasisSettings& settings);

}  // namespace pmdplan
