#pragma once
// Roadmaps in the plane for the search and connection tests: a node at (x, y), the same point as its
// configuration and its unit coordinates, from the middle of the segment (step 0.5), hand dimension 2.
#include <Eigen/Core>

#include "pmdplan/planning/roadmap.hpp"

namespace pmdplan::test {

inline NodeIndex addAt(Roadmap& roadmap, double x, double y) {
  return roadmap.addNode({Eigen::Vector2d(x, y), Eigen::Vector2d(x, y), 0.5, 2});
}

}  // namespace pmdplan::test
