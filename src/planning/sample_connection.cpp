#include "pmdplan/planning/sample_connection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pmdplan {
namespace {

using Candidate = std::pair<double, NodeIndex>;  // (distance, node): ordered by distance, then index

}  // namespace

std::vector<NodeIndex> findNeighbours(const Roadmap& roadmap, NodeIndex node, std::size_t count, double threshold) {
  std::vector<Candidate> candidates;
  candidates.reserve(roadmap.nodeCount());
  // One pass over the nodes' coordinates side by side (Roadmap::distance's arithmetic).
  const std::size_t dimension = roadmap.dimension();
  const double* units = roadmap.units();
  const double* u = units + node * dimension;
  for (NodeIndex other = 0; other < roadmap.nodeCount(); ++other) {
    if (other == node) continue;
    const double* v = units + other * dimension;
    double sum = 0.0;
    for (std::size_t i = 0; i < dimension; ++i) sum += (u[i] - v[i]) * (u[i] - v[i]);
    const double d = std::sqrt(sum);
    if (d <= threshold) candidates.emplace_back(d, other);
  }
  const std::size_t kept = std::min(count, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(kept), candidates.end());
  std::vector<NodeIndex> neighbours;
  neighbours.reserve(kept);
  for (std::size_t i = 0; i < kept; ++i) neighbours.push_back(candidates[i].second);
  return neighbours;
}

std::size_t connectSample(Roadmap& roadmap, NodeIndex node, const ConnectionRule& rule,
                          std::optional<NodeIndex> forcedNeighbour, MotionValidator& motionValidator) {
  std::vector<NodeIndex> neighbours = findNeighbours(roadmap, node, rule.neighbours, rule.threshold);
  if (forcedNeighbour && *forcedNeighbour != node &&
      std::find(neighbours.begin(), neighbours.end(), *forcedNeighbour) == neighbours.end()) {
    // Keep "nearest first" with the forced node among the others.
    const double d = roadmap.distance(node, *forcedNeighbour);
    auto at = std::find_if(neighbours.begin(), neighbours.end(), [&](NodeIndex other) {
      const double dOther = roadmap.distance(node, other);
      return dOther > d || (dOther == d && other > *forcedNeighbour);
    });
    neighbours.insert(at, *forcedNeighbour);
  }
  std::size_t added = 0;
  for (const NodeIndex neighbour : neighbours) {
    if (roadmap.sameComponent(neighbour, node)) continue;
    if (motionValidator.isValid(roadmap.node(neighbour).configuration, roadmap.node(node).configuration)) {
      roadmap.addEdge(neighbour, node);
      ++added;
    }
  }
  return added;
}

}  // namespace pmdplan
