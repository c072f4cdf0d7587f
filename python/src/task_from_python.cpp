#include "task_from_python.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <numbers>
#include <set>

#include "conversions.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/model/mesh_file.hpp"

namespace pmdplan::python {
namespace {

constexpr const char* kObstacleForm =
    "an obstacle {name, one of box / cylinder / sphere / mesh, xyz, optional rpy_deg}";

std::vector<double> numbers(py::handle value, std::size_t count, const std::string& field, const std::string& form,
                            bool positive) {
  std::vector<double> result;
  try {
    result = value.cast<std::vector<double>>();
  } catch (const py::cast_error&) {
    throw InputError("", field, "expected " + form);
  }
  if (result.size() != count) throw InputError("", field, "expected " + form);
  for (const double v : result)
    if (!std::isfinite(v) || (positive && !(v > 0.0))) throw InputError("", field, "expected " + form);
  return result;
}

double positiveNumber(py::handle value, const std::string& field, const std::string& form) {
  return numbers(py::make_tuple(value), 1, field, form, true)[0];
}

py::dict mapWithKeys(py::handle value, const std::set<std::string>& allowed, const std::string& field,
                     const std::string& form) {
  if (!py::isinstance<py::dict>(value)) throw InputError("", field, "expected " + form);
  auto dict = py::reinterpret_borrow<py::dict>(value);
  for (const auto& [key, entry] : dict) {
    const std::string name = py::str(key);
    if (!allowed.count(name)) throw InputError("", field + "." + name, "unknown key; expected " + form);
  }
  return dict;
}

py::handle required(const py::dict& dict, const char* key, const std::string& field, const std::string& form) {
  if (!dict.contains(key)) throw InputError("", field + "." + key, "missing; expected " + form);
  return dict[key];
}

Shape shapeFrom(const std::string& type, py::handle value, const std::string& field) {
  if (type == "box") {
    const auto v = numbers(value, 3, field, "full extents [x, y, z] in metres, each greater than 0", true);
    return BoxShape{Eigen::Vector3d(v[0], v[1], v[2])};
  }
  if (type == "sphere") return SphereShape{positiveNumber(value, field, "a radius in metres greater than 0")};
  if (type == "cylinder") {
    const std::string form = "{radius, length} in metres (the axis is the local z)";
    const auto dict = mapWithKeys(value, {"radius", "length"}, field, form);
    CylinderShape cylinder;
    cylinder.radius =
        positiveNumber(required(dict, "radius", field, form), field + ".radius", "a length in metres greater than 0");
    cylinder.length =
        positiveNumber(required(dict, "length", field, form), field + ".length", "a length in metres greater than 0");
    return cylinder;
  }
  const std::string form = "{file, optional scale [x, y, z]} (a relative file is relative to the working directory)";
  const auto dict = mapWithKeys(value, {"file", "scale"}, field, form);
  MeshShape mesh;
  const py::handle file = required(dict, "file", field, form);
  if (!py::isinstance<py::str>(file) && !py::hasattr(file, "__fspath__"))
    throw InputError("", field + ".file", "expected a mesh file path");
  mesh.file = std::filesystem::absolute(py::str(file).cast<std::string>()).lexically_normal();
  std::error_code error;
  if (!std::filesystem::exists(mesh.file, error))
    throw InputError("", field + ".file", "mesh file not found: " + mesh.file.string());
  if (dict.contains("scale")) {
    const auto s = numbers(dict["scale"], 3, field + ".scale", "scale factors [x, y, z], each greater than 0", true);
    mesh.scale = Eigen::Vector3d(s[0], s[1], s[2]);
  }
  // The scale within ShapeBounds before the file is read (".mesh.scale[i]" becomes "[i]" of the scale).
  if (auto problem = shapeBoundsProblem(mesh))
    throw InputError("", field + ".scale" + problem->part.substr(problem->part.find('[')), problem->message);
  // Read now, through the same checks as a task file's meshes (model/mesh_file.hpp).
  return loadMeshShape(mesh.file, mesh.scale);
}

Eigen::Matrix3d rotationFromDegrees(const std::vector<double>& rpy) {
  const double k = std::numbers::pi / 180.0;
  return (Eigen::AngleAxisd(rpy[2] * k, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy[1] * k, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy[0] * k, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Isometry3d placementOfDict(const py::dict& dict, const std::string& field) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const auto xyz = numbers(required(dict, "xyz", field, "a position [x, y, z] in metres"), 3, field + ".xyz",
                           "a position [x, y, z] in metres", false);
  pose.translation() = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
  checkPositionBounds(pose.translation(), "", field + ".xyz");
  if (dict.contains("rpy_deg"))
    pose.linear() = rotationFromDegrees(
        numbers(dict["rpy_deg"], 3, field + ".rpy_deg", "fixed-axis angles [roll, pitch, yaw] in degrees", false));
  return pose;
}

}  // namespace

Eigen::Isometry3d placementFrom(py::handle value, const std::string& field) {
  if (value.is_none()) return Eigen::Isometry3d::Identity();
  if (py::isinstance<py::dict>(value))
    return placementOfDict(mapWithKeys(value, {"xyz", "rpy_deg"}, field, "{xyz, optional rpy_deg} or a 4x4 matrix"),
                           field);
  const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!array || array.ndim() != 2 || array.shape(0) != 4 || array.shape(1) != 4) {
    PyErr_Clear();
    throw InputError("", field, "expected {xyz: [x, y, z], rpy_deg: [r, p, y]} or a 4x4 homogeneous matrix");
  }
  Eigen::Matrix4d matrix;
  const auto cells = array.unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) matrix(r, c) = cells(r, c);
  const Eigen::Matrix3d rotation = matrix.topLeftCorner<3, 3>();
  if (!matrix.allFinite() || !(rotation * rotation.transpose()).isIdentity(1e-9) || rotation.determinant() < 0.0 ||
      !matrix.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)))
    throw InputError("", field, "expected a 4x4 homogeneous matrix with a rotation (orthonormal, determinant 1)");
  checkPositionBounds(matrix.topRightCorner<3, 1>(), "", field + ".translation");
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.matrix() = matrix;
  return pose;
}

std::vector<Obstacle> obstaclesFrom(py::handle list) {
  std::vector<Obstacle> obstacles;
  if (list.is_none()) return obstacles;
  if (!py::isinstance<py::sequence>(list) || py::isinstance<py::str>(list))
    throw InputError("", "obstacles", std::string("expected a list of ") + kObstacleForm);
  std::set<std::string> names;
  MeshTriangleBudget meshBudget("obstacle meshes of the task");
  const auto items = py::reinterpret_borrow<py::sequence>(list);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string field = "obstacles[" + std::to_string(i) + "]";
    const auto dict =
        mapWithKeys(items[i], {"name", "box", "cylinder", "sphere", "mesh", "xyz", "rpy_deg"}, field, kObstacleForm);
    Obstacle obstacle;
    const py::handle name = required(dict, "name", field, "a unique obstacle name");
    if (!py::isinstance<py::str>(name) || name.cast<std::string>().empty())
      throw InputError("", field + ".name", "expected a unique obstacle name (a non-empty str)");
    obstacle.name = name.cast<std::string>();
    if (!names.insert(obstacle.name).second)
      throw InputError("", field + ".name",
                       "obstacle name '" + obstacle.name + "' is already used; names must be unique");
    std::string type;
    for (const char* candidate : {"box", "cylinder", "sphere", "mesh"}) {
      if (!dict.contains(candidate)) continue;
      if (!type.empty())
        throw InputError("", field + "." + candidate,
                         "an obstacle has exactly one shape, but " + type + " is given too");
      type = candidate;
    }
    if (type.empty())
      throw InputError(
          "", field,
          "no shape; expected one of box: [x, y, z], cylinder: {radius, length}, sphere: radius, mesh: {file, scale}");
    obstacle.shape = shapeFrom(type, dict[type.c_str()], field + "." + type);
    checkShapeBounds(obstacle.shape, "", field);  // the rule of task files and URDFs (model/collision_shape.hpp)
    if (const auto* mesh = std::get_if<MeshShape>(&obstacle.shape)) meshBudget.add(*mesh, "", field + ".mesh");
    obstacle.pose = placementOfDict(dict, field);
    obstacles.push_back(std::move(obstacle));
  }
  return obstacles;
}

py::dict obstacleToPython(const Obstacle& obstacle) {
  py::dict dict;
  dict["name"] = obstacle.name;
  std::visit(
      [&](const auto& shape) {
        using S = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<S, BoxShape>)
          dict["box"] = std::vector<double>{shape.size.x(), shape.size.y(), shape.size.z()};
        else if constexpr (std::is_same_v<S, CylinderShape>)
          dict["cylinder"] = py::dict(py::arg("radius") = shape.radius, py::arg("length") = shape.length);
        else if constexpr (std::is_same_v<S, SphereShape>)
          dict["sphere"] = shape.radius;
        else
          dict["mesh"] =
              py::dict(py::arg("file") = shape.file.string(),
                       py::arg("scale") = std::vector<double>{shape.scale.x(), shape.scale.y(), shape.scale.z()});
      },
      obstacle.shape);
  const Eigen::Vector3d t = obstacle.pose.translation();
  dict["xyz"] = std::vector<double>{t.x(), t.y(), t.z()};
  // R = Rz(yaw)·Ry(pitch)·Rx(roll): Eigen's eulerAngles(2, 1, 0) gives (yaw, pitch, roll).
  const Eigen::Vector3d ypr = obstacle.pose.linear().eulerAngles(2, 1, 0) * (180.0 / std::numbers::pi);
  dict["rpy_deg"] = std::vector<double>{ypr[2], ypr[1], ypr[0]};
  return dict;
}

Task taskFrom(std::shared_ptr<const RobotModel> robot, py::handle start, py::handle goal, py::handle obstacles,
              py::handle base, const TaskDescription& description) {
  Task task;
  if (const std::string problem = taskNameProblem(description.name); !problem.empty())
    throw InputError("", "name", problem);
  task.name = description.name;
  task.description = description.description;
  task.robot = std::move(robot);
  task.base = placementFrom(base, "base");
  task.obstacles = obstaclesFrom(obstacles);
  task.start = jointValuesFrom(task.robot->activeJoints(), start, "start");
  task.goal = jointValuesFrom(task.robot->activeJoints(), goal, "goal");
  if (description.target) {
    if (!task.findObstacle(*description.target))
      throw InputError("", "target", "'" + *description.target + "' is not one of the obstacles");
    task.target = description.target;
  }
  return task;
}

}  // namespace pmdplan::python
