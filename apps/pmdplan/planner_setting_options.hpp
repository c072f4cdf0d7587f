#pragma once
// The planner settings of plannerSettingTable() and `--preset` as command-line options, declared
// the same way on every command that runs the PMD roadmap planner (`plan`, `bench`).
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan::cli {

struct PlannerSettingOptions {
  std::string preset = plannerPresetName(PlannerPreset::Paper);
  std::vector<std::string> values;    ///< per table row, the text given on the command line
  std::vector<CLI::Option*> options;  ///< per table row; count() > 0 when given
};

/// Declares --preset and one option per setting, each with the paper's default in its help.
/// `seedHelp` replaces the seed's help line (bench's --seed is the first of the runs' seeds).
void addPlannerSettingOptions(CLI::App& app, PlannerSettingOptions& settings, const std::string& seedHelp = "");

/// The preset's values for the mode, then every given setting, then PlannerSettings::check();
/// throws InputError naming the flag ("--rho-a", "--preset") for bad input.
PlannerSettings resolvePlannerSettings(const PlannerSettingOptions& settings, HandSamplingMode mode);

}  // namespace pmdplan::cli
