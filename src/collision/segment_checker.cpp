#include "pmdplan/collision/segment_checker.hpp"

#include <deque>
#include <stdexcept>

namespace pmdplan {

SegmentChecker::SegmentChecker(StateValidator& states, const RobotModel& model, double tolerance)
    : states_(states), bound_(model), tolerance_(tolerance) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("the motion tolerance must be positive");
}

bool SegmentChecker::isValid(const Configuration& from, const Configuration& to) {
  const long n = bound_.intervals(from, to, tolerance_);
  // Breadth-first bisection of the index range (0, n): each interior state exactly once, coarse
  // to fine.
  std::deque<std::pair<long, long>> ranges{{0, n}};
  Configuration q(from.size());
  while (!ranges.empty()) {
    const auto [lo, hi] = ranges.front();
    ranges.pop_front();
    if (hi - lo < 2) continue;
    const long mid = lo + (hi - lo) / 2;
    q = from + (to - from) * (static_cast<double>(mid) / static_cast<double>(n));
    ++statesChecked_;
    if (!states_.isValid(q)) return false;
    ranges.emplace_back(lo, mid);
    ranges.emplace_back(mid, hi);
  }
  return true;
}

SegmentInspection SegmentChecker::inspect(ExactCollisionChecker& checker, const Configuration& from,
                                          const Configuration& to) const {
  return inspect([&checker](const Configuration& q) { return checker.check(q); }, from, to);
}

SegmentInspection SegmentChecker::inspect(const std::function<CollisionReport(const Configuration&)>& check,
                                          const Configuration& from, const Configuration& to) const {
  SegmentInspection result;
  const long n = bound_.intervals(from, to, tolerance_);
  result.statesNeeded = n + 1;
  for (long i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n);
    const Configuration q = from + (to - from) * t;
    ++result.statesChecked;
    auto report = check(q);
    if (!report.free()) {
      result.free = false;
      result.firstCollision = t;
      result.collisions = std::move(report);
      break;
    }
  }
  return result;
}

}  // namespace pmdplan
