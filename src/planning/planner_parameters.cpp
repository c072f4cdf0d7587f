#include "pmdplan/planning/planner_parameters.hpp"

#include <cmath>
#include <string>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

PlannerParameters PlannerParameters::defaultsFor(HandSamplingMode mode) {
  PlannerParameters parameters;
  if (mode == HandSamplingMode::FullSpace) {
    parameters.armTrials = 20;
    parameters.handTrials = 20;
  }
  return parameters;
}

void PlannerParameters::check() const {
  if (!(initialArmHalfSize > 0.0) || !std::isfinite(initialArmHalfSize))
    throw InputError("", "rho-a", "must be a positive number (normalised joint units), got " +
                                      std::to_string(initialArmHalfSize));
  if (neighbourCount < 1) throw InputError("", "neighbours", "must be at least 1");
  if (!(neighbourThresholdFactor > 0.0) || !std::isfinite(neighbourThresholdFactor))
    throw InputError("", "neighbour-threshold", "must be a positive factor of the start-goal distance, got " +
                                                    std::to_string(neighbourThresholdFactor));
  if (armTrials < 1) throw InputError("", "arm-trials", "must be at least 1, got " + std::to_string(armTrials));
  if (handTrials < 1) throw InputError("", "hand-trials", "must be at least 1, got " + std::to_string(handTrials));
  if (minSweepVisits < 1) throw InputError("", "sweep-visits", "must be at least 1");
  if (maxSamples < 1) throw InputError("", "max-samples", "must be at least 1");
  if (!(timeLimit > 0.0) || (std::isfinite(timeLimit) && timeLimit > kMaxFiniteTimeLimitSeconds))
    throw InputError("", "time-limit", "must be a positive number of seconds up to 1e6 (or inf: no limit), got " + std::to_string(timeLimit));
}

}  // namespace pmdplan
