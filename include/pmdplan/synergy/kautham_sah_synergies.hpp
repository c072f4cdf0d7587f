#pragma once
// The principal motion directions the paper's authors planned with (Kautham control files derived
// from their glove data; docs/reference_data.md §4), converted from Kautham's negative-flexion convention to ours:
// for thumb_base and every proximal and medium joint p = 1 - p_kautham and the components are
// negated; abduction joints keep both.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"

namespace pmdplan {

struct KauthamSahSynergies {
  /// The 13 SAH hand joints in the paper's order (thumb_base … ring_medium).
  std::vector<std::string> joints;
  /// The limits the table's units are normalised over: Kautham's, in our convention (radians;
  /// thumb_base 0..90 deg, abduction -15..15, proximal -4..75, medium 4..75), one per joint.
  JointLimits limits;
  /// Mean posture, normalised units over `limits`, our convention.
  Eigen::VectorXd mean;
  /// Columns: PMD 1-4 (unit vectors, our convention), zero on thumb_base and middle_abduction.
  Eigen::MatrixXd directions;
  /// Box widths along the PMDs in the same units (not variances; see docs/reference_data.md §4).
  Eigen::VectorXd span;
};

const KauthamSahSynergies& kauthamSahSynergies();

}  // namespace pmdplan
