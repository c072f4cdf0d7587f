#include "pmdplan/synergy/synergy_fit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "pinned_product_blocking.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

// Model values are kept to 12 decimals: far below anything that matters for sampling, and it makes
// the written file short and the same on every build (the last bits of an eigensolver may differ).
double tidy(double value) { return std::round(value * 1e12) / 1e12; }

void orientLargestComponentPositive(Eigen::Ref<Eigen::VectorXd> direction) {
  Eigen::Index largest = 0;
  direction.cwiseAbs().maxCoeff(&largest);
  if (direction(largest) < 0) direction = -direction;
}

std::vector<int> ownAxisIndices(const JointLimits& joints, const SynergyFitSettings& options) {
  std::vector<int> indices;
  for (const auto& name : options.ownAxisJoints) {
    const auto it = std::find_if(joints.begin(), joints.end(), [&](const JointLimit& j) { return j.name == name; });
    if (it == joints.end()) {
      std::string names;
      for (const auto& joint : joints) names += (names.empty() ? "" : ", ") + joint.name;
      throw InputError("", "own-axis joints", "'" + name + "' is not one of the hand joints " + names);
    }
    indices.push_back(static_cast<int>(it - joints.begin()));
  }
  return indices;
}

}  // namespace

SynergyFit fitSynergyModel(const Eigen::MatrixXd& postures, const JointLimits& joints,
                           const SynergyFitSettings& options, const PostureSource& source) {
  const auto jointCount = static_cast<Eigen::Index>(joints.size());
  if (postures.cols() != jointCount)
    throw std::invalid_argument("fitSynergyModel: postures have " + std::to_string(postures.cols()) + " columns for " +
                                std::to_string(jointCount) + " joints");
  const std::vector<int> ownAxis = ownAxisIndices(joints, options);
  const auto frames = postures.rows();
  if (frames < 2)
    throw InputError(source.file, source.location.empty() ? "frames" : source.location,
                     std::to_string(frames) + " frame(s): a PCA needs more frames than joints");

  for (Eigen::Index f = 0; f < frames; ++f)
    for (Eigen::Index j = 0; j < jointCount; ++j)
      if (!std::isfinite(postures(f, j)))
        throw InputError(source.file, "frame " + std::to_string(f + 1),
                         "joint " + joints[static_cast<std::size_t>(j)].name +
                             " is not a finite number after calibration and mapping; check the coefficients of the "
                             "calibration and the mapping");

  Eigen::MatrixXd unit(frames, jointCount);
  for (Eigen::Index j = 0; j < jointCount; ++j) {
    const JointLimit& limit = joints[static_cast<std::size_t>(j)];
    if (!(limit.range() > 0))
      throw std::invalid_argument("fitSynergyModel: joint " + limit.name + " has an empty range");
    unit.col(j) = (postures.col(j).array() - limit.lower) / limit.range();
    const double low = unit.col(j).minCoeff();
    const double high = unit.col(j).maxCoeff();
    if (low < -1e-9 || high > 1 + 1e-9)
      throw InputError(source.file, source.location.empty() ? "frames" : source.location,
                       "joint " + limit.name + " leaves its limits [" + exactNumberText(limit.lower) + ", " +
                           exactNumberText(limit.upper) + "] rad; map (and clamp) postures before the PCA");
  }

  SynergyFit fit;
  fit.frames = static_cast<int>(frames);
  std::vector<int> pca;
  std::vector<int> varying;
  for (Eigen::Index j = 0; j < jointCount; ++j) {
    const std::string& name = joints[static_cast<std::size_t>(j)].name;
    const bool constant = unit.col(j).maxCoeff() - unit.col(j).minCoeff() <= options.constantTolerance;
    const bool own = std::find(ownAxis.begin(), ownAxis.end(), j) != ownAxis.end();
    if (constant)
      fit.constantJoints.push_back(name);
    else
      varying.push_back(static_cast<int>(j));
    if (!constant && !own) {
      pca.push_back(static_cast<int>(j));
      fit.pcaJoints.push_back(name);
    }
    if (!constant) fit.varyingJoints.push_back(name);
  }
  if (pca.empty())
    throw InputError(source.file, source.location.empty() ? "frames" : source.location,
                     "constant data set: no joint outside the own-axis joints moves in " + std::to_string(frames) +
                         " frames (after mapping and clamping), so there is nothing to analyse");
  const auto p = static_cast<Eigen::Index>(pca.size());
  if (frames <= p)
    throw InputError(source.file, source.location.empty() ? "frames" : source.location,
                     std::to_string(frames) + " frames for " + std::to_string(p) +
                         " joints in the PCA; need at least " + std::to_string(p + 1));

  const Eigen::RowVectorXd mean = unit.colwise().mean();
  Eigen::MatrixXd centred(frames, p);
  for (Eigen::Index k = 0; k < p; ++k)
    centred.col(k) = unit.col(pca[static_cast<std::size_t>(k)]).array() - mean(pca[static_cast<std::size_t>(k)]);
  const Eigen::MatrixXd covariance = gramOverFrames(centred) / static_cast<double>(frames - 1);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  if (solver.info() != Eigen::Success) throw std::runtime_error("fitSynergyModel: eigensolver failed");
  const double total = covariance.trace();

  SynergyModel& model = fit.model;
  model.joints = joints;
  model.provenance = source.provenance;
  model.orthonormal = true;
  for (const int j : ownAxis) model.ownAxisJoints.push_back(joints[static_cast<std::size_t>(j)].name);
  model.mean = mean.transpose().unaryExpr(&tidy);
  model.directions = Eigen::MatrixXd::Zero(jointCount, p);
  model.sigma.resize(p);
  model.varianceFraction.resize(p);
  fit.cumulativeVariance.resize(p);
  double cumulative = 0.0;
  for (Eigen::Index k = 0; k < p; ++k) {
    const Eigen::Index source_k = p - 1 - k;  // the solver sorts ascending
    Eigen::VectorXd component = solver.eigenvectors().col(source_k);
    orientLargestComponentPositive(component);
    const double variance = std::max(solver.eigenvalues()(source_k), 0.0);
    for (Eigen::Index r = 0; r < p; ++r) model.directions(pca[static_cast<std::size_t>(r)], k) = tidy(component(r));
    model.sigma(k) = tidy(std::sqrt(variance));
    model.varianceFraction(k) = tidy(variance / total);
    cumulative += variance / total;
    fit.cumulativeVariance(k) = cumulative;
  }

  const auto v = static_cast<Eigen::Index>(varying.size());
  Eigen::MatrixXd moving(frames, v);
  for (Eigen::Index k = 0; k < v; ++k)
    moving.col(k) = unit.col(varying[static_cast<std::size_t>(k)]).array() - mean(varying[static_cast<std::size_t>(k)]);
  const Eigen::MatrixXd movingCovariance = gramOverFrames(moving);
  const Eigen::VectorXd scale = movingCovariance.diagonal().cwiseSqrt().cwiseInverse();
  fit.correlation = scale.asDiagonal() * movingCovariance * scale.asDiagonal();
  return fit;
}

}  // namespace pmdplan
