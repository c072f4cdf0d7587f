#pragma once
// Tasks built in Python: obstacles as dicts of the task file's form ({"name", one of "box",
// "cylinder", "sphere", "mesh", "xyz", optional "rpy_deg"}), placements as {"xyz", "rpy_deg"} or a
// 4x4 homogeneous matrix, start and goal as joint values. Errors name the argument the way a task
// file's keys are named (obstacles[2].cylinder.radius).
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/world/task.hpp"

namespace pmdplan::python {

namespace py = pybind11;

std::vector<Obstacle> obstaclesFrom(py::handle list);
Eigen::Isometry3d placementFrom(py::handle value, const std::string& field);

/// The obstacle back in the dict form obstaclesFrom reads (rotation as rpy_deg).
py::dict obstacleToPython(const Obstacle& obstacle);

struct TaskDescription {
  std::string name = "python_task";
  std::string description;
  std::optional<std::string> target;
};

/// Checks the target names an obstacle.
Task taskFrom(std::shared_ptr<const RobotModel> robot, py::handle start, py::handle goal, py::handle obstacles,
              py::handle base, const TaskDescription& description);

}  // namespace pmdplan::python
