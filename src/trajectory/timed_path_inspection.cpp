#include "pmdplan/trajectory/timed_path_inspection.hpp"

#include <cmath>
#include <stdexcept>

namespace pmdplan {

TimedPathInspection inspectTimedPath(const TimedPath& timed, StateValidator& states, const SweptDistanceBound& bound,
                                     double tolerance, bool arcsOnly) {
  if (!(tolerance > 0.0)) throw std::invalid_argument("the inspection tolerance must be positive");
  TimedPathInspection inspection;
  const auto& levers = bound.leverArms();
  for (const BlendedPath* path : timed.paths()) {
    for (const auto& segment : path->segments()) {
      if (arcsOnly && !segment.circular) continue;
      double rate = 0.0;  // metres any point moves per unit of path length, at most
      for (Eigen::Index i = 0; i < segment.x.size(); ++i) {
        const double joint = segment.circular ? std::hypot(segment.x[i], segment.y[i]) : std::abs(segment.x[i]);
        rate += levers[static_cast<std::size_t>(i)] * joint;
      }
      const long intervals = std::max(1L, static_cast<long>(std::ceil(segment.length * rate / tolerance)));
      for (long k = 0; k <= intervals; ++k) {
        const double s = segment.start + segment.length * static_cast<double>(k) / static_cast<double>(intervals);
        const Configuration q = path->position(s, k == intervals);
        ++inspection.statesChecked;
        if (!states.isValid(q)) {
          inspection.free = false;
          inspection.firstCollision = q;
          return inspection;
        }
      }
    }
  }
  return inspection;
}

}  // namespace pmdplan
