#include "synthetic_latent_motion.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "pinned_product_blocking.hpp"
#include "pmdplan/core/portable_math.hpp"

namespace pmdplan {
namespace {

enum class Primitive { OpenClose, Spread, Opposition, Pinch };

/// Adds one primitive's bell-shaped excursion (0 -> 1 -> 0 over the episode) to the latent rows.
void addPrimitive(Primitive primitive, double amplitude, int start, int length, Eigen::MatrixXd& latent) {
  // Latent coordinates 0-3 are PMD 1-4 (see kautham_sah_synergies.hpp for what each one does).
  Eigen::Vector4d weights = Eigen::Vector4d::Zero();
  switch (primitive) {
    case Primitive::OpenClose:
      weights << 0.0, 1.0, 0.0, 0.0;
      break;  // all fingers close and open
    case Primitive::Spread:
      weights << 0.4, 0.0, 0.0, 1.0;
      break;  // fingers spread apart
    case Primitive::Opposition:
      weights << 0.0, 0.0, 1.0, 0.0;
      break;  // thumb swings across the palm
    case Primitive::Pinch:
      weights << 0.3, 0.7, 0.7, 0.0;
      break;  // thumb meets the closing fingers
  }
  for (int i = 0; i < length && start + i < latent.rows(); ++i) {
    const double phase = portable::sin(std::numbers::pi * (i + 0.5) / length);
    for (int k = 0; k < 4 && k < latent.cols(); ++k) latent(start + i, k) += amplitude * weights(k) * phase * phase;
  }
}

}  // namespace

Eigen::VectorXd ornsteinUhlenbeck(int frames, double sampleRateHz, double timeConstantS, DeterministicRandom& random) {
  Eigen::VectorXd path(frames);
  const double decay = portable::exp(-1.0 / (sampleRateHz * timeConstantS));
  const double kick = std::sqrt(1.0 - decay * decay);
  double value = random.normal();
  for (int f = 0; f < frames; ++f) {
    path(f) = value;
    value = decay * value + kick * random.normal();
  }
  return path;
}

Eigen::MatrixXd generateLatentMotion(const LatentMotionSettings& settings, DeterministicRandom& random) {
  const int frames = settings.frames;
  const auto count = static_cast<Eigen::Index>(settings.variances.size());
  Eigen::MatrixXd latent(frames, count);
  for (Eigen::Index k = 0; k < count; ++k)
    latent.col(k) = ornsteinUhlenbeck(frames, settings.sampleRateHz, settings.timeConstantS, random);

  // Episodes of 1-3 s; a share of them carry a primitive, the rest is free wandering.
  for (int start = 0; start < frames;) {
    const int length = std::max(1, static_cast<int>(random.uniform(1.0, 3.0) * settings.sampleRateHz));
    if (random.uniform() < settings.primitiveShare) {
      const auto primitive = static_cast<Primitive>(random.below(4));
      const double amplitude = random.uniform(1.5, 2.5) * (random.uniform() < 0.5 ? -1.0 : 1.0);
      addPrimitive(primitive, amplitude, start, length, latent);
    }
    start += length;
  }

  latent.rowwise() -= latent.colwise().mean();
  if (frames <= 2 * count) return latent;  // too few frames to whiten; used only for tiny samples
  const Eigen::MatrixXd covariance = gramOverFrames(latent) / static_cast<double>(frames - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  // Symmetric whitening moves the paths least of all whitening transforms, keeping them smooth.
  const Eigen::MatrixXd whitening = solver.eigenvectors() *
                                    solver.eigenvalues().cwiseSqrt().cwiseInverse().asDiagonal() *
                                    solver.eigenvectors().transpose();
  Eigen::MatrixXd white = latent * whitening;
  for (Eigen::Index k = 0; k < count; ++k) white.col(k) *= std::sqrt(settings.variances[static_cast<std::size_t>(k)]);
  return white;
}

}  // namespace pmdplan
