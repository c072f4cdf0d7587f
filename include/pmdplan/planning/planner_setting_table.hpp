#pragma once
// The one declaration of the planner's settings as the command line names them: `pmdplan plan`
// and `pmdplan bench` both build their options from this table (same flags, same help, same
// errors), and a bench journal records the settings of its runs with it.
#include <functional>
#include <string>
#include <vector>

#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan {

struct PlannerSetting {
  std::string flag;       ///< without the dashes: "rho-a"
  std::string symbol;     ///< the paper's name: "rho_a", "K", "n_A", or "" where the paper has none
  std::string help;       ///< one line: what it is and its unit
  std::string valueName;  ///< what the value looks like in the help: "NUMBER", "COUNT", "on|off", ...
  /// Parses the whole text strictly into the field; throws InputError (no file, field "--flag")
  /// for text that is not a value of the field's type (range checks: PlannerSettings::check).
  std::function<void(PlannerSettings&, const std::string&)> set;
  /// The field's value as text that `set` reads back to the same value.
  std::function<std::string(const PlannerSettings&)> get;
};

/// Every setting, in the order the help lists them (the Algorithm 4 ones first).
const std::vector<PlannerSetting>& plannerSettingTable();

/// "flag=value flag=value ..." of every setting, e.g. for a journal header or a run's record.
std::string describePlannerSettings(const PlannerSettings& parameters);

}  // namespace pmdplan
