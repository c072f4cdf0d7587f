#include "pmdplan/collision/fast_segment_checker.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pmdplan {

void bisectionOrder(long intervals, std::vector<long>& order, std::size_t limit) {
  order.clear();
  if (intervals < 2) return;
  // Breadth-first over the ranges (lo, hi), as SegmentChecker's queue visits them; the midpoints
  // are the visited states.
  std::vector<std::pair<long, long>> ranges{{0, intervals}};
  for (std::size_t next = 0; next < ranges.size() && order.size() < limit; ++next) {
    const auto [lo, hi] = ranges[next];
    if (hi - lo < 2) continue;
    const long mid = lo + (hi - lo) / 2;
    order.push_back(mid);
    ranges.emplace_back(lo, mid);
    ranges.emplace_back(mid, hi);
  }
}

FastSegmentChecker::FastSegmentChecker(FastCollisionChecker& states, const RobotModel& model, double tolerance)
    : states_(states), bound_(model), tolerance_(tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("the motion tolerance must be positive");
}

long FastSegmentChecker::reach(double gap, double share, long n) {
  if (!(gap > 0.0)) return 0;
  const double states = gap * share * static_cast<double>(n) * (1.0 - 1e-9);
  if (states >= static_cast<double>(n)) return n;
  // ceil(states) - 1: the whole states strictly below `states`.
  const auto whole = static_cast<long>(states);
  return static_cast<double>(whole) == states ? whole - 1 : whole;
}

bool FastSegmentChecker::isValid(const Configuration& from, const Configuration& to) {
  const long n = bound_.intervals(from, to, tolerance_);
  if (n < 2) return true;
  states_.setMotion(from, to);
  const Configuration delta = to - from;
  // The very expression SegmentChecker uses, so the states are bit for bit the same.
  const auto stateAt = [&](long i, Configuration& q) {
    q.noalias() = from + delta * (static_cast<double>(i) / static_cast<double>(n));
  };
  const std::size_t pairs = states_.pairCount();

  // 1. The coarse states (state 1, where the sweep starts, then the first bisection states), a
  // batch at a time; every pair's gap at each of them is kept.
  bisectionOrder(n, order_, static_cast<std::size_t>(kCoarseStates));
  order_.erase(std::remove(order_.begin(), order_.end(), 1L), order_.end());
  order_.insert(order_.begin(), 1L);
  const auto coarse = static_cast<long>(order_.size());
  coarseGaps_.resize(static_cast<std::size_t>(coarse) * pairs);
  constexpr int kLanes = FastCollisionChecker::kLanes;
  for (long begin = 0; begin < coarse; begin += kLanes) {
    const int count = static_cast<int>(std::min<long>(kLanes, coarse - begin));
    const Configuration* pointers[kLanes];
    bool valid[kLanes];
    double safe[kLanes];
    for (int k = 0; k < count; ++k) {
      stateAt(order_[static_cast<std::size_t>(begin + k)], batch_[k]);
      pointers[k] = &batch_[k];
    }
    states_.checkBatch(pointers, count, valid, safe, coarseGaps_.data() + static_cast<std::size_t>(begin) * pairs);
    statesChecked_ += static_cast<std::size_t>(count);
    for (int k = 0; k < count; ++k)
      if (!valid[k]) return false;
  }

  // 2. The sweep: bucket i lists the pairs whose certificate ends just before state i.
  bucketHead_.assign(static_cast<std::size_t>(n) + 1, -1);
  nextInBucket_.resize(pairs);
  const auto schedule = [&](std::size_t p, long lastFree) {
    if (lastFree + 1 >= n) return;  // free to the end
    nextInBucket_[p] = bucketHead_[static_cast<std::size_t>(lastFree + 1)];
    bucketHead_[static_cast<std::size_t>(lastFree + 1)] = static_cast<int>(p);
  };
  // The farthest state the certificate of pair p from one of the two coarse states on either
  // side of state i covers (-1: neither covers i; a farther one rarely would, and missing it
  // costs a test, never an answer).
  byPosition_.clear();
  for (long c = 0; c < coarse; ++c) byPosition_.emplace_back(order_[static_cast<std::size_t>(c)], c);
  std::sort(byPosition_.begin(), byPosition_.end());
  const auto coarseCover = [&](std::size_t p, long i) {
    long best = -1;
    const double share = states_.pairs().share(p);
    const auto above = std::lower_bound(byPosition_.begin(), byPosition_.end(), std::pair<long, long>(i, -1));
    for (auto it = above == byPosition_.begin() ? above : above - 1; it != byPosition_.end() && it <= above; ++it) {
      const long r = reach(coarseGaps_[static_cast<std::size_t>(it->second) * pairs + p], share, n);
      if (std::abs(i - it->first) <= r) best = std::max(best, it->first + r);
    }
    return best;
  };
  for (std::size_t p = 0; p < pairs; ++p) schedule(p, coarseCover(p, 1));  // state 1 is coarse: covered
  long swept = 0;
  for (long i = 2; i < n; ++i) {
    int p = bucketHead_[static_cast<std::size_t>(i)];
    if (p < 0) continue;
    bucketHead_[static_cast<std::size_t>(i)] = -1;
    // The pairs due here that no coarse state covers are tested at state i, posed for them only.
    covered_.clear();
    testing_.clear();
    for (; p >= 0; p = nextInBucket_[static_cast<std::size_t>(p)]) {
      const auto pair = static_cast<std::size_t>(p);
      const long cover = coarseCover(pair, i);
      if (cover >= i)
        covered_.emplace_back(pair, cover);
      else
        testing_.push_back(pair);
    }
    for (const auto& [pair, cover] : covered_) schedule(pair, cover);
    if (testing_.empty()) continue;
    stateAt(i, state_);
    states_.pairs().pose(state_, testing_.data(), testing_.size());
    ++swept;
    for (const std::size_t pair : testing_) {
      const double gap = states_.pairs().test(pair);
      if (gap < 0.0) {
        statesChecked_ += static_cast<std::size_t>(swept);
        return false;
      }
      schedule(pair, i + reach(gap, states_.pairs().share(pair), n));
    }
  }
  statesChecked_ += static_cast<std::size_t>(swept);
  statesSkipped_ += static_cast<std::size_t>(n - 1 - coarse - swept);
  return true;
}

}  // namespace pmdplan
