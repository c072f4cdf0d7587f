#include "pmdplan/bench/human_likeness_independent.hpp"

#include <Eigen/QR>

#include "pmdplan/synergy/figure7_joint_pairs.hpp"
#include "pmdplan/synergy/kautham_sah_synergies.hpp"

namespace pmdplan {

std::optional<IndependentHandReference> independentHandReference(const PlanningSpace& space) {
  const KauthamSahSynergies& table = kauthamSahSynergies();
  IndependentHandReference reference;
  for (const std::string& joint : table.joints) {
    const int slot = space.indexOf(joint);
    if (slot < 0) return std::nullopt;
    reference.tableSlots.push_back(slot);
  }
  const int n = static_cast<int>(table.joints.size());
  const int pmds = static_cast<int>(table.directions.cols());
  Eigen::MatrixXd span = Eigen::MatrixXd::Zero(n, pmds + 1);
  span(0, 0) = 1.0;  // the thumb base, the table's own axis (its first joint)
  span.rightCols(pmds) = table.directions;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(span);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, pmds + 1);
  reference.complementProjector = Eigen::MatrixXd::Identity(n, n) - q * q.transpose();
  for (const Figure7JointPair& pair : figure7JointPairs()) {
    if (pair.paper == PaperCorrelation::Uncorrelated) continue;
    const double paperSign = pair.paper == PaperCorrelation::Positive ? 1.0 : -1.0;
    reference.coupledPairs.push_back({space.indexOf(pair.first), space.indexOf(pair.second),
                                      paperSign * paperSignOf(pair.first) * paperSignOf(pair.second)});
  }
  return reference;
}

double authorsSubspaceDistance(const IndependentHandReference& reference, const Configuration& q) {
  const KauthamSahSynergies& table = kauthamSahSynergies();
  Eigen::VectorXd offset(static_cast<Eigen::Index>(reference.tableSlots.size()));
  for (std::size_t j = 0; j < reference.tableSlots.size(); ++j)
    offset(static_cast<Eigen::Index>(j)) =
        table.limits[j].normalise(q(reference.tableSlots[j])) - table.mean(static_cast<Eigen::Index>(j));
  return (reference.complementProjector * offset).norm();
}

double jointCoupling(const std::vector<Configuration>& path, const PlanningSpace& space,
                     const IndependentHandReference& reference) {
  double agreement = 0.0, motion = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const double length = space.distance(path[k - 1], path[k]);
    if (!(length > 0.0)) continue;
    const Eigen::VectorXd change = space.normalise(path[k]) - space.normalise(path[k - 1]);
    for (const CoupledJointPair& pair : reference.coupledPairs) {
      const double a = change(pair.first), b = change(pair.second);
      agreement += 2.0 * pair.sign * a * b / length;
      motion += (a * a + b * b) / length;
    }
  }
  return motion > 0.0 ? agreement / motion : 0.0;
}

}  // namespace pmdplan
