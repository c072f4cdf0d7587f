// `pmdplan view PATH.json [MORE.json ...] [--out DIR] [--serve PORT] [--task TASK] [--synergies MODEL.yaml]`
// or `pmdplan view BENCH_DIR --seed N ...`: writes a self-contained web viewer folder for planned
// paths of one task (the robot, the task's obstacles, the paths as one animation, the synergy
// readout and explorer) and, with --serve, serves it on 127.0.0.1 until stopped.
#include <iostream>
#include <memory>
#include <optional>

#include "command_registry.hpp"
#include "package_path_option.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "pmdplan/io/servers/static_file_server.hpp"
#include "pmdplan/io/viewer/path_robot_match.hpp"
#include "pmdplan/io/viewer/path_set.hpp"
#include "pmdplan/io/viewer/viewer_data.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"
#include "pmdplan/io/viewer/viewer_folder_outputs.hpp"
#include "pmdplan/synergy/synergy_model_resolution.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::cli::view_command {
namespace {

struct Options {
  std::vector<std::string> paths;
  std::optional<std::uint64_t> seed;  // with a bench folder: its paths of this seed
  std::string out;
  std::optional<int> servePort;
  std::string task;
  std::string synergies;
};

/// PATH.json -> PATH-viewer beside it; BENCH_DIR --seed N -> BENCH_DIR/seedN-viewer.
std::filesystem::path defaultOutput(const Options& o) {
  const std::filesystem::path path = o.paths.front();
  if (o.seed) return path / ("seed" + std::to_string(*o.seed) + "-viewer");
  return path.parent_path() / (path.stem().string() + "-viewer");
}

/// The files to view: the paths given, or a bench folder's paths of --seed.
std::vector<std::filesystem::path> inputFiles(const Options& o) {
  const bool folder = std::filesystem::is_directory(o.paths.front());
  if (folder && o.paths.size() > 1)
    throw InputError(o.paths.front(), "path",
                     "is a folder: view one bench folder (with --seed N) or path files, not both");
  if (folder && !o.seed)
    throw InputError(o.paths.front(), "--seed", "is a folder: give --seed N to view its paths of one seed");
  if (!folder && o.seed) throw InputError("", "--seed", "picks the paths of a bench folder; expected PATH to be one");
  if (folder) return benchSeedPaths(o.paths.front(), *o.seed);
  return {o.paths.begin(), o.paths.end()};
}

/// The path names its task; a task given on the command line wins (say, a task file that moved).
Task loadPathTask(const Options& o, const ViewInput& input) {
  if (!o.task.empty()) return loadTaskByName(o.task);
  try {
    return loadTaskByName(input.path.task);
  } catch (const InputError& error) {
    if (!error.file().empty()) throw;  // the task file itself is bad: its own message says where
    throw InputError(input.file.string(), "task", error.message() + "; give the task with --task TASK");
  }
}

int run(const Options& o) {
  std::vector<ViewInput> inputs;
  for (const auto& file : inputFiles(o)) inputs.push_back(readViewInput(file));
  checkOneTask(inputs);
  const PathFile& path = inputs.front().path;
  const std::optional<TrajectoryFile>& trajectory = inputs.front().trajectory;
  const Task task = loadPathTask(o, inputs.front());
  for (const ViewInput& input : inputs)
    if (!o.task.empty() && task.name != input.path.task) {
      // Another task than the path's own: only if the path starts and ends where that task does.
      const auto warnings = pathEndWarnings(task, pathConfigurations(input.path, *task.robot, input.file.string()));
      if (!warnings.empty())
        throw InputError(input.file.string(), "task",
                         "the path was planned for task '" + input.path.task + "', not --task " + task.name + ": " +
                             warnings.front() + "; view it with its own task");
    }
  const ResolvedSynergyModel synergies =
      resolveSynergyModel(task.robot->name(), o.synergies, SynergyModelNeed::Optional);

  ViewerDataSettings parameters;
  parameters.trajectory = trajectory ? &*trajectory : nullptr;
  ViewerData data = viewerData(task, path, synergies.get(), {inputs.front().file, synergies.file}, parameters);
  addOverlayPaths(data, task, inputs, parameters);
  const std::filesystem::path out = o.out.empty() ? defaultOutput(o) : std::filesystem::path(o.out);
  checkViewerFolderOutputs(out, data, viewerAssetDirectory(), "--out");  // no file of it may be an input
  writeViewerFolder(out, data, viewerAssetDirectory());
  std::cout << "wrote " << out.string() << "/ (";
  if (inputs.size() > 1) std::cout << inputs.size() << " paths; the first: ";
  std::cout << data.document["path"]["states"].size() << " states from "
            << data.document["path"]["waypoint_count"].get<std::size_t>() << " waypoints"
            << (synergies.model ? "" : "; no synergy model for robot " + task.robot->name()) << "): open "
            << (out / "index.html").string() << " in a browser\n";
  if (!o.servePort) return 0;
  StaticFileServer server(out, *o.servePort);
  std::cout << "serving " << out.string() << " at http://127.0.0.1:" << server.port() << "/ (Ctrl-C to stop)"
            << std::endl;
  server.serveForever();
}

const CommandRegistrar registrar{
    "view",
    "Write a web viewer folder for paths of one task (robot, obstacles, animation, synergies); optionally serve it",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      addPackagePathOption(app);
      app.add_option(
             "path", o->paths,
             "Path files (JSON) written by pmdplan plan, or trajectory files (plan --trajectory, time), all of one "
             "task; or a folder written by pmdplan bench --paths (with --seed)")
          ->required();
      app.add_option("--seed", o->seed,
                     "With a bench folder: view its paths of this seed (pmd, full, then the others)");
      app.add_option("--out", o->out, "Viewer folder to write (default: PATH's name with -viewer, beside it)");
      app.add_option("--serve", o->servePort, "Serve the folder on 127.0.0.1:PORT until stopped (0: any free port)");
      app.add_option("--task", o->task, "Task name or file (default: the task the path file names)");
      app.add_option("--synergies", o->synergies, "Synergy model YAML (default: the robot's shipped model, if any)");
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli::view_command
