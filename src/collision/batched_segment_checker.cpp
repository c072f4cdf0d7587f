#include "pmdplan/collision/batched_segment_checker.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pmdplan {

void bisectionOrder(long intervals, std::vector<long>& order) {
  order.clear();
  if (intervals < 2) return;
  // Breadth-first over the ranges (lo, hi), as SegmentChecker's queue visits them; `order` itself
  // holds the queue of range starts, the midpoints being the visited states.
  std::vector<std::pair<long, long>> ranges{{0, intervals}};
  for (std::size_t next = 0; next < ranges.size(); ++next) {
    const auto [lo, hi] = ranges[next];
    if (hi - lo < 2) continue;
    const long mid = lo + (hi - lo) / 2;
    order.push_back(mid);
    ranges.emplace_back(lo, mid);
    ranges.emplace_back(mid, hi);
  }
}

BatchedSegmentChecker::BatchedSegmentChecker(FastCollisionChecker& states, const RobotModel& model, double tolerance)
    : states_(states), bound_(model), tolerance_(tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("the motion tolerance must be positive");
}

bool BatchedSegmentChecker::isValid(const Configuration& from, const Configuration& to) {
  const long n = bound_.intervals(from, to, tolerance_);
  if (n < 2) return true;
  bisectionOrder(n, order_);
  covered_.assign(static_cast<std::size_t>(n) + 1, 0);
  // Safe values come back as fractions of this segment (per-pair displacement bounds, linear
  // along it); a state m steps away lies m / n of the segment away.
  states_.setMotion(from, to);
  const Configuration delta = to - from;

  constexpr int kLanes = FastCollisionChecker::kLanes;
  Configuration batch[kLanes];
  const Configuration* pointers[kLanes];
  long indices[kLanes];
  bool valid[kLanes];
  double safe[kLanes];
  std::size_t next = 0;
  while (next < order_.size()) {
    int count = 0;
    for (; next < order_.size() && count < kLanes; ++next) {
      const long i = order_[next];
      if (covered_[static_cast<std::size_t>(i)]) {
        ++statesSkipped_;
        continue;
      }
      // The very expression SegmentChecker uses, so the states are bit for bit the same.
      batch[count] = from + delta * (static_cast<double>(i) / static_cast<double>(n));
      pointers[count] = &batch[count];
      indices[count++] = i;
    }
    if (count == 0) break;
    states_.checkBatch(pointers, count, valid, safe);
    statesChecked_ += static_cast<std::size_t>(count);
    for (int k = 0; k < count; ++k)
      if (!valid[k]) return false;
    for (int k = 0; k < count; ++k) {
      if (!(safe[k] > 0.0)) continue;
      // Skip the states strictly within the safe fraction (a relative allowance for the rounding
      // of the interpolated states).
      const double reach = safe[k] * static_cast<double>(n) * (1.0 - 1e-9);
      const long m = reach >= static_cast<double>(n) ? n : static_cast<long>(std::ceil(reach)) - 1;
      const long lo = std::max(1L, indices[k] - m), hi = std::min(n - 1, indices[k] + m);
      std::fill(covered_.begin() + lo, covered_.begin() + hi + 1, 1);
    }
  }
  return true;
}

}  // namespace pmdplan
