#pragma once
// The one declaration of the planner's settings: one row per setting, with its key, help, kind
// and text conversions. Every front end is built from it: `pmdplan plan` and `pmdplan bench`
// declare one option per row ("--rho-a"), Python's PlannerSettings one property per row ("rho_a"),
// OmplPmdPlanner one OMPL parameter per row ("rho_a"), and a bench journal records a run's
// settings with it. docs/architecture.md ("How to add a setting") says what a new row needs.
#include <functional>
#include <string>
#include <vector>

#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan {

/// What a setting's value is, so that a front end can expose it typed.
enum class SettingKind {
  Number,  ///< a real number (a double; "inf" where the field allows it): Python float
  Count,   ///< a whole number >= 0: Python int
  Choice,  ///< one of the row's `choices`, by name: Python str
  Switch,  ///< on or off (text "on" / "off"): Python bool
};

/// "number", "count", "choice", "switch".
std::string settingKindName(SettingKind kind);

/// "rho_a" for "rho-a": a setting's name in Python and OMPL (the key with underscores).
std::string settingName(const std::string& key);

struct PlannerSetting {
  /// The setting's key: the command-line flag without its dashes ("rho-a"). The library's
  /// InputErrors about the setting name this key as their field; each front end spells it its way
  /// ("--rho-a" on the command line, name() in Python).
  std::string flag;
  std::string symbol;  ///< the paper's name: "rho_a", "K", "n_A", or "" where the paper has none
  std::string help;    ///< one line: what it is and its unit
  SettingKind kind = SettingKind::Number;
  /// The accepted texts of a Choice ("factorial", "linear") or a Switch ("on", "off"); empty otherwise.
  std::vector<std::string> choices;
  /// Parses the whole text strictly into the field; throws InputError (no file, field `flag`) for
  /// text that is not a value of the field's kind (range checks: PlannerSettings::check).
  std::function<void(PlannerSettings&, const std::string&)> set;
  /// The field's value as text that `set` reads back to the same value.
  std::function<std::string(const PlannerSettings&)> get;

  /// The Python property and OMPL parameter name: settingName(flag), "rho_a".
  std::string name() const { return settingName(flag); }
  /// How the value looks in the command line's help: "NUMBER", "COUNT", "factorial|linear", "on|off".
  std::string valueName() const;
};

/// Every setting, in the order the help lists them (the Algorithm 4 ones first).
const std::vector<PlannerSetting>& plannerSettingTable();

/// The row whose key or name is `keyOrName` ("rho-a" or "rho_a"), or nullptr.
const PlannerSetting* findPlannerSetting(const std::string& keyOrName);

/// "flag=value flag=value ..." of every setting, e.g. for a journal header or a run's record.
std::string describePlannerSettings(const PlannerSettings& parameters);

}  // namespace pmdplan
