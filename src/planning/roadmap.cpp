#include "pmdplan/planning/roadmap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pmdplan {

NodeIndex Roadmap::addNode(RoadmapNode node) {
  if (!nodes_.empty() && node.unit.size() != nodes_.front().unit.size())
    throw std::invalid_argument("Roadmap::addNode: node has " + std::to_string(node.unit.size()) +
                                " normalised coordinates, the roadmap " + std::to_string(nodes_.front().unit.size()));
  dimension_ = static_cast<std::size_t>(node.unit.size());
  units_.insert(units_.end(), node.unit.data(), node.unit.data() + node.unit.size());
  smallestStep_.push_back(node.step);
  largestStep_.push_back(node.step);
  nodes_.push_back(std::move(node));
  adjacency_.emplace_back();
  components_.add();
  return nodes_.size() - 1;
}

void Roadmap::addEdge(NodeIndex a, NodeIndex b) {
  if (a >= nodes_.size() || b >= nodes_.size() || a == b)
    throw std::invalid_argument("Roadmap::addEdge: bad edge " + std::to_string(a) + "-" + std::to_string(b));
  const double length = distance(a, b);
  adjacency_[a].push_back({b, length});
  adjacency_[b].push_back({a, length});
  const std::size_t rootA = components_.find(a), rootB = components_.find(b);
  if (components_.unite(a, b)) {
    const std::size_t root = components_.find(a);
    smallestStep_[root] = std::min(smallestStep_[rootA], smallestStep_[rootB]);
    largestStep_[root] = std::max(largestStep_[rootA], largestStep_[rootB]);
  }
  ++edgeCount_;
}

double Roadmap::distance(NodeIndex a, NodeIndex b) const {
  // A plain loop in index order: Eigen's vectorised norm() sums in an order that depends on the
  // SIMD width, and a last-bit difference could reorder neighbours on another machine.
  const double* u = units_.data() + a * dimension_;
  const double* v = units_.data() + b * dimension_;
  double sum = 0.0;
  for (std::size_t i = 0; i < dimension_; ++i) sum += (u[i] - v[i]) * (u[i] - v[i]);
  return std::sqrt(sum);
}

void Roadmap::clear() {
  nodes_.clear();
  units_.clear();
  smallestStep_.clear();
  largestStep_.clear();
  adjacency_.clear();
  components_.clear();
  edgeCount_ = 0;
}

}  // namespace pmdplan
