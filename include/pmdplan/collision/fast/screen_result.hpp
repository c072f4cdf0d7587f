#pragma once
// What the fast checker's geometric stages say about a configuration, and how its checks were
// decided (fast_collision_checker.hpp).
#include <cstddef>
#include <utility>
#include <vector>

namespace pmdplan {

/// What the geometric stages alone say about one configuration (no exact checks).
struct ScreenResult {
  /// Pairs proven to overlap by more than the band (the exact checker agrees: they collide).
  std::vector<std::pair<int, int>> overlappingSelf;              ///< link indices
  std::vector<std::pair<int, std::size_t>> overlappingObstacle;  ///< (link, obstacle index)
  /// Pairs neither proven apart nor overlapping: the exact checker decides them.
  std::vector<std::pair<int, int>> uncertainSelf;
  std::vector<std::pair<int, std::size_t>> uncertainObstacle;
  /// When every pair is proven apart: how far (m) every point of the robot may move with all of
  /// them staying apart (a lower bound from the gaps, halved for two moving links); else 0.
  double safeDisplacement = 0.0;
  bool provenFree() const {
    return overlappingSelf.empty() && overlappingObstacle.empty() && uncertainSelf.empty() && uncertainObstacle.empty();
  }
};

/// How the checks of a FastCollisionChecker were decided.
struct FastCheckStatistics {
  std::size_t provenFree = 0;          ///< every pair proven apart by the geometric stages
  std::size_t provenColliding = 0;     ///< a pair proven overlapping (the exact checker not asked)
  std::size_t confirmedFree = 0;       ///< uncertain pairs, all found free by the exact checker
  std::size_t confirmedColliding = 0;  ///< an uncertain pair found colliding by the exact checker
  std::size_t pairsConfirmed = 0;      ///< exact pair tests run
};

}  // namespace pmdplan
