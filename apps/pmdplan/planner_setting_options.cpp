#include "planner_setting_options.hpp"

#include <cctype>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"

namespace pmdplan::cli {
namespace {

/// "(paper default 10; full: 20)" or "(paper default 0.001)".
std::string defaultText(const PlannerSetting& setting) {
  const std::string pmd = setting.get(PlannerSettings::defaultsFor(HandSamplingMode::Synergy));
  const std::string full = setting.get(PlannerSettings::defaultsFor(HandSamplingMode::FullSpace));
  return " (default " + pmd + (pmd == full ? "" : "; full: " + full) + ")";
}

}  // namespace

void addPlannerSettingOptions(CLI::App& app, PlannerSettingOptions& settings, const std::string& seedHelp) {
  app.add_option("--preset", settings.preset,
                 "Planner defaults: " + knownPlannerPresetNames() + " (default paper; see docs/deviations.md)");
  const auto& table = plannerSettingTable();
  settings.values.assign(table.size(), "");
  settings.options.assign(table.size(), nullptr);
  for (std::size_t i = 0; i < table.size(); ++i) {
    const PlannerSetting& s = table[i];
    std::string help = s.flag == "seed" && !seedHelp.empty() ? seedHelp : s.help;
    help[0] = s.symbol.empty() ? static_cast<char>(std::toupper(static_cast<unsigned char>(help[0]))) : help[0];
    if (!s.symbol.empty()) help = s.symbol + ": " + help;
    settings.options[i] =
        app.add_option("--" + s.flag, settings.values[i], help + defaultText(s))->type_name(s.valueName());
  }
}

PlannerSettings resolvePlannerSettings(const PlannerSettingOptions& settings, HandSamplingMode mode) {
  const auto preset = parsePlannerPreset(settings.preset);
  if (!preset)
    throw InputError("", "--preset",
                     "'" + settings.preset + "' is not a preset; expected one of " + knownPlannerPresetNames());
  PlannerSettings parameters = PlannerSettings::preset(*preset, mode);
  const auto& table = plannerSettingTable();
  try {
    for (std::size_t i = 0; i < table.size(); ++i)
      if (settings.options.at(i)->count() > 0) table[i].set(parameters, settings.values.at(i));
    parameters.check();
  } catch (const InputError& e) {
    throw InputError("", "--" + e.field(), e.message());  // the setting's key as the flag it is here
  }
  return parameters;
}

}  // namespace pmdplan::cli
