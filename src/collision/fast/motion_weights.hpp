#pragma once
// How fast each pair of the fast checker may close its gap as the joints move (checker_model.hpp):
// metres per unit of each active joint, per self pair (only the joints below the two links'
// common ancestor count) and per geometric link (its whole chain), and from them the shares that
// turn a gap into a safe displacement, by default or for one straight motion.
#include <cstddef>
#include <utility>
#include <vector>

#include "pmdplan/model/configuration.hpp"
#include "pmdplan/model/robot_model.hpp"

namespace pmdplan::fast {

class MotionWeights {
 public:
  MotionWeights() = default;
  /// For `selfPairs` and `geometricLinks` (link indices); `moving`: per link, does any joint move it.
  MotionWeights(const RobotModel& model, const std::vector<std::pair<int, int>>& selfPairs,
                const std::vector<int>& geometricLinks, const std::vector<char>& moving);

  /// The gap multipliers before any motion is set, in metres: 1 / (the pair's links that move) per
  /// self pair, 1 per geometric link (against an obstacle).
  void defaultShares(std::vector<double>& pairShare, std::vector<double>& linkShare) const;
  /// The multipliers for the straight motion from -> to: 1 / (how far the pair's sides may approach
  /// over the whole segment), rounded up by a relative 1e-9 so rounding never makes a gap look
  /// safer than it is; gap * share is then a fraction of the segment.
  void motionShares(const Configuration& from, const Configuration& to, std::vector<double>& pairShare,
                    std::vector<double>& linkShare) const;

 private:
  std::size_t dof_ = 0;
  std::vector<double> pairWeights_, linkWeights_;  ///< dof_ values per pair / link
  std::vector<double> defaultPairShare_;
  std::size_t linkCount_ = 0;
};

}  // namespace pmdplan::fast
