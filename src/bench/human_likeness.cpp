#include "pmdplan/bench/human_likeness.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pmdplan/bench/human_likeness_independent.hpp"
#include "pmdplan/synergy/synergy_readout.hpp"

namespace pmdplan {
namespace {

struct PostureMeasure {
  double subspaceDistance;
  double mahalanobis;
};

PostureMeasure measurePosture(const SynergyModel& model, const std::vector<int>& slots, const Configuration& q,
                              const HumanLikenessSettings& options) {
  const SynergyReadout readout = synergyReadout(model, slots, q);
  const int k = std::clamp(options.subspaceDirections, 0, model.directionCount());
  double squared = 0.0;
  for (int i = 0; i < model.directionCount(); ++i) {
    const double sigma = model.sigma[i];
    if (sigma < options.minimumSigma) continue;
    const double z = readout.coefficients[i] / sigma;
    squared += z * z;
  }
  return {readout.distanceFromSubspace[k], std::sqrt(squared)};
}

}  // namespace

HumanLikeness measureHumanLikeness(const std::vector<Configuration>& path, const PlanningSpace& space,
                                   const SynergyModel& model, const std::vector<int>& slots,
                                   const HumanLikenessSettings& options) {
  if (path.empty()) throw std::invalid_argument("measureHumanLikeness: empty path");
  if (!(options.step > 0.0)) throw std::invalid_argument("measureHumanLikeness: step must be positive");
  const std::optional<IndependentHandReference> reference = independentHandReference(space);
  double distanceSum = 0.0, mahalanobisSum = 0.0, distanceMax = 0.0, authorsSum = 0.0, authorsMax = 0.0;
  std::size_t points = 0;
  const auto add = [&](const Configuration& q) {
    const PostureMeasure m = measurePosture(model, slots, q, options);
    distanceSum += m.subspaceDistance;
    mahalanobisSum += m.mahalanobis;
    distanceMax = std::max(distanceMax, m.subspaceDistance);
    if (reference) {
      const double authors = authorsSubspaceDistance(*reference, q);
      authorsSum += authors;
      authorsMax = std::max(authorsMax, authors);
    }
    ++points;
  };
  add(path.front());
  for (std::size_t s = 1; s < path.size(); ++s) {
    const Configuration& a = path[s - 1];
    const Configuration& b = path[s];
    const auto intervals = static_cast<long>(std::max(1.0, std::ceil(space.distance(a, b) / options.step)));
    for (long i = 1; i <= intervals; ++i) {
      const double t = static_cast<double>(i) / static_cast<double>(intervals);
      add(i == intervals ? b : Configuration(a + t * (b - a)));
    }
  }
  HumanLikeness result;
  result.subspaceDistanceMean = distanceSum / static_cast<double>(points);
  result.subspaceDistanceMax = distanceMax;
  result.mahalanobisMean = mahalanobisSum / static_cast<double>(points);
  if (reference)
    result.independent = IndependentHumanLikeness{authorsSum / static_cast<double>(points), authorsMax,
                                                  jointCoupling(path, space, *reference)};
  return result;
}

}  // namespace pmdplan
