#pragma once
// Hand samples from the PMD subspace (Sect. 5.1, Eq. 1, Algorithm 2): c_h = clamp(b + E'·s),
// s uniform in the box B^h. Axis 1 is each own-axis joint (thumb base) over its whole range, then
// PMD 1, 2, ... with half-widths lambda_i = kappa·sigma_i.
#include <Eigen/Core>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/planning/hand_sampler.hpp"
#include "pmdplan/planning/planning_space.hpp"
#include "pmdplan/synergy/synergy_model.hpp"

namespace pmdplan {

struct SynergySamplingSettings {
  /// lambda_i = kappa·sigma_i: the box half-width along PMD i in standard deviations (default 2).
  double kappa = 2.0;
  /// Most PMDs ever used (the paper's runs needed thumb base + 4 PMDs); capped by the model's count.
  int maxPmds = 4;
};

class SynergyHandSampler final : public HandSampler {
 public:
  /// Throws InputError (no file; field "kappa" or "max_directions") if a parameter is out of range,
  /// and checkSynergyModelFitsHand's error (synergy/hand_fit.hpp, no file) if the model does not fit
  /// the space's hand.
  SynergyHandSampler(const PlanningSpace& space, const SynergyModel& model, SynergySamplingSettings parameters = {});

  /// Own-axis joints + 1 PMD: 2 for the SAH.
  int initialDimension() const override { return ownAxisCount() + 1; }
  int maxDimension() const override { return ownAxisCount() + directionCount(); }
  void sample(int dimension, UnitPoints& points, Configuration& q) const override;
  std::string name() const override { return "pmd"; }

  int ownAxisCount() const { return static_cast<int>(ownAxisSlots_.size()); }
  /// PMDs in use (model's count capped by maxPmds).
  int directionCount() const { return static_cast<int>(halfWidths_.size()); }

 private:
  std::vector<int> configIndex_;   ///< per model joint: its configuration index
  JointLimits modelLimits_;        ///< the limits the model normalises with
  JointLimits robotLimits_;        ///< the space's limits of the same joints (final clamp)
  Eigen::VectorXd mean_;           ///< b
  Eigen::MatrixXd directions_;     ///< E' without the own axes: the PMDs in use
  Eigen::VectorXd halfWidths_;     ///< lambda_i
  std::vector<int> ownAxisSlots_;  ///< model joint slots sampled over their whole range
};

}  // namespace pmdplan
