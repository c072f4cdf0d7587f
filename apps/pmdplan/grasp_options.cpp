#include "grasp_options.hpp"

#include "pmdplan/core/input_error.hpp"

namespace pmdplan::cli {

void addGraspOptions(CLI::App& app, GraspOptions& options) {
  app.add_option("--grasp-clearance-mm", options.clearanceMm,
                 "A grasp goal's derived pre-grasp clears the target by this much");
  app.add_option("--opening-step", options.openingStep,
                 "Step of the pre-grasp search, a fraction of the way to the open hand");
}

GraspSettings resolveGraspSettings(const GraspOptions& options) {
  GraspSettings settings;
  settings.clearance = options.clearanceMm / 1000.0;
  settings.openingStep = options.openingStep;
  try {
    settings.check();
  } catch (const InputError& e) {
    throw InputError("", "--" + e.field(), e.message());
  }
  return settings;
}

}  // namespace pmdplan::cli
