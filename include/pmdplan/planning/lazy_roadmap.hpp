#pragma once
// The roadmap of the lazy PMD planner (Bohlin & Kavraki's Lazy PRM): free nodes joined by edges
// that are assumed free until checked. An edge is Unknown when added, Free or Blocked once its
// motion check has run; the search ignores Blocked edges only.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/planning/roadmap.hpp"

namespace pmdplan {

using EdgeIndex = std::size_t;

enum class LazyEdgeStatus : char { Unknown, Free, Blocked };

struct LazyEdge {
  NodeIndex from = 0;
  NodeIndex to = 0;
  double length = 0.0;  ///< normalised joint-space distance
  LazyEdgeStatus status = LazyEdgeStatus::Unknown;
  std::size_t probesChecked = 0;  ///< inner states of the edge checked one by one so far
};

/// A path through the roadmap: nodes from the first to the last, and the edges between them.
struct LazyPath {
  std::vector<NodeIndex> nodes;
  std::vector<EdgeIndex> edges;
};

class LazyRoadmap {
 public:
  /// `unit`: the configuration normalised to [0, 1] per joint (the space distances are measured in).
  NodeIndex addNode(Configuration configuration, const Eigen::VectorXd& unit);
  EdgeIndex addEdge(NodeIndex from, NodeIndex to);

  std::size_t nodeCount() const { return configurations_.size(); }
  std::size_t edgeCount() const { return edges_.size(); }
  const Configuration& configuration(NodeIndex i) const { return configurations_[i]; }
  const LazyEdge& edge(EdgeIndex e) const { return edges_[e]; }
  LazyEdge& edge(EdgeIndex e) { return edges_[e]; }
  double distance(NodeIndex a, NodeIndex b) const;

  /// Up to `count` nodes other than `node` nearest to it, at most `threshold` away, nearest first;
  /// equal distances by node index.
  std::vector<NodeIndex> nearest(NodeIndex node, std::size_t count, double threshold) const;
  /// A* over the edges not Blocked, the distance to `to` as heuristic; ties by node index, so the
  /// result depends on the roadmap only. Empty nodes if `to` cannot be reached.
  LazyPath shortestPath(NodeIndex from, NodeIndex to) const;

  void clear();

 private:
  std::vector<Configuration> configurations_;
  std::vector<double> units_;  ///< the nodes' normalised coordinates side by side
  std::size_t dimension_ = 0;
  std::vector<std::vector<EdgeIndex>> adjacency_;
  std::vector<LazyEdge> edges_;
};

}  // namespace pmdplan
