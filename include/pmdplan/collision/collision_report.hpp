#pragma once
// Which pairs collide: robot link names, or a link and an obstacle name.
#include <string>
#include <utility>
#include <vector>

namespace pmdplan {

using CollisionPair = std::pair<std::string, std::string>;

struct CollisionReport {
  std::vector<CollisionPair> pairs;  ///< sorted, each pair once
  bool free() const { return pairs.empty(); }
};

/// The pairs as text: "a - b, c - d".
std::string pairsText(const CollisionReport& report);

}  // namespace pmdplan
