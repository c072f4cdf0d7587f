#pragma once
// Algorithm 3 (ConnectSample): join a new node to its nearest neighbours by free straight segments,
// skipping neighbours already in its component.
#include <cstddef>
#include <optional>
#include <vector>

#include "pmdplan/collision/motion_validator.hpp"
#include "pmdplan/planning/roadmap.hpp"

namespace pmdplan {

/// FINDNEIGHBORS: up to `count` (K) nodes nearest to `node` in normalised joint space, at most
/// `threshold` away, nearest first; equal distances are ordered by node index so the result never
/// depends on anything but the roadmap. Brute force: the roadmaps stay small.
std::vector<NodeIndex> findNeighbours(const Roadmap& roadmap, NodeIndex node, std::size_t count, double threshold);

struct ConnectionRule {
  std::size_t neighbours = 10;  ///< K
  double threshold = 0.0;       ///< neighbouring threshold, d(c_ini, c_goal)
};

/// Algorithm 3 for a node already added. `forcedNeighbour` (c_ini for samples of the first
/// hypercube, c_goal for the last) is tried whether or not it is among the K nearest or within the
/// threshold (Sect. 5.2). Candidates are tried nearest first; one whose component the node has
/// already joined is skipped without a motion check. Returns the number of edges added.
std::size_t connectSample(Roadmap& roadmap, NodeIndex node, const ConnectionRule& rule,
                          std::optional<NodeIndex> forcedNeighbour, MotionValidator& motionValidator);

}  // namespace pmdplan
