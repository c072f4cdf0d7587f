#pragma once
// The synthetic operator's latent synergy coordinates over time (private to synergy/).
#include <Eigen/Core>
#include <vector>

#include "deterministic_random.hpp"

namespace pmdplan {

struct LatentMotionSettings {
  int frames = 0;
  double sampleRateHz = 100.0;
  double timeConstantS = 0.8;
  double primitiveShare = 0.6;
  /// Target variance of each latent coordinate (normalised units squared).
  std::vector<double> variances;
};

/// One row per frame, one column per latent coordinate: smooth random motion (Ornstein-Uhlenbeck)
/// plus motion primitives on the first four coordinates (PMD 1-4: spread/flex, open/close, thumb
/// opposition, finger spread with thumb bend). The recording is then centred and whitened so that
/// its sample covariance is exactly diag(variances): a real operator's recording is one sample of
/// their motion, but ours is meant to carry the published spectrum, not a random draw around it.
Eigen::MatrixXd generateLatentMotion(const LatentMotionSettings& settings, DeterministicRandom& random);

/// An Ornstein-Uhlenbeck path with unit stationary variance.
Eigen::VectorXd ornsteinUhlenbeck(int frames, double sampleRateHz, double timeConstantS, DeterministicRandom& random);

}  // namespace pmdplan
