#pragma once
// One tree of the bidirectional PMD planner: free configurations, each joined to its parent by a
// straight segment whose motion check may be pending (lazy), the root first. Nodes keep their
// normalised coordinates side by side for the nearest-node scan (trees stay small: tens to a few
// thousand nodes). A segment found blocked cuts its node off with everything below it.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "pmdplan/model/configuration.hpp"

namespace pmdplan {

class ConnectTree {
 public:
  using Node = std::size_t;
  static constexpr Node kNoParent = static_cast<Node>(-1);

  /// `unit`: the configuration normalised to [0, 1] per joint. The first node is the root; every
  /// other node's parent is a live node added before it. The segment to the parent starts unchecked.
  Node add(Configuration configuration, const Eigen::VectorXd& unit, Node parent);

  /// Nodes ever added, cut ones included.
  std::size_t size() const { return parents_.size(); }
  /// Nodes not cut off.
  std::size_t liveCount() const { return liveCount_; }
  bool isLive(Node n) const { return live_[n] != 0; }
  const Configuration& configuration(Node n) const { return configurations_[n]; }
  Eigen::Map<const Eigen::VectorXd> unit(Node n) const;
  Node parent(Node n) const { return parents_[n]; }

  /// Whether the segment from `n` to its parent has passed its motion check.
  bool segmentChecked(Node n) const { return checked_[n] != 0; }
  void markSegmentFree(Node n) { checked_[n] = 1; }
  /// The segment from `n` to its parent is blocked: `n` and every node below it are cut off.
  void cut(Node n);

  /// The live node nearest to `unit` (normalised Euclidean distance); ties by the lower index.
  /// The root is never cut, so there is one.
  Node nearest(const Eigen::VectorXd& unit) const;
  /// The nodes from `n` up to the root, `n` first.
  std::vector<Node> branch(Node n) const;

  void clear();

 private:
  std::vector<Configuration> configurations_;
  std::vector<double> units_;
  std::vector<Node> parents_;
  std::vector<char> checked_;
  std::vector<char> live_;
  std::size_t liveCount_ = 0;
  std::size_t dimension_ = 0;
};

}  // namespace pmdplan
