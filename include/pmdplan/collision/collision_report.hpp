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

}  // namespace pmdplan
