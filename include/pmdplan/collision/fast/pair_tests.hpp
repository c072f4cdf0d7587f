#pragma once
// The fast checker one pair at a time, for motion checks that follow each pair along a segment
// (FastSegmentChecker). Pairs are numbered: the self pairs with a moving link, then every moving
// link with geometry against every obstacle — the order of checkBatch's pairGaps.
#include <cstddef>

#include "pmdplan/model/configuration.hpp"

namespace pmdplan {
namespace fast {
class CheckerModel;
class CheckerScratch;
}  // namespace fast

class PairTests {
 public:
  std::size_t pairCount() const;
  /// Forward kinematics of q for test of the given pairs only (not counted as a check).
  void pose(const Configuration& q, const std::size_t* pairs, std::size_t count);
  /// Pair `pair` at the posed state: a lower bound on its gap (m), 0 if only the exact checker
  /// could clear it (and did), -1 if it collides.
  double test(std::size_t pair);
  /// After FastCollisionChecker::setMotion: 1 / (how far, in m, the pair's two sides may approach
  /// each other over the whole segment), so gap * share is the fraction of the segment it stays
  /// apart for.
  double share(std::size_t pair) const;

 private:
  friend class FastCollisionChecker;
  PairTests(const fast::CheckerModel& model, fast::CheckerScratch& scratch) : model_(&model), scratch_(&scratch) {}
  const fast::CheckerModel* model_;
  fast::CheckerScratch* scratch_;
};

}  // namespace pmdplan
