#pragma once
// Between Python values (numpy arrays, sequences, dicts of joint names) and the library's
// configurations, paths and JSON documents. Bad values are InputErrors naming the argument as `field`.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmdplan/core/joint_limit.hpp"
#include "pmdplan/model/configuration.hpp"

namespace pmdplan::python {

namespace py = pybind11;

/// Joint values for `joints` from an array-like of one value per joint (in order) or a dict
/// {joint name: value} naming every joint once. Radians (metres for prismatic joints); finite and
/// within the limits (a value at most 1e-9 outside is taken as the limit, as task files are read)
/// unless `withinLimits` is false.
Eigen::VectorXd jointValuesFrom(const JointLimits& joints, py::handle value, const std::string& field,
                                bool withinLimits = true);

/// Rows of an array-like of shape (points, joints.size()) as configurations, checked like
/// jointValuesFrom (`within_limits` false: only the shape and finiteness are checked).
std::vector<Configuration> configurationsFrom(const JointLimits& joints, py::handle value, const std::string& field,
                                              bool withinLimits = true);

/// A float64 array of shape (points, dof).
py::array_t<double> pathArray(const std::vector<Configuration>& path, int dof);

/// {name: value} in joint order.
py::dict jointDict(const JointLimits& joints, const Eigen::VectorXd& values);

/// A library JSON document as the Python value json.loads gives for its text (the dicts the
/// CLI's --json prints).
py::object pythonFromJson(const nlohmann::ordered_json& document);
py::object pythonFromJson(const nlohmann::json& document);

}  // namespace pmdplan::python
