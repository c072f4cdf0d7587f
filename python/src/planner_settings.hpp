#pragma once
// The planner's settings as Python passes them (bind_planner_settings.cpp makes a property of every
// row of planning/planner_setting_table.hpp).
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>

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

/// An InputError's field as Python names it: a setting's key ("time-limit") as its property name
/// ("time_limit"); any other field as it is.
std::string pythonFieldName(const std::string& field);

/// PlannerSettings::check() with the field named as the Python property ("time_limit").
void checkPlannerParameters(const PlannerSettings& parameters);

}  // namespace pmdplan::python
