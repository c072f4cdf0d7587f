#include "pmdplan/planning/lazy_roadmap.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace pmdplan {

NodeIndex LazyRoadmap::addNode(Configuration configuration, const Eigen::VectorXd& unit) {
  if (configurations_.empty()) dimension_ = static_cast<std::size_t>(unit.size());
  configurations_.push_back(std::move(configuration));
  units_.insert(units_.end(), unit.data(), unit.data() + unit.size());
  adjacency_.emplace_back();
  return configurations_.size() - 1;
}

EdgeIndex LazyRoadmap::addEdge(NodeIndex from, NodeIndex to) {
  edges_.push_back({from, to, distance(from, to), LazyEdgeStatus::Unknown, 0});
  const EdgeIndex e = edges_.size() - 1;
  adjacency_[from].push_back(e);
  adjacency_[to].push_back(e);
  return e;
}

double LazyRoadmap::distance(NodeIndex a, NodeIndex b) const {
  const double* u = units_.data() + a * dimension_;
  const double* v = units_.data() + b * dimension_;
  double sum = 0.0;
  for (std::size_t i = 0; i < dimension_; ++i) sum += (u[i] - v[i]) * (u[i] - v[i]);
  return std::sqrt(sum);
}

std::vector<NodeIndex> LazyRoadmap::nearest(NodeIndex node, std::size_t count, double threshold) const {
  std::vector<std::pair<double, NodeIndex>> candidates;
  candidates.reserve(nodeCount());
  for (NodeIndex other = 0; other < nodeCount(); ++other) {
    if (other == node) continue;
    const double d = distance(node, other);
    if (d <= threshold) candidates.emplace_back(d, other);
  }
  const std::size_t kept = std::min(count, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(kept), candidates.end());
  std::vector<NodeIndex> result;
  result.reserve(kept);
  for (std::size_t i = 0; i < kept; ++i) result.push_back(candidates[i].second);
  return result;
}

LazyPath LazyRoadmap::shortestPath(NodeIndex from, NodeIndex to) const {
  constexpr double unreached = std::numeric_limits<double>::infinity();
  constexpr EdgeIndex none = std::numeric_limits<EdgeIndex>::max();
  std::vector<double> cost(nodeCount(), unreached);
  std::vector<EdgeIndex> via(nodeCount(), none);
  std::vector<char> closed(nodeCount(), 0);
  using Key = std::pair<double, NodeIndex>;  // (cost + heuristic, node): ties by node index
  std::priority_queue<Key, std::vector<Key>, std::greater<Key>> open;
  cost[from] = 0.0;
  open.emplace(distance(from, to), from);
  while (!open.empty()) {
    const NodeIndex current = open.top().second;
    open.pop();
    if (closed[current] != 0) continue;
    closed[current] = 1;
    if (current == to) break;
    for (const EdgeIndex e : adjacency_[current]) {
      const LazyEdge& edge = edges_[e];
      if (edge.status == LazyEdgeStatus::Blocked) continue;
      const NodeIndex next = edge.from == current ? edge.to : edge.from;
      const double candidate = cost[current] + edge.length;
      if (closed[next] != 0 || !(candidate < cost[next])) continue;
      cost[next] = candidate;
      via[next] = e;
      open.emplace(candidate + distance(next, to), next);
    }
  }
  LazyPath path;
  if (closed[to] == 0) return path;
  for (NodeIndex at = to;;) {
    path.nodes.push_back(at);
    if (at == from) break;
    const LazyEdge& edge = edges_[via[at]];
    path.edges.push_back(via[at]);
    at = edge.from == at ? edge.to : edge.from;
  }
  std::reverse(path.nodes.begin(), path.nodes.end());
  std::reverse(path.edges.begin(), path.edges.end());
  return path;
}

void LazyRoadmap::clear() {
  configurations_.clear();
  units_.clear();
  dimension_ = 0;
  adjacency_.clear();
  edges_.clear();
}

}  // namespace pmdplan
