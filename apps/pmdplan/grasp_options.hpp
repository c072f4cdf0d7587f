#pragma once
// How a grasp goal's pre-grasp is derived (docs/grasp_goals.md) as command-line options, declared
// the same way on `plan`, which derives it, and `check`, which says whether plan will find one.
#include <CLI/CLI.hpp>

#include "pmdplan/planning/grasp_approach.hpp"

namespace pmdplan::cli {

struct GraspOptions {
  double clearanceMm = 1000.0 * GraspSettings{}.clearance;
  double openingStep = GraspSettings{}.openingStep;
};

/// Declares --grasp-clearance-mm and --opening-step.
void addGraspOptions(CLI::App& app, GraspOptions& options);

/// The settings, checked; throws InputError naming the flag for bad values.
GraspSettings resolveGraspSettings(const GraspOptions& options);

}  // namespace pmdplan::cli
