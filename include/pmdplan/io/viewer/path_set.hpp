#pragma once
// Several paths of one task viewed together (`pmdplan view a.json b.json ...`, or a bench folder's
// paths of one seed): reading each input, refusing paths of different tasks, finding a bench
// folder's path files, and the viewer document's overlay paths.
//
// A bench folder (`pmdplan bench --paths DIR`) holds one path file per solved run, named
// TASK.PLANNER.seedN.path.json (benchPathFileName: ompl:RRTConnect as ompl-RRTConnect). The viewer shows a seed's files
// with pmd first, then full, then the other planners by name: the first path is the one whose synergy readout, joint
// plots and collision colours the page shows.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/io/viewer/viewer_data.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {

/// One input of `view`: a path file or a timed trajectory file.
struct ViewInput {
  std::filesystem::path file;
  PathFile path;  ///< trajectoryAsPathFile() of the trajectory, if it is one
  std::optional<TrajectoryFile> trajectory;
};

/// Reads a path or a trajectory file (InputError naming the file for bad content).
ViewInput readViewInput(const std::filesystem::path& file);

/// Throws InputError (the file, field "task") for an input planned for another task than the
/// first input's: paths are viewed together only when they are of one task and so one robot.
void checkOneTask(const std::vector<ViewInput>& inputs);

/// "can_on_table.ompl-RRTConnect.seed3.path.json": the planner's ':' (and any '/' or '.') as '-'.
std::string benchPathFileName(const std::string& task, const std::string& planner, std::uint64_t seed);

/// The path files of `seed` in a bench folder, pmd first, then full, then the others by name.
/// Throws InputError (the folder, field "--seed") if there are none, naming the seeds there are.
std::vector<std::filesystem::path> benchSeedPaths(const std::filesystem::path& folder, std::uint64_t seed);

/// "pmd, seed 1 (a.json)": the name the page's legend gives a path.
std::string viewPathName(const ViewInput& input);

/// Adds the second and later inputs to a document viewerData() built from the first: each as an
/// overlay path, their warnings prefixed with their file's name, the title naming every planner.
void addOverlayPaths(ViewerData& data, const Task& task, const std::vector<ViewInput>& inputs,
                     const ViewerDataSettings& parameters);

}  // namespace pmdplan
