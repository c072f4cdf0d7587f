#pragma once
// The planner's settings as Python passes them (bind_planner_settings.cpp holds the fields).
#include <pybind11/pybind11.h>

#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/planner_parameters.hpp"

namespace pmdplan::python {

namespace py = pybind11;

/// `settings` (a PlannerSettings, or None for the mode's defaults) as the library's parameters.
PlannerParameters plannerParametersFrom(py::handle settings, HandSamplingMode mode);

/// PlannerParameters::check() with the field named as the CLI's option ("--time-limit").
void checkPlannerParameters(const PlannerParameters& parameters);

}  // namespace pmdplan::python
