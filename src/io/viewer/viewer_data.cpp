#include "pmdplan/io/viewer/viewer_data.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "pmdplan/collision/grasp_rule.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/path_file_validation.hpp"
#include "pmdplan/io/files/statistics_json.hpp"
#include "pmdplan/io/viewer/path_robot_match.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/io/viewer/state_clearance.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"
#include "pmdplan/synergy/synergy_readout.hpp"

namespace pmdplan {
namespace {

using Json = nlohmann::ordered_json;

Json numbers(const Eigen::VectorXd& values) {
  Json list = Json::array();
  for (Eigen::Index i = 0; i < values.size(); ++i) list.push_back(values[i]);
  return list;
}

Json poseJson(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.linear());
  return Json{{"position", numbers(pose.translation())}, {"quaternion", Json::array({q.x(), q.y(), q.z(), q.w()})}};
}

Json shapeJson(const Shape& shape, const std::string& meshFile) {
  return std::visit(
      [&](const auto& s) -> Json {
        using T = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<T, BoxShape>)
          return Json{{"type", "box"}, {"size", numbers(s.size)}};
        else if constexpr (std::is_same_v<T, CylinderShape>)
          return Json{{"type", "cylinder"}, {"radius", s.radius}, {"length", s.length}};
        else if constexpr (std::is_same_v<T, SphereShape>)
          return Json{{"type", "sphere"}, {"radius", s.radius}};
        else
          return Json{{"type", "mesh"}, {"file", meshFile}, {"scale", numbers(s.scale)}};
      },
      shape);
}

Json taskJson(const Task& task, std::vector<ViewerFolderFile>& files) {
  Json obstacles = Json::array();
  for (std::size_t i = 0; i < task.obstacles.size(); ++i) {
    const Obstacle& obstacle = task.obstacles[i];
    std::string meshFile;
    if (const auto* mesh = std::get_if<MeshShape>(&obstacle.shape)) {
      // Numbered, so two obstacles with meshes of the same file name do not overwrite each other.
      meshFile = "meshes/" + std::to_string(i) + "-" + mesh->file.filename().string();
      files.push_back({mesh->file, meshFile});
    }
    Json item{{"name", obstacle.name}, {"shape", shapeJson(obstacle.shape, meshFile)}};
    item.update(poseJson(obstacle.pose));
    obstacles.push_back(std::move(item));
  }
  return Json{{"name", task.name},
              {"description", task.description},
              {"target", task.target ? Json(*task.target) : Json()},
              {"base", poseJson(task.base)},
              {"obstacles", std::move(obstacles)}};
}

/// The robot's visual meshes that resolved, copied into the folder: URDF reference -> folder path.
Json robotMeshFiles(const RobotModel& robot, std::vector<ViewerFolderFile>& files) {
  Json meshFiles = Json::object();
  for (const Link& link : robot.links())
    for (const VisualMesh& mesh : link.visualMeshes) {
      if (mesh.file.empty() || meshFiles.contains(mesh.reference)) continue;
      if (!isViewerMeshFile(mesh.file)) continue;  // only a mesh leaves with the folder (viewer_folder.hpp)
      // Numbered, so meshes of the same file name from different packages do not overwrite each other.
      const std::string copy = "robot-meshes/" + std::to_string(meshFiles.size()) + "-" + mesh.file.filename().string();
      files.push_back({mesh.file, copy});
      meshFiles[mesh.reference] = copy;
    }
  return meshFiles;
}

Json robotJson(const RobotModel& robot, std::vector<ViewerFolderFile>& files) {
  Json lower = Json::array(), upper = Json::array(), hand = Json::array(), mimic = Json::object(),
       held = Json::object();
  for (const auto& [name, value] : robot.heldJoints()) held[name] = value;
  for (const JointLimit& joint : robot.activeJoints()) {
    lower.push_back(joint.lower);
    upper.push_back(joint.upper);
  }
  if (robot.hasGroup("hand"))
    for (const int index : robot.group("hand"))
      hand.push_back(robot.activeJoints()[static_cast<std::size_t>(index)].name);
  for (const MimicRelation& relation : mimicRelations(robot))
    mimic[relation.joint] = Json::array({relation.source, relation.multiplier, relation.offset});
  const int palm = robot.palmLink();
  return Json{{"name", robot.name()},
              {"palm_link", palm >= 0 ? Json(robot.links()[static_cast<std::size_t>(palm)].name) : Json()},
              {"urdf", readTextFile(robot.urdfPath())},
              {"joint_names", robot.activeJointNames()},
              {"lower", std::move(lower)},
              {"upper", std::move(upper)},
              {"hand_joints", std::move(hand)},
              {"mimic", std::move(mimic)},
              {"held_joints", std::move(held)},
              {"mesh_files", robotMeshFiles(robot, files)}};
}

Json synergiesJson(const SynergyModel& model, const std::vector<int>& slots, const PathTimeline& timeline,
                   int plannerDirections) {
  Json names = Json::array(), lower = Json::array(), upper = Json::array(), directions = Json::array();
  for (const JointLimit& joint : model.joints) {
    names.push_back(joint.name);
    lower.push_back(joint.lower);
    upper.push_back(joint.upper);
  }
  for (int k = 0; k < model.directionCount(); ++k) directions.push_back(numbers(model.directions.col(k)));
  Json ownAxis = Json::array(), coefficients = Json::array(), distance = Json::array();
  for (const Configuration& state : timeline.states) {
    const SynergyReadout readout = synergyReadout(model, slots, state);
    ownAxis.push_back(numbers(readout.ownAxis));
    coefficients.push_back(numbers(readout.coefficients));
    distance.push_back(numbers(readout.distanceFromSubspace));
  }
  return Json{{"provenance", model.provenance},
              {"joint_names", std::move(names)},
              {"lower", std::move(lower)},
              {"upper", std::move(upper)},
              {"own_axis_joints", model.ownAxisJoints},
              {"orthonormal", model.orthonormal},
              {"mean", numbers(model.mean)},
              {"directions", std::move(directions)},
              {"sigma", numbers(model.sigma)},
              {"variance_fraction", numbers(model.varianceFraction)},
              {"planner_directions", std::clamp(plannerDirections, 0, model.directionCount())},
              {"readout", Json{{"own_axis", std::move(ownAxis)},
                               {"coefficients", std::move(coefficients)},
                               {"distance_from_subspace", std::move(distance)}}}};
}

/// A trajectory's points are the states; its ends are the only waypoints it keeps.
PathTimeline trajectoryTimeline(const TrajectoryFile& trajectory, const RobotModel& robot,
                                const std::vector<Configuration>& positions, const std::string& file) {
  if (trajectory.trajectory.jointNames != robot.activeJointNames())
    throw InputError(file, "joint_names", "expected the robot's active joints in its configuration order");
  PathTimeline timeline;
  timeline.states = positions;
  timeline.waypointStates = {0, static_cast<int>(positions.size()) - 1};
  return timeline;
}

Json trajectoryTimingJson(const TrajectoryFile& trajectory) {
  Json times = Json::array(), velocities = Json::array();
  for (const TimedState& point : trajectory.trajectory.points) {
    times.push_back(point.time);
    velocities.push_back(numbers(point.velocity));
  }
  return Json{{"duration", trajectory.trajectory.points.back().time},
              {"blend_tolerance", trajectory.blendTolerance},
              {"velocity_limits", trajectory.velocityLimits},
              {"acceleration_limits", trajectory.accelerationLimits},
              {"times", std::move(times)},
              {"velocities", std::move(velocities)}};
}

}  // namespace

std::vector<std::string> pathEndWarnings(const Task& task, const std::vector<Configuration>& points) {
  std::vector<std::string> warnings;
  const auto check = [&](const Configuration& q, const Configuration& expected, const char* end, const char* what) {
    const double off = (q - expected).cwiseAbs().maxCoeff();
    if (off > kEndTolerance)
      warnings.push_back(std::string("the path's ") + end + " is not task " + task.name + "'s " + what +
                         " (a joint differs by " + std::to_string(off * 180.0 / M_PI) + " deg)");
  };
  check(points.front(), task.start, "first point", "start");
  check(points.back(), task.goal, "last point", "goal");
  return warnings;
}

PathFile trajectoryAsPathFile(const TrajectoryFile& trajectory) {
  PathFile path;
  path.task = trajectory.task;
  path.planner = trajectory.planner;
  path.seed = trajectory.seed;
  path.jointNames = trajectory.trajectory.jointNames;
  path.mimic = trajectory.mimic;
  for (const TimedState& point : trajectory.trajectory.points) path.points.push_back(point.position);
  return path;
}

ViewerPath viewerPath(const Task& task, const PathFile& path, const std::filesystem::path& pathFile,
                      const ViewerDataSettings& parameters) {
  const RobotModel& robot = *task.robot;
  const std::vector<Configuration> waypoints = pathConfigurations(path, robot, pathFile.string());
  ViewerPath result;
  Json timing;
  if (parameters.trajectory) {
    result.timeline = trajectoryTimeline(*parameters.trajectory, robot, waypoints, pathFile.string());
    timing = trajectoryTimingJson(*parameters.trajectory);
  } else {
    result.timeline = pathTimeline(waypoints, robot, parameters.timeline);
  }
  Json states = Json::array();
  for (const Configuration& state : result.timeline.states) states.push_back(numbers(state));
  result.json = Json{{"planner", path.planner},
                     {"seed", path.seed},
                     {"statistics", statisticsToJson(path.statistics, false)},
                     {"waypoint_count", waypoints.size()},
                     {"state_spacing", parameters.timeline.stateSpacing},
                     {"states", std::move(states)},
                     {"waypoint_states", result.timeline.waypointStates},
                     {"timing", std::move(timing)}};
  result.warnings = pathEndWarnings(task, waypoints);
  // The path's phases (a grasp's closing) as the timeline's: its closing starts at the pre-grasp's state.
  const PathPhases phases{path.closingFrom};
  const PathPhases statePhases{phases.closingFrom
                                   ? std::optional<std::size_t>(result.timeline.waypointStates.at(*phases.closingFrom))
                                   : std::nullopt};
  Json clearance = Json::array(), colliding = Json::array(), contact = Json::array(), validation;
  try {
    for (const StateClearance& state : stateClearances(task, result.timeline.states, statePhases)) {
      clearance.push_back(state.clearance);
      colliding.push_back(state.collidingLinks);
      contact.push_back(state.contactLinks);
    }
    validation = pathJudgementJson(validateTaskPath(task, waypoints, phases, parameters.toleranceMm));
  } catch (const InputError& error) {
    // Geometry the checker cannot load (an empty mesh, ...): the page still shows the path.
    clearance = colliding = contact = validation = Json();
    result.warnings.push_back("no collisions or clearance shown: " + error.file() + ": " + error.message());
  }
  result.json["clearance"] = std::move(clearance);
  result.json["colliding_links"] = std::move(colliding);
  result.json["contact_links"] = std::move(contact);
  result.json["closing_from_state"] = statePhases.closingFrom ? Json(*statePhases.closingFrom) : Json();
  result.json["validation"] = std::move(validation);
  return result;
}

ViewerData viewerData(const Task& task, const PathFile& path, const SynergyModel* synergies,
                      const ViewerSources& sources, const ViewerDataSettings& parameters) {
  const RobotModel& robot = *task.robot;
  ViewerPath shown = viewerPath(task, path, sources.pathFile, parameters);
  const std::vector<int> slots =
      synergies ? modelJointSlots(*synergies, robot, sources.synergyFile.string()) : std::vector<int>{};

  ViewerData data;
  Json& document = data.document;
  document["format"] = "pmdplan-viewer-data";
  document["version"] = 1;
  document["title"] = task.name + " - " + path.planner + " planner, seed " + std::to_string(path.seed);
  document["sources"] = Json{{"path_file", sources.pathFile.filename().string()},
                             {"task_file", task.file.filename().string()},
                             {"synergy_file", synergies ? Json(sources.synergyFile.filename().string()) : Json()}};
  document["task"] = taskJson(task, data.files);
  document["robot"] = robotJson(robot, data.files);
  document["path"] = std::move(shown.json);
  document["warnings"] = std::move(shown.warnings);
  document["synergies"] =
      synergies ? synergiesJson(*synergies, slots, shown.timeline, parameters.plannerDirections) : Json();
  return data;
}

}  // namespace pmdplan
