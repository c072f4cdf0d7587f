#pragma once
// The probabilistic roadmap: collision-free configurations joined by free straight segments, with
// its connected components kept up to date as edges are added.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/disjoint_sets.hpp"

namespace pmdplan {

using NodeIndex = std::size_t;

struct RoadmapNode {
  Configuration configuration;
  /// The configuration normalised to [0, 1] per joint: the space distances are measured in.
  Eigen::VectorXd unit;
  /// Where on the start-goal arm segment the hypercube it came from was centred (fraction from
  /// the start): 0 for the start, 1 for the goal. Drives the search range of Fig. 13.
  double step = 0.0;
  /// Active hand-sampling dimension that produced it; 0 for the start and the goal.
  int handDimension = 0;
};

struct RoadmapEdge {
  NodeIndex target = 0;
  double length = 0.0;  ///< normalised joint-space distance
};

class Roadmap {
 public:
  NodeIndex addNode(RoadmapNode node);
  /// Joins two nodes (undirected); the length is their normalised distance.
  void addEdge(NodeIndex a, NodeIndex b);

  bool sameComponent(NodeIndex a, NodeIndex b) const { return components_.same(a, b); }
  std::size_t componentCount() const { return components_.setCount(); }
  /// The smallest and the largest step of the nodes in i's component (kept as edges join them).
  double smallestStep(NodeIndex i) const { return smallestStep_[components_.find(i)]; }
  double largestStep(NodeIndex i) const { return largestStep_[components_.find(i)]; }

  std::size_t nodeCount() const { return nodes_.size(); }
  std::size_t edgeCount() const { return edgeCount_; }
  const RoadmapNode& node(NodeIndex i) const { return nodes_[i]; }
  const std::vector<RoadmapEdge>& edges(NodeIndex i) const { return adjacency_[i]; }
  /// Normalised distance between two nodes.
  double distance(NodeIndex a, NodeIndex b) const;
  /// The normalised coordinates of every node, node after node (dimension() values each).
  const double* units() const { return units_.data(); }
  std::size_t dimension() const { return dimension_; }

  void clear();

 private:
  std::vector<RoadmapNode> nodes_;
  std::vector<double> units_;  ///< the nodes' `unit` side by side, for scans over all of them
  std::size_t dimension_ = 0;
  std::vector<std::vector<RoadmapEdge>> adjacency_;
  DisjointSets components_;
  std::vector<double> smallestStep_, largestStep_;  ///< by component representative
  std::size_t edgeCount_ = 0;
};

}  // namespace pmdplan
