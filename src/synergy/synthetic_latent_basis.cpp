#include "synthetic_latent_basis.hpp"

#include <Eigen/LU>
#include <cmath>

namespace pmdplan {
namespace {

/// Rotation of the complement: the Cayley transform of a skew-symmetric matrix built from
/// `parameters` (one per pair a > b).
Eigen::MatrixXd cayleyRotation(const Eigen::VectorXd& parameters, Eigen::Index size) {
  Eigen::MatrixXd skew = Eigen::MatrixXd::Zero(size, size);
  Eigen::Index p = 0;
  for (Eigen::Index a = 0; a < size; ++a)
    for (Eigen::Index b = 0; b < a; ++b) {
      skew(a, b) = parameters(p);
      skew(b, a) = -parameters(p);
      ++p;
    }
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(size, size);
  return (identity - 0.5 * skew).inverse() * (identity + 0.5 * skew);
}

}  // namespace

Eigen::MatrixXd latentBasis(const LatentBasisSettings& settings) {
  const auto n = settings.pmds.rows();
  const auto published = settings.pmds.cols();
  Eigen::MatrixXd basis(n, n);
  Eigen::Index filled = 0;
  const auto addOrthogonalised = [&](Eigen::VectorXd vector) {
    for (Eigen::Index k = 0; k < filled; ++k) vector -= basis.col(k).dot(vector) * basis.col(k);
    if (vector.norm() < 1e-6) return;
    basis.col(filled++) = vector.normalized();
  };
  for (Eigen::Index k = 0; k < published; ++k) {
    Eigen::VectorXd pmd = settings.pmds.col(k);
    if (k != 2) pmd(settings.thumbRollRow) = 0.0;
    addOrthogonalised(pmd);
  }
  for (Eigen::Index i = 0; i < n && filled < n; ++i) addOrthogonalised(Eigen::VectorXd::Unit(n, i));

  // Turn the complement (whose variances are fixed, largest first) to make the thumb roll's
  // correlations with the finger joints small: plain descent on the squared correlations over
  // rotations Q = cayley(x), with a finite-difference gradient. Deterministic, and tiny (7x7).
  const Eigen::MatrixXd top = basis.leftCols(published);
  const Eigen::MatrixXd complement = basis.rightCols(n - published);
  const Eigen::MatrixXd fixedPart = top * settings.variances.head(published).asDiagonal() * top.transpose();
  const Eigen::VectorXd complementVariances = settings.variances.tail(n - published);
  const auto m = n - published;
  const auto cost = [&](const Eigen::MatrixXd& rotation) {
    const Eigen::MatrixXd turned = complement * rotation;
    const Eigen::MatrixXd covariance = fixedPart + turned * complementVariances.asDiagonal() * turned.transpose();
    double sum = 0;
    const int t = settings.thumbRollRow;
    for (const int j : settings.fingerRows) {
      const double r = covariance(t, j) / std::sqrt(covariance(t, t) * covariance(j, j));
      sum += r * r;
    }
    return sum;
  };
  Eigen::MatrixXd rotation = Eigen::MatrixXd::Identity(m, m);
  const Eigen::Index parameterCount = m * (m - 1) / 2;
  double current = cost(rotation);
  double step = 1.0;
  for (int iteration = 0; iteration < 300 && step > 1e-9; ++iteration) {
    Eigen::VectorXd gradient(parameterCount);
    for (Eigen::Index p = 0; p < parameterCount; ++p) {
      const double h = 1e-6;
      const Eigen::VectorXd delta = Eigen::VectorXd::Unit(parameterCount, p) * h;
      gradient(p) = (cost(rotation * cayleyRotation(delta, m)) - cost(rotation * cayleyRotation(-delta, m))) / (2 * h);
    }
    if (gradient.norm() < 1e-12) break;
    // Backtracking: halve the step until the cost drops; grow it again after a success.
    while (step > 1e-9) {
      const Eigen::MatrixXd candidate = rotation * cayleyRotation(-step * gradient / gradient.norm(), m);
      const double value = cost(candidate);
      if (value < current) {
        rotation = candidate;
        current = value;
        step *= 1.5;
        break;
      }
      step *= 0.5;
    }
  }
  basis.rightCols(m) = complement * rotation;
  return basis;
}

}  // namespace pmdplan
