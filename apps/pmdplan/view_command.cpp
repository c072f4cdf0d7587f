// `pmdplan view PATH.json [--out DIR] [--serve PORT] [--task TASK] [--synergies MODEL.yaml]`:
// writes a self-contained web viewer folder for a planned path (the robot, the task's obstacles,
// the path as an animation, the synergy readout and explorer) and, with --serve, serves it on
// 127.0.0.1 until stopped.
#include <iostream>
#include <memory>
#include <optional>

#include "command_registry.hpp"
#include "package_path_option.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/path_file.hpp"
#include "pmdplan/io/path_robot_match.hpp"
#include "pmdplan/io/trajectory_file.hpp"
#include "pmdplan/io/static_file_server.hpp"
#include "pmdplan/io/viewer_data.hpp"
#include "pmdplan/io/viewer_folder.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan::cli {
namespace {

struct Options {
  std::string path;
  std::string out;
  std::optional<int> servePort;
  std::string task;
  std::string synergies;
};

/// PATH.json -> PATH-viewer beside it.
std::filesystem::path defaultOutput(const std::filesystem::path& path) {
  return path.parent_path() / (path.stem().string() + "-viewer");
}

/// The path names its task; a task given on the command line wins (say, a task file that moved).
Task loadPathTask(const Options& o, const PathFile& path) {
  if (!o.task.empty()) return loadTaskByName(o.task);
  try {
    return loadTaskByName(path.task);
  } catch (const InputError& error) {
    if (!error.file().empty()) throw;  // the task file itself is bad: its own message says where
    throw InputError(o.path, "task", error.message() + "; give the task with --task TASK");
  }
}

int run(const Options& o) {
  const std::string text = readTextFile(o.path);
  std::optional<TrajectoryFile> trajectory;
  if (isTrajectoryFileText(text)) trajectory = parseTrajectoryFile(text, o.path);
  const PathFile path = trajectory ? trajectoryAsPathFile(*trajectory) : parsePathFile(text, o.path);
  const Task task = loadPathTask(o, path);
  if (!o.task.empty() && task.name != path.task) {
    // Another task than the path's own: only if the path starts and ends where that task does.
    const auto warnings = pathEndWarnings(task, pathConfigurations(path, *task.robot, o.path));
    if (!warnings.empty())
      throw InputError(o.path, "task", "the path was planned for task '" + path.task + "', not --task " + task.name + ": " +
                                           warnings.front() + "; view it with its own task");
  }
  std::filesystem::path synergyFile = o.synergies;
  if (synergyFile.empty() && std::filesystem::exists(defaultSynergyModelPath(task.robot->name())))
    synergyFile = defaultSynergyModelPath(task.robot->name());
  const std::optional<SynergyModel> synergies =
      synergyFile.empty() ? std::nullopt : std::optional<SynergyModel>(loadSynergyModel(synergyFile));

  ViewerDataParameters parameters;
  parameters.trajectory = trajectory ? &*trajectory : nullptr;
  const ViewerData data = viewerData(task, path, synergies ? &*synergies : nullptr, {o.path, synergyFile}, parameters);
  const std::filesystem::path out = o.out.empty() ? defaultOutput(o.path) : std::filesystem::path(o.out);
  writeViewerFolder(out, data, viewerAssetDirectory());
  std::cout << "wrote " << out.string() << "/ (" << data.document["path"]["states"].size() << " states from "
            << data.document["path"]["waypoint_count"].get<std::size_t>() << " waypoints"
            << (synergies ? "" : "; no synergy model for robot " + task.robot->name()) << "): open "
            << (out / "index.html").string() << " in a browser\n";
  if (!o.servePort) return 0;
  StaticFileServer server(out, *o.servePort);
  std::cout << "serving " << out.string() << " at http://127.0.0.1:" << server.port() << "/ (Ctrl-C to stop)" << std::endl;
  server.serveForever();
}

const CommandRegistrar registrar{
    "view", "Write a web viewer folder for a path (robot, obstacles, animation, synergies); optionally serve it",
    [](CLI::App& app) {
      auto o = std::make_shared<Options>();
      addPackagePathOption(app);
      app.add_option("path", o->path, "Path file (JSON) written by pmdplan plan, or a trajectory file (plan --trajectory, time)")->required();
      app.add_option("--out", o->out, "Viewer folder to write (default: PATH's name with -viewer, beside it)");
      app.add_option("--serve", o->servePort, "Serve the folder on 127.0.0.1:PORT until stopped (0: any free port)");
      app.add_option("--task", o->task, "Task name or file (default: the task the path file names)");
      app.add_option("--synergies", o->synergies, "Synergy model YAML (default: the robot's shipped model, if any)");
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace pmdplan::cli
