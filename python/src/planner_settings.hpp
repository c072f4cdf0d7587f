#pragma once
// The planner's settings as Python passes them (bind_planner_settings.cpp holds the fields).
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>

#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan::python {

namespace py = pybind11;

/// `settings` (a PlannerSettings, or None for the mode's defaults) as the library's parameters,
/// with plan()'s seed and time_limit arguments, when given, in place of theirs.
PlannerSettings plannerParametersFrom(py::handle settings, HandSamplingMode mode, std::optional<std::uint64_t> seed,
                                        std::optional<double> timeLimit);

std::uint64_t seedOf(const PlannerSettings& parameters);
/// The time limit plan() gives planners without settings (OMPL's).
double defaultTimeLimit();

/// PlannerSettings::check() with the field named as the CLI's option ("--time-limit").
void checkPlannerParameters(const PlannerSettings& parameters);

}  // namespace pmdplan::python
