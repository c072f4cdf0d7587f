// pmdplan.Robot (a URDF with its SRDF-style companion) and pmdplan.Task (a task file, a built-in
// task, or one built from Python values).
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "conversions.hpp"
#include "task_from_python.hpp"

namespace pmdplan::python {
namespace {

PyRobot robotOf(RobotModel model) { return PyRobot{std::make_shared<const RobotModel>(std::move(model))}; }

Eigen::VectorXd limitValues(const JointLimits& joints, bool upper) {
  Eigen::VectorXd values(static_cast<Eigen::Index>(joints.size()));
  for (std::size_t i = 0; i < joints.size(); ++i)
    values[static_cast<Eigen::Index>(i)] = upper ? joints[i].upper : joints[i].lower;
  return values;
}

PyTask taskOf(Task task, std::shared_ptr<const int> world = std::make_shared<const int>(0)) {
  return PyTask{std::make_shared<const Task>(std::move(task)), std::move(world)};
}

void bindRobot(py::module_& m) {
  py::class_<PyRobot>(m, "Robot",
                      "A robot's kinematic tree from URDF, with its planning groups (arm, hand) from the SRDF.")
      .def_static(
          "load",
          [](const std::filesystem::path& urdf, std::optional<std::filesystem::path> srdf) {
            return robotOf(RobotModel::load(urdf, srdf));
          },
          py::arg("urdf"), py::arg("srdf") = py::none(),
          "Loads a URDF and, if given, its SRDF-style companion (groups, skippable collision pairs).")
      .def_static(
          "builtin", [](const std::string& name) { return robotOf(RobotModel::loadBuiltIn(name)); }, py::arg("name"),
          "A built-in robot by name (sah_tx90).")
      .def_static(
          "from_name_or_path", [](const std::string& name) { return robotOf(RobotModel::loadByNameOrPath(name)); },
          py::arg("name_or_urdf"), "A built-in robot's name, or a .urdf path (its .srdf beside it, if present).")
      .def_property_readonly("name", [](const PyRobot& r) { return r.model->name(); })
      .def_property_readonly("urdf_path", [](const PyRobot& r) { return r.model->urdfPath(); })
      .def_property_readonly(
          "dof", [](const PyRobot& r) { return r.model->dof(); }, "Number of active joints.")
      .def_property_readonly(
          "joint_names", [](const PyRobot& r) { return r.model->activeJointNames(); },
          "Active joints in configuration order (arm first, then hand).")
      .def_property_readonly("lower", [](const PyRobot& r) { return limitValues(r.model->activeJoints(), false); })
      .def_property_readonly("upper", [](const PyRobot& r) { return limitValues(r.model->activeJoints(), true); })
      .def_property_readonly(
          "groups",
          [](const PyRobot& r) {
            py::dict groups;
            for (const auto& [name, joints] : r.model->groupDefinitions()) groups[py::str(name)] = r.model->group(name);
            return groups;
          },
          "Planning groups: name -> configuration indices of their active joints.")
      .def_property_readonly("palm_link",
                             [](const PyRobot& r) {
                               const int palm = r.model->palmLink();
                               return palm < 0 ? std::string() : r.model->links()[static_cast<std::size_t>(palm)].name;
                             })
      .def(
          "configuration",
          [](const PyRobot& r, py::handle values) {
            return jointValuesFrom(r.model->activeJoints(), values, "configuration");
          },
          py::arg("values"),
          "A configuration (numpy array, radians) from a dict {joint name: value} or a sequence; checked against the "
          "limits.")
      .def(
          "joint_dict",
          [](const PyRobot& r, py::handle values) {
            return jointDict(r.model->activeJoints(),
                             jointValuesFrom(r.model->activeJoints(), values, "configuration"));
          },
          py::arg("configuration"), "The configuration as {joint name: value}.")
      .def(
          "normalise",
          [](const PyRobot& r, py::handle values) {
            return r.model->normalise(jointValuesFrom(r.model->activeJoints(), values, "configuration"));
          },
          py::arg("configuration"), "Joint values mapped to [0, 1] by their limits (the planning metric).")
      .def("__repr__", [](const PyRobot& r) {
        return "<pmdplan.Robot " + r.model->name() + ", " + std::to_string(r.model->dof()) + " joints>";
      });
}

void bindTask(py::module_& m) {
  py::class_<PyTask>(m, "Task", "A planning task: robot and base pose, obstacles, start and goal (radians).")
      .def(py::init([](const PyRobot& robot, py::handle start, py::handle goal, py::handle obstacles, py::handle base,
                       std::string name, std::string description, std::optional<std::string> target) {
             return taskOf(taskFrom(robot.model, start, goal, obstacles, base,
                                    TaskDescription{std::move(name), std::move(description), std::move(target)}));
           }),
           py::arg("robot"), py::arg("start"), py::arg("goal"), py::arg("obstacles") = py::list(),
           py::arg("base") = py::none(), py::arg("name") = "python_task", py::arg("description") = "",
           py::arg("target") = py::none(),
           "A task built in Python. start/goal: arrays or {joint name: radians}; obstacles: dicts of the task file's "
           "form\n"
           "({'name', one of 'box' [x, y, z] / 'cylinder' {'radius', 'length'} / 'sphere' r / 'mesh' {'file', "
           "'scale'},\n"
           "'xyz', optional 'rpy_deg'}); base: {'xyz', 'rpy_deg'} or a 4x4 matrix. Raises InputError for bad values.")
      .def_static(
          "load", [](const std::string& nameOrPath) { return taskOf(loadTaskByName(nameOrPath)); },
          py::arg("name_or_path"),
          "A built-in task (can_on_table, cans_on_desk, can_in_box, cans_in_shelf, t_in_clutter) or a task file.")
      .def(
          "replace",
          [](const PyTask& t, py::handle start, py::handle goal, py::handle obstacles,
             std::optional<std::string> name) {
            Task task = *t.task;
            const auto& joints = task.robot->activeJoints();
            if (!start.is_none()) task.start = jointValuesFrom(joints, start, "start");
            if (!goal.is_none()) task.goal = jointValuesFrom(joints, goal, "goal");
            std::shared_ptr<const int> world = t.world;
            if (!obstacles.is_none()) {
              task.obstacles = obstaclesFrom(obstacles);
              if (task.target && !task.findObstacle(*task.target)) task.target.reset();
              world = std::make_shared<const int>(0);
            }
            if (name) {
              if (const std::string problem = taskNameProblem(*name); !problem.empty())
                throw InputError("", "name", problem);
              task.name = *name;
            }
            return taskOf(std::move(task), std::move(world));
          },
          py::arg("start") = py::none(), py::arg("goal") = py::none(), py::arg("obstacles") = py::none(),
          py::arg("name") = py::none(),
          "A copy with another start, goal, obstacle list or name (the rest kept). Without new obstacles it\n"
          "may be planned with the original's CollisionChecker.")
      .def_property_readonly("name", [](const PyTask& t) { return t.task->name; })
      .def_property_readonly("description", [](const PyTask& t) { return t.task->description; })
      .def_property_readonly(
          "file", [](const PyTask& t) { return t.task->file; }, "Where it was read from (empty if built in Python).")
      .def_property_readonly("robot", [](const PyTask& t) { return PyRobot{t.task->robot}; })
      .def_property_readonly("start", [](const PyTask& t) { return Eigen::VectorXd(t.task->start); })
      .def_property_readonly("goal", [](const PyTask& t) { return Eigen::VectorXd(t.task->goal); })
      .def_property_readonly("target", [](const PyTask& t) { return t.task->target; })
      .def_property_readonly(
          "base", [](const PyTask& t) { return Eigen::Matrix4d(t.task->base.matrix()); },
          "Robot root link in the world (4x4).")
      .def_property_readonly(
          "obstacles",
          [](const PyTask& t) {
            py::list list;
            for (const auto& obstacle : t.task->obstacles) list.append(obstacleToPython(obstacle));
            return list;
          },
          "The obstacles in the dict form Task() reads.")
      .def("__repr__", [](const PyTask& t) {
        return "<pmdplan.Task " + t.task->name + ", " + std::to_string(t.task->obstacles.size()) + " obstacles>";
      });
}

}  // namespace

void bindRobotAndTask(py::module_& m) {
  bindRobot(m);
  bindTask(m);
}

}  // namespace pmdplan::python
