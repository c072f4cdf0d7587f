#pragma once
// Human-likeness that does not use the planner's synergy model (docs/human_likeness.md):
//  - the distance of each hand posture from the subspace of a second, independent model, the
//    principal motion directions the paper's authors planned with (the Kautham table,
//    kautham_sah_synergies.hpp): its mean posture plus the thumb-base axis and PMD 1-4;
//  - the joint coupling of the hand's motion: how well the motion of the joint pairs whose
//    correlation the paper's Fig. 7 shows (figure7_joint_pairs.hpp) follows the sign of that
//    correlation. No PCA: only the pairs and their signs.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "pmdplan/bench/run_record.hpp"
#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/planning_space.hpp"

namespace pmdplan {

/// One correlated pair of Fig. 7 in our sign convention.
struct CoupledJointPair {
  int first = 0;      ///< configuration index
  int second = 0;     ///< configuration index
  double sign = 1.0;  ///< +1: the joints move together (our positive-flexion signs), -1: opposite
};

/// What the two measures need, located in one planning space.
struct IndependentHandReference {
  /// Configuration index of each joint of the Kautham table, in the table's order.
  std::vector<int> tableSlots;
  /// I - Q Q^T: projects the table's normalised posture minus its mean onto the orthogonal
  /// complement of span{thumb-base axis, PMD 1-4} (Q an orthonormal basis of that span).
  Eigen::MatrixXd complementProjector;
  /// Fig. 7's positive and negative pairs (the uncorrelated ones carry no sign and are left out).
  std::vector<CoupledJointPair> coupledPairs;
};

/// std::nullopt if `space` lacks one of the table's 13 hand joints (matched by name).
std::optional<IndependentHandReference> independentHandReference(const PlanningSpace& space);

/// Euclidean distance of the hand posture in `q` from the authors' PMD subspace, normalised units
/// over the table's limits.
double authorsSubspaceDistance(const IndependentHandReference& reference, const Configuration& q);

/// The arc-length integral of the coupled pairs' joint velocities, in normalised joint units:
///   C = sum_k sum_p 2 s_p da db / L_k  /  sum_k sum_p (da^2 + db^2) / L_k
/// over the path's straight segments k (L_k their normalised length, da and db the normalised
/// changes of the pair's joints, s_p its sign). In [-1, 1]; 0 for a path whose pair joints stay.
double jointCoupling(const std::vector<Configuration>& path, const PlanningSpace& space,
                     const IndependentHandReference& reference);

}  // namespace pmdplan
