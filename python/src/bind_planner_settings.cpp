// pmdplan.PlannerSettings: one property per row of plannerSettingTable()
// (planning/planner_setting_table.hpp), made by one loop over the table. A property's name is the
// row's name() ("rho_a"), its Python type follows the row's kind (float, int, str, bool), its
// setter reads the value through the row's text setter, and errors name the property. No field of
// PlannerSettings is named here: a new row of the table is a new property without a change here.
#include <pybind11/stl.h>

#include <charconv>
#include <limits>
#include <optional>

#include "bindings.hpp"
#include "planner_settings.hpp"
#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/planner_setting_table.hpp"

namespace pmdplan::python {
namespace {

/// Whose defaults a planner of the roster starts from (plan()'s message for an unknown one).
HandSamplingMode modeFrom(const std::string& planner) { return plannerNamed(planner, "planner").mode; }

std::string typeNameOf(py::handle value) { return py::str(py::type::of(value).attr("__name__")).cast<std::string>(); }

InputError wrongType(const PlannerSetting& row, py::handle value, const std::string& expected) {
  return InputError("", row.name(), "expected " + expected + ", got " + typeNameOf(value));
}

/// A Python value as the row's text: a float (or int) for a Number, an int for a Count, a str for
/// a Choice, a bool for a Switch; InputError naming the property for another type.
std::string settingText(const PlannerSetting& row, py::handle value) {
  const bool isBool = py::isinstance<py::bool_>(value);
  switch (row.kind) {
    case SettingKind::Number: {
      if (isBool || py::isinstance<py::str>(value)) throw wrongType(row, value, "a float");
      double number = 0.0;
      try {
        number = value.cast<double>();
      } catch (const py::cast_error&) {
        throw wrongType(row, value, "a float");
      }
      return py::repr(py::float_(number)).cast<std::string>();  // the shortest text of the double
    }
    case SettingKind::Count: {
      if (isBool || !PyIndex_Check(value.ptr())) throw wrongType(row, value, "an int");
      return py::str(py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()))).cast<std::string>();
    }
    case SettingKind::Choice:
      if (!py::isinstance<py::str>(value)) throw wrongType(row, value, "a str");
      return value.cast<std::string>();
    case SettingKind::Switch: {
      py::detail::make_caster<bool> flag;
      if (!flag.load(value, false)) throw wrongType(row, value, "a bool");
      return py::detail::cast_op<bool>(flag) ? "on" : "off";
    }
  }
  return "";
}

/// The row's text as the Python value of its kind.
py::object settingValue(const PlannerSetting& row, const std::string& text) {
  switch (row.kind) {
    case SettingKind::Number: {
      if (text == "inf") return py::float_(std::numeric_limits<double>::infinity());
      if (text == "-inf") return py::float_(-std::numeric_limits<double>::infinity());
      double number = 0.0;
      std::from_chars(text.data(), text.data() + text.size(), number);
      return py::float_(number);
    }
    case SettingKind::Count: {
      unsigned long long count = 0;
      std::from_chars(text.data(), text.data() + text.size(), count);
      return py::int_(count);
    }
    case SettingKind::Choice:
      return py::str(text);
    case SettingKind::Switch:
      return py::bool_(text == "on");
  }
  return py::none();
}

void setSetting(const PlannerSetting& row, PlannerSettings& settings, py::handle value) {
  try {
    row.set(settings, settingText(row, value));
  } catch (const InputError& e) {
    throw InputError(e.file(), pythonFieldName(e.field()), e.message());
  }
}

py::object settingDefault(const PlannerSetting& row, HandSamplingMode mode) {
  return settingValue(row, row.get(PlannerSettings::defaultsFor(mode)));
}

/// "rho_a: initial half-size ... (default 0.001). A float." from the row's help and defaults.
std::string settingDoc(const PlannerSetting& row) {
  const std::string pmd = py::repr(settingDefault(row, HandSamplingMode::Synergy)).cast<std::string>();
  const std::string full = py::repr(settingDefault(row, HandSamplingMode::FullSpace)).cast<std::string>();
  std::string doc = (row.symbol.empty() ? "" : row.symbol + ": ") + row.help + " (default " + pmd +
                    (pmd == full ? "" : "; planner 'full': " + full) + ").";
  if (row.kind == SettingKind::Choice) {
    doc += " One of";
    for (std::size_t i = 0; i < row.choices.size(); ++i) doc += (i == 0 ? " '" : ", '") + row.choices[i] + "'";
    doc += ".";
  }
  return doc + " Command line: --" + row.flag + "; OMPL parameter: " + row.name() + ".";
}

std::string pythonTypeName(SettingKind kind) {
  switch (kind) {
    case SettingKind::Number:
      return "float";
    case SettingKind::Count:
      return "int";
    case SettingKind::Choice:
      return "str";
    case SettingKind::Switch:
      return "bool";
  }
  return "float";
}

/// One dict per table row, for code that walks the settings (and the stub and docs checks).
py::list settingFields() {
  py::list fields;
  for (const PlannerSetting& row : plannerSettingTable()) {
    py::dict field;
    field["name"] = row.name();
    field["flag"] = "--" + row.flag;
    field["kind"] = settingKindName(row.kind);
    field["type"] = pythonTypeName(row.kind);
    field["choices"] = row.choices;
    field["symbol"] = row.symbol;
    field["help"] = row.help;
    field["default"] = settingDefault(row, HandSamplingMode::Synergy);
    field["default_full"] = settingDefault(row, HandSamplingMode::FullSpace);
    fields.append(field);
  }
  return fields;
}

PlannerSettings makeSettings(const std::string& planner, const py::kwargs& values) {
  PlannerSettings settings = PlannerSettings::defaultsFor(modeFrom(planner));
  for (const auto& [key, value] : values) {
    const std::string name = py::str(key).cast<std::string>();
    const PlannerSetting* row = findPlannerSetting(name);
    if (!row || row->name() != name) {
      std::string known;
      for (const PlannerSetting& s : plannerSettingTable()) known += (known.empty() ? "" : ", ") + s.name();
      throw py::type_error("PlannerSettings() got an unexpected keyword argument '" + name +
                           "'; its settings: " + known);
    }
    setSetting(*row, settings, value);
  }
  return settings;
}

std::string settingsRepr(const PlannerSettings& settings) {
  std::string text = "PlannerSettings(";
  for (const PlannerSetting& row : plannerSettingTable())
    text += (text.back() == '(' ? "" : ", ") + row.name() + "=" +
            py::repr(settingValue(row, row.get(settings))).cast<std::string>();
  return text + ")";
}

}  // namespace

std::string pythonFieldName(const std::string& field) {
  const PlannerSetting* row = findPlannerSetting(field);
  return row ? row->name() : field;
}

PlannerSettings plannerParametersFrom(py::handle settings, HandSamplingMode mode, std::optional<std::uint64_t> seed,
                                      std::optional<double> timeLimit) {
  PlannerSettings parameters = PlannerSettings::defaultsFor(mode);
  if (!settings.is_none()) {
    try {
      parameters = settings.cast<PlannerSettings>();
    } catch (const py::cast_error&) {
      throw InputError("", "settings", "expected a pmdplan.PlannerSettings");
    }
  }
  if (seed) parameters.seed = *seed;
  if (timeLimit) parameters.timeLimit = *timeLimit;
  return parameters;
}

std::uint64_t seedOf(const PlannerSettings& parameters) { return parameters.seed; }

double defaultTimeLimit() { return PlannerSettings{}.timeLimit; }

void checkPlannerParameters(const PlannerSettings& parameters) {
  try {
    parameters.check();
  } catch (const InputError& e) {
    throw InputError(e.file(), pythonFieldName(e.field()), e.message());
  }
}

void bindPlannerSettings(py::module_& m) {
  py::class_<PlannerSettings> settings(
      m, "PlannerSettings",
      "Settings of the PMD roadmap planners: one property per setting of the command line (--rho-a is rho_a).\n\n"
      "PlannerSettings(planner='pmd', **settings): the defaults of a planner of planners() ('pmd', 'pmd-lazy',\n"
      "'pmd-connect', 'ompl:...': the paper's Table 3, n_A = n_H = 10; 'full': 20), then the given settings, e.g.\n"
      "PlannerSettings('pmd', rho_a=0.01, smooth=False).");
  settings
      .def(py::init(&makeSettings), py::arg("planner") = "pmd",
           "The planner's defaults, then the given settings (by property name).")
      .def_static("fields", &settingFields,
                  "One dict per setting: name, flag, kind (number, count, choice, switch), type (float, int, str, "
                  "bool), choices, symbol, help, default, default_full.")
      .def("check", &checkPlannerParameters, "Raises InputError naming the setting for a value out of range.")
      .def("__repr__", &settingsRepr)
      .def(
          "__eq__",
          [](const PlannerSettings& a, py::handle b) {
            return py::isinstance<PlannerSettings>(b) &&
                   describePlannerSettings(a) == describePlannerSettings(b.cast<const PlannerSettings&>());
          },
          py::is_operator());
  for (const PlannerSetting& row : plannerSettingTable()) {
    const py::cpp_function getter([&row](const PlannerSettings& s) { return settingValue(row, row.get(s)); },
                                  py::is_method(settings));
    const py::cpp_function setter([&row](PlannerSettings& s, py::handle value) { setSetting(row, s, value); },
                                  py::is_method(settings));
    settings.def_property(row.name().c_str(), getter, setter, settingDoc(row).c_str());
  }
}

}  // namespace pmdplan::python
