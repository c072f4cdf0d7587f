#include "pmdplan/planning/planner_settings.hpp"

#include <cmath>
#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

constexpr PlannerPreset kPresets[] = {PlannerPreset::Paper, PlannerPreset::Kautham, PlannerPreset::Wide};

}  // namespace

std::string plannerPresetName(PlannerPreset preset) {
  switch (preset) {
    case PlannerPreset::Paper:
      return "paper";
    case PlannerPreset::Kautham:
      return "kautham";
    case PlannerPreset::Wide:
      return "wide";
  }
  return "paper";
}

std::optional<PlannerPreset> parsePlannerPreset(const std::string& name) {
  for (const PlannerPreset preset : kPresets)
    if (plannerPresetName(preset) == name) return preset;
  return std::nullopt;
}

std::string knownPlannerPresetNames() {
  std::string names;
  for (const PlannerPreset preset : kPresets) names += (names.empty() ? "" : ", ") + plannerPresetName(preset);
  return names;
}

PlannerSettings PlannerSettings::preset(PlannerPreset preset, HandSamplingMode mode) {
  PlannerSettings parameters;
  if (mode == HandSamplingMode::FullSpace) {  // Table 3's values in parentheses
    parameters.armTrials = 20;
    parameters.handTrials = 20;
  }
  if (preset == PlannerPreset::Kautham) {
    parameters.neighbourThreshold = 4.0;
    parameters.rhoAGrowth = ArmBoxGrowth::Linear;
  } else if (preset == PlannerPreset::Wide) {
    parameters.neighbourThreshold = 2.0;
  }
  return parameters;
}

void PlannerSettings::check() const {
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  if (!positive(rhoA) || rhoA > 1.0)
    throw InputError("", "rho-a",
                     "must be a number in (0, 1] (normalised arm-joint units), got " + messageNumberText(rhoA));
  if (neighbours < 1) throw InputError("", "neighbours", "must be a whole number >= 1");
  if (!positive(neighbourThreshold))
    throw InputError(
        "", "neighbour-threshold",
        "must be a positive, finite factor of the start-goal distance, got " + messageNumberText(neighbourThreshold));
  if (armTrials < 1)
    throw InputError("", "arm-trials", "must be a whole number >= 1, got " + std::to_string(armTrials));
  if (handTrials < 1)
    throw InputError("", "hand-trials", "must be a whole number >= 1, got " + std::to_string(handTrials));
  if (sweepVisits < 1) throw InputError("", "sweep-visits", "must be a whole number >= 1");
  if (maxSamples < 1) throw InputError("", "max-samples", "must be a whole number >= 1");
  if (!positive(pmdBox.kappa))
    throw InputError(
        "", "kappa",
        "must be a positive, finite number of standard deviations, got " + messageNumberText(pmdBox.kappa));
  if (pmdBox.maxPmds < 1)
    throw InputError("", "max-pmds", "must be a whole number >= 1, got " + std::to_string(pmdBox.maxPmds));
  if (!(timeLimit > 0.0) || (std::isfinite(timeLimit) && timeLimit > kMaxFiniteTimeLimitSeconds))
    throw InputError(
        "", "time-limit",
        "must be a positive number of seconds up to 1e6 (or inf: no limit), got " + messageNumberText(timeLimit));
  lazy.check();
  connect.check();
}

}  // namespace pmdplan
