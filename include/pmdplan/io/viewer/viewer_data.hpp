#pragma once
// Everything the web viewer shows, as one JSON document (the viewer folder's viewer-data.js):
//
//   format "pmdplan-viewer-data", version 1, title
//   sources   {path_file, task_file, synergy_file}                      file names only
//   task      {name, description, target, base: {position, quaternion},
//              obstacles: [{name, shape, position, quaternion}]}        metres; quaternion [x, y, z, w]
//             shape: {type: box, size: [x, y, z]} | {type: cylinder, radius, length} (axis z)
//                  | {type: sphere, radius} | {type: mesh, file, scale}  file relative to the folder
//   robot     {name, palm_link, urdf (the URDF text), joint_names, lower, upper (active joints,
//              rad), hand_joints, mimic: {joint: [source, multiplier, offset]}}
//   path      {planner, seed, statistics, waypoint_count, state_spacing, states: [[rad ...]],
//              waypoint_states: [state index of each waypoint],
//              closing_from_state: the state where a grasp path's closing phase starts (its
//                pre-grasp), or null; every later state is judged with hand-target contact allowed,
//              clearance: [m per state: the moving links' distance to the obstacles over the pairs
//                that count in the state's phase; while closing, not the hand's to the target],
//              colliding_links: [[link names] per state: links in colliding pairs that count],
//              contact_links: [[link names] per state: hand links in allowed grasp contact with the
//                target (closing phase only)],
//              validation: the path judged as `pmdplan validate --json` judges it
//                (io/files/path_validation_json.hpp), at `ViewerDataSettings::toleranceMm`
//              (the last four null, with a warning, when the checker cannot load the task's geometry),
//              timing: null, or for a timed trajectory {duration, blend_tolerance, velocity_limits,
//                      acceleration_limits, times: [s per state], velocities: [[rad/s ...]]}}
//   overlay_paths  only when several paths are viewed together (path_set.hpp): the second and
//             later paths, each like `path` plus {name, file}; `path` then has a name and file too
//   warnings  ["the path's first point is not task T's start ...", ...]: shown on the page
//   synergies {provenance, joint_names, lower, upper, own_axis_joints, orthonormal, mean,
//              directions: [[...]], sigma, variance_fraction (normalised units), planner_directions,
//              readout: {own_axis, coefficients, distance_from_subspace}: one row per state}
//             or null when the robot has no synergy model
//
// The numbers are those of the library (the viewer recomputes nothing it could get wrong): the
// states are the path timeline, the readout comes from synergyReadout() for every state, the
// collisions, grasp contact, clearance and validation from the grasp rule (collision/grasp_rule.hpp).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/io/viewer/path_timeline.hpp"
#include "pmdplan/synergy/synergy_model.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

struct ViewerSources {
  std::filesystem::path pathFile;
  std::filesystem::path synergyFile;
};

struct ViewerDataSettings {
  PathTimelineSettings timeline;
  /// The PMDs the planner samples (thumb base + this many): the viewer's default for the
  /// distance-from-subspace readout. Capped by the model's direction count.
  int plannerDirections = 4;
  /// A timed trajectory (the viewer plays it in real time): its points are the states, and the
  /// path given to viewerData() is trajectoryAsPathFile() of it. Null for a path file.
  const TrajectoryFile* trajectory = nullptr;
  /// The motion tolerance of the path's validation (mm), as `pmdplan validate --tolerance-mm`.
  double toleranceMm = 1.0;
};

/// A path's ends farther than this (rad, any joint) from the task's start and goal are not its ends.
constexpr double kEndTolerance = 1e-6;

/// Warnings for a path (in the robot's configuration order) whose ends are not the task's.
std::vector<std::string> pathEndWarnings(const Task& task, const std::vector<Configuration>& points);

/// The trajectory's positions as a path file's points (for viewerData with `trajectory` set).
PathFile trajectoryAsPathFile(const TrajectoryFile& trajectory);

/// A file the viewer folder needs besides the data (a mesh obstacle's geometry).
struct ViewerFolderFile {
  std::filesystem::path source;
  std::string relativePath;
};

struct ViewerData {
  nlohmann::ordered_json document;
  std::vector<ViewerFolderFile> files;
};

/// One path as the viewer shows it: the document's "path" object, the warnings about it (ends
/// that are not the task's, no clearance) and its timeline.
struct ViewerPath {
  nlohmann::ordered_json json;
  std::vector<std::string> warnings;
  PathTimeline timeline;
};

/// Checks that the path fits the task's robot (InputError naming `pathFile`, see
/// pathConfigurations()) and builds its "path" object.
ViewerPath viewerPath(const Task& task, const PathFile& path, const std::filesystem::path& pathFile,
                      const ViewerDataSettings& parameters = {});

/// Checks that the path and the synergy model fit the task's robot (InputError naming the path
/// file or the model file otherwise, see pathConfigurations() and modelJointSlots()) and builds
/// the document. `synergies` may be null (a robot without a model: no synergy panel).
ViewerData viewerData(const Task& task, const PathFile& path, const SynergyModel* synergies,
                      const ViewerSources& sources, const ViewerDataSettings& parameters = {});

}  // namespace pmdplan
