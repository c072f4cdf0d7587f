#include "pmdplan/planning/connect_tree.hpp"

#include <limits>
#include <stdexcept>

namespace pmdplan {

ConnectTree::Node ConnectTree::add(Configuration configuration, const Eigen::VectorXd& unit, Node parent) {
  if (parents_.empty()) {
    if (parent != kNoParent) throw std::invalid_argument("ConnectTree::add: the root has no parent");
    dimension_ = static_cast<std::size_t>(unit.size());
  } else if (parent >= parents_.size() || !live_[parent]) {
    throw std::invalid_argument("ConnectTree::add: the parent is not a live node of the tree");
  }
  if (static_cast<std::size_t>(unit.size()) != dimension_)
    throw std::invalid_argument("ConnectTree::add: the node's dimension differs from the root's");
  configurations_.push_back(std::move(configuration));
  units_.insert(units_.end(), unit.data(), unit.data() + unit.size());
  parents_.push_back(parent);
  checked_.push_back(parent == kNoParent ? 1 : 0);
  live_.push_back(1);
  ++liveCount_;
  return parents_.size() - 1;
}

Eigen::Map<const Eigen::VectorXd> ConnectTree::unit(Node n) const {
  return {units_.data() + n * dimension_, static_cast<Eigen::Index>(dimension_)};
}

void ConnectTree::cut(Node n) {
  if (n == 0 || n >= parents_.size()) throw std::invalid_argument("ConnectTree::cut: not a node below the root");
  // A node's parent was added before it, so one pass in order reaches every node below `n`.
  for (Node i = n; i < parents_.size(); ++i)
    if (live_[i] && (i == n || !live_[parents_[i]])) {
      live_[i] = 0;
      --liveCount_;
    }
}

ConnectTree::Node ConnectTree::nearest(const Eigen::VectorXd& unit) const {
  if (parents_.empty()) throw std::logic_error("ConnectTree::nearest: the tree is empty");
  Node best = 0;
  double bestSquared = std::numeric_limits<double>::infinity();
  for (Node n = 0; n < parents_.size(); ++n) {
    if (!live_[n]) continue;
    const double* u = units_.data() + n * dimension_;
    double sum = 0.0;
    for (std::size_t i = 0; i < dimension_; ++i) {
      const double d = u[i] - unit[static_cast<Eigen::Index>(i)];
      sum += d * d;
    }
    if (sum < bestSquared) {
      bestSquared = sum;
      best = n;
    }
  }
  return best;
}

std::vector<ConnectTree::Node> ConnectTree::branch(Node n) const {
  std::vector<Node> nodes;
  for (Node at = n; at != kNoParent; at = parents_[at]) nodes.push_back(at);
  return nodes;
}

void ConnectTree::clear() {
  configurations_.clear();
  units_.clear();
  parents_.clear();
  checked_.clear();
  live_.clear();
  liveCount_ = 0;
  dimension_ = 0;
}

}  // namespace pmdplan
