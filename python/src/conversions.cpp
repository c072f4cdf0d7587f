#include "conversions.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan::python {
namespace {

double checkedValue(const JointLimit& joint, double value, const std::string& field, bool withinLimits) {
  if (!std::isfinite(value)) throw InputError("", field, "joint '" + joint.name + "': expected a finite number");
  if (!withinLimits) return value;
  constexpr double kSlack = 1e-9;
  if (value < joint.lower - kSlack || value > joint.upper + kSlack)
    throw InputError("", field,
                     "joint '" + joint.name + "' = " + std::to_string(value) + " is outside its limits [" +
                         std::to_string(joint.lower) + ", " + std::to_string(joint.upper) + "]");
  return std::min(std::max(value, joint.lower), joint.upper);
}

std::string expectedShape(std::size_t joints) {
  return "expected " + std::to_string(joints) + " joint values or a dict of joint names";
}

}  // namespace

Eigen::VectorXd jointValuesFrom(const JointLimits& joints, py::handle value, const std::string& field,
                                bool withinLimits) {
  Eigen::VectorXd values(static_cast<Eigen::Index>(joints.size()));
  if (py::isinstance<py::dict>(value)) {
    const auto dict = py::reinterpret_borrow<py::dict>(value);
    std::set<std::string> seen;
    for (const auto& [key, entry] : dict) {
      if (!py::isinstance<py::str>(key)) throw InputError("", field, "keys must be joint names (str)");
      const auto name = key.cast<std::string>();
      std::size_t index = 0;
      while (index < joints.size() && joints[index].name != name) ++index;
      if (index == joints.size()) throw InputError("", field, "'" + name + "' is not one of the joints");
      double number = 0.0;
      try {
        number = entry.cast<double>();
      } catch (const py::cast_error&) {
        throw InputError("", field, "joint '" + name + "': expected a number");
      }
      values[static_cast<Eigen::Index>(index)] = checkedValue(joints[index], number, field, withinLimits);
      seen.insert(name);
    }
    for (const auto& joint : joints)
      if (!seen.count(joint.name)) throw InputError("", field, "joint '" + joint.name + "' is missing");
    return values;
  }
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  } catch (const py::error_already_set&) {
  }
  if (!array || array.ndim() != 1 || static_cast<std::size_t>(array.shape(0)) != joints.size())
    throw InputError("", field, expectedShape(joints.size()));
  for (std::size_t i = 0; i < joints.size(); ++i)
    values[static_cast<Eigen::Index>(i)] =
        checkedValue(joints[i], array.at(static_cast<py::ssize_t>(i)), field, withinLimits);
  return values;
}

std::vector<Configuration> configurationsFrom(const JointLimits& joints, py::handle value, const std::string& field,
                                              bool withinLimits) {
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  } catch (const py::error_already_set&) {
  }
  if (!array || array.ndim() != 2 || static_cast<std::size_t>(array.shape(1)) != joints.size())
    throw InputError(
        "", field, "expected an array of shape (n, " + std::to_string(joints.size()) + "): one row per configuration");
  const auto rows = array.unchecked<2>();
  std::vector<Configuration> result(static_cast<std::size_t>(rows.shape(0)),
                                    Configuration(static_cast<Eigen::Index>(joints.size())));
  for (py::ssize_t r = 0; r < rows.shape(0); ++r)
    for (std::size_t j = 0; j < joints.size(); ++j)
      result[static_cast<std::size_t>(r)][static_cast<Eigen::Index>(j)] = checkedValue(
          joints[j], rows(r, static_cast<py::ssize_t>(j)), field + "[" + std::to_string(r) + "]", withinLimits);
  return result;
}

py::array_t<double> pathArray(const std::vector<Configuration>& path, int dof) {
  py::array_t<double> array({static_cast<py::ssize_t>(path.size()), static_cast<py::ssize_t>(dof)});
  auto out = array.mutable_unchecked<2>();
  for (std::size_t r = 0; r < path.size(); ++r)
    for (int j = 0; j < dof; ++j) out(static_cast<py::ssize_t>(r), j) = path[r][j];
  return array;
}

py::dict jointDict(const JointLimits& joints, const Eigen::VectorXd& values) {
  py::dict dict;
  for (std::size_t i = 0; i < joints.size(); ++i) dict[py::str(joints[i].name)] = values[static_cast<Eigen::Index>(i)];
  return dict;
}

py::object pythonFromJson(const nlohmann::ordered_json& document) {
  return py::module_::import("json").attr("loads")(document.dump());
}

py::object pythonFromJson(const nlohmann::json& document) {
  return py::module_::import("json").attr("loads")(document.dump());
}

}  // namespace pmdplan::python
