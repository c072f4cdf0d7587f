#pragma once
// What the fast checker's geometric stages say about a configuration, and how its checks were
// decided (fast_collision_checker.hpp).
#include <cstddef>
#include <utility>
#include <vector>

namespace pmdplan {

/// What the geometric stages alone say about one configuration (no FCL).
struct ScreenResult {
  /// Pairs proven to overlap by more than the band (FCL agrees: they collide).
  std::vector<std::pair<int, int>> overlappingSelf;              ///< link indices
  std::vector<std::pair<int, std::size_t>> overlappingObstacle;  ///< (link, obstacle index)
  /// Pairs neither proven apart nor overlapping: FCL decides them.
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
  std::size_t provenColliding = 0;     ///< a pair proven overlapping (FCL not asked)
  std::size_t confirmedFree = 0;       ///< uncertain pairs, all found free by FCL
  std::size_t confirmedColliding = 0;  ///< an uncertain pair found colliding by FCL
  std::size_t pairsConfirmed = 0;      ///< FCL pair tests run
};

}  // namespace pmdplan
