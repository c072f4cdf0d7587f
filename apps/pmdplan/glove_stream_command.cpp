// `pmdplan glove stream (--device TTY | --replay REC) [-o postures.csv] [--raw-out raw.csv]
// [--project-pmds K] [--serve PORT]`: the glove live. Each frame, as it arrives from a CyberGlove
// on a serial line or from a recording played at its recorded rate, is calibrated, mapped to the
// robot hand's joints, optionally filtered onto the first K PMDs, written to the recordings and
// published to the web viewer as a server-sent event. Ctrl-C ends it cleanly (exit 0); a device that
// closes, falls silent or sends no replies ends it with exit 2 and keeps what was recorded.
#include "glove_stream_command.hpp"

#include <chrono>
#include <csignal>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "package_path_option.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/glove_calibration_file.hpp"
#include "pmdplan/glove/glove_csv.hpp"
#include "pmdplan/glove/glove_live_source.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"
#include "pmdplan/io/files/live_csv_file.hpp"
#include "pmdplan/io/servers/event_stream_server.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/io/viewer/viewer_data.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"
#include "pmdplan/synergy/pmd_posture_filter.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/world/task.hpp"
#include "viewer_folder_outputs.hpp"

namespace pmdplan::cli {
namespace {

volatile std::sig_atomic_t stopSignal = 0;
extern "C" void requestStop(int signal) { stopSignal = signal; }

void catchStopSignals() {
  struct sigaction action {};
  action.sa_handler = requestStop;  // no SA_RESTART: a wait on the device returns at once
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

struct StreamOptions {
  std::string device;
  std::string replay;
  std::string format = "auto";
  GloveDeviceSettings deviceSettings;
  double replayRate = 100.0;
  double speed = 1.0;
  long long frames = 0;
  std::string calibration;
  std::string mapping;
  std::string task = "can_on_table";
  std::optional<int> projectPmds;
  std::string synergies;
  std::string output;
  std::string rawOutput;
  std::optional<int> servePort;
  std::string out;
};

GloveRecording readReplay(const StreamOptions& o) {
  std::string format = o.format;
  const auto extension = std::filesystem::path(o.replay).extension();
  if (format == "auto")
    format = (extension == ".bin" || extension == ".raw" || extension == ".serial") ? "serial" : "csv";
  if (format == "csv") return readGloveCsv(o.replay);
  if (format == "serial") return readGloveSerialStream(o.replay);
  throw InputError("", "--format", "expected csv, serial or auto, got '" + o.format + "'");
}

std::filesystem::path calibrationPath(const StreamOptions& o) {
  if (!o.calibration.empty()) return o.calibration;
  if (!o.replay.empty()) {
    const auto beside = std::filesystem::path(o.replay).replace_extension(".calibration.yaml");
    if (std::filesystem::exists(beside)) return beside;
    throw InputError(o.replay, "--calibration",
                     "no calibration given and " + beside.filename().string() +
                         " is not beside the recording; pass --calibration FILE");
  }
  throw InputError(o.device, "--calibration",
                   "a live glove needs its operator's calibration: pass --calibration FILE.yaml");
}

/// The page: the task's scene with the robot at the task's start; the live hand replaces its hand.
ViewerData liveViewerData(const Task& task, const SynergyModel* synergies, const std::filesystem::path& synergyFile,
                          const JointLimits& hand, const std::string& source, const std::optional<int>& projectPmds) {
  PathFile still;
  still.task = task.name;
  still.planner = "glove";
  for (const auto& joint : task.robot->activeJoints()) still.jointNames.push_back(joint.name);
  still.points = {task.start, task.start};
  still.mimic = mimicRelations(*task.robot);
  ViewerData data = viewerData(task, still, synergies, {"glove stream", synergyFile});
  data.document["title"] = "glove live · " + task.robot->name();
  data.document["warnings"] = nlohmann::ordered_json::array();  // a still pose, not a path: its ends are no one's goal
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (const auto& joint : hand) joints.push_back(joint.name);
  data.document["live"] = {
      {"events", "events"},
      {"hand_joints", joints},
      {"source", source},
      {"project_pmds", projectPmds ? nlohmann::ordered_json(*projectPmds) : nlohmann::ordered_json()}};
  return data;
}

std::string rowText(double timeS, const Eigen::VectorXd& values) {
  std::string row = exactNumberText(timeS);
  for (Eigen::Index i = 0; i < values.size(); ++i) row += "," + exactNumberText(values(i));
  return row;
}

double epochMilliseconds() {
  return std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
}

int runStream(const StreamOptions& o) {
  if (o.device.empty() == o.replay.empty())
    throw InputError(
        "", "--device",
        "give one source: the glove's serial device (--device /dev/ttyUSB0) or a recording to play (--replay REC.csv)");
  if (o.output.empty() && o.rawOutput.empty() && !o.servePort)
    throw InputError("", "-o",
                     "nothing to do: give -o POSTURES.csv (the recording), --raw-out RAW.csv, --serve PORT (the live "
                     "viewer), or several");
  if (o.frames < 0) throw InputError("", "--frames", "expected 0 (no limit) or a number of frames to stop after");
  const Task task = loadTaskByName(o.task);
  const JointLimits hand = task.robot->groupJoints("hand");
  const std::filesystem::path calibrationFile = calibrationPath(o);
  const GloveCalibration calibration = loadGloveCalibration(calibrationFile);
  const std::filesystem::path mappingFile =
      o.mapping.empty() ? defaultHandMappingPath() : std::filesystem::path(o.mapping);
  const HandMapping mapping = loadHandMapping(mappingFile);
  rulesForJoints(mapping, hand);  // a mapping of another hand fails here, not at the first frame

  std::filesystem::path synergyFile = o.synergies;
  if (synergyFile.empty() && (o.projectPmds || o.servePort) &&
      std::filesystem::exists(defaultSynergyModelPath(task.robot->name())))
    synergyFile = defaultSynergyModelPath(task.robot->name());
  if (o.projectPmds && synergyFile.empty())
    throw InputError("", "--synergies",
                     "--project-pmds needs a synergy model and robot " + task.robot->name() +
                         " has none shipped: pass --synergies MODEL.yaml");
  const std::optional<SynergyModel> synergies =
      synergyFile.empty() ? std::nullopt : std::optional<SynergyModel>(loadSynergyModel(synergyFile));
  std::optional<PmdPostureFilter> filter;
  if (o.projectPmds) filter.emplace(*synergies, hand, *o.projectPmds, synergyFile.string(), "--project-pmds");

  std::unique_ptr<GloveLiveSource> source = o.device.empty()
                                                ? replayGloveRecording(readReplay(o), o.replayRate, o.speed)
                                                : openGloveDevice(o.device, o.deviceSettings);

  std::vector<std::string> notes{"pmdplan glove stream: " + source->description(),
                                 "calibration " + calibrationFile.filename().string() + ", mapping " +
                                     mappingFile.filename().string() + ", robot " + task.robot->name()};
  if (filter)
    notes.push_back("filtered onto the own axes + the first " + std::to_string(filter->directions()) + " PMDs of " +
                    synergyFile.filename().string());
  const std::initializer_list<std::filesystem::path> inputs{o.replay, calibrationFile, mappingFile, synergyFile};
  if (!o.output.empty() && !o.rawOutput.empty() &&
      std::filesystem::weakly_canonical(o.output) == std::filesystem::weakly_canonical(o.rawOutput))
    throw InputError(o.output, "--raw-out", "the posture recording (-o) and the raw one (--raw-out) must be two files");
  // Before the viewer folder is written: every input is read, and no NAME.partial may be in the way.
  if (!o.output.empty()) LiveCsvFile::checkTarget(o.output, "-o", inputs);
  if (!o.rawOutput.empty()) LiveCsvFile::checkTarget(o.rawOutput, "--raw-out", inputs);
  std::unique_ptr<EventStreamServer> server;
  if (o.servePort) {
    const std::filesystem::path folder =
        !o.out.empty() ? std::filesystem::path(o.out)
        : !o.output.empty()
            ? std::filesystem::path(std::filesystem::path(o.output).replace_extension("").string() + "-viewer")
            : std::filesystem::path("glove-live-viewer");
    const ViewerData page = liveViewerData(task, synergies ? &*synergies : nullptr, synergyFile, hand,
                                           source->description(), o.projectPmds);
    checkViewerFolderOutputs(folder, page, viewerAssetDirectory(), "--out");  // no file of it may be an input
    writeViewerFolder(folder, page, viewerAssetDirectory());
    server = std::make_unique<EventStreamServer>(folder, *o.servePort);
    std::cout << "serving " << folder.string() << " at http://127.0.0.1:" << server->port()
              << "/ (live; Ctrl-C to stop)" << std::endl;
  }
  std::optional<LiveCsvFile> postures, raw;
  if (!o.output.empty()) {
    std::vector<std::string> postureNotes = notes;
    postureNotes.push_back("hand joint positions in rad; time_s from the first frame");
    std::string header = "time_s";
    for (const auto& joint : hand) header += "," + joint.name;
    postures.emplace(o.output, "-o", postureNotes, header, inputs);
  }
  if (!o.rawOutput.empty()) {
    std::string header = "time_s";
    for (const auto name : cyberGloveSensorNames()) header += "," + std::string(name);
    raw.emplace(o.rawOutput, "--raw-out", notes, header, inputs);
  }

  catchStopSignals();
  std::cout << "streaming from " << source->description() << std::endl;

  long long frames = 0, clamped = 0;
  std::string ending;
  const auto finishFiles = [&] {
    std::string kept;
    for (auto* file : {postures ? &*postures : nullptr, raw ? &*raw : nullptr}) {
      if (!file) continue;
      const long long rows = file->finish();
      kept += rows ? "; " + std::to_string(rows) + " frames kept in " + file->target().string()
                   : "; no frames, " + file->target().string() + " not written";
    }
    return kept;
  };
  try {
    GloveLiveFrame frame;
    const auto stop = [] { return stopSignal != 0; };
    for (;;) {
      if (o.frames > 0 && frames >= o.frames) {
        ending = "stopped after --frames " + std::to_string(o.frames);
        break;
      }
      const GloveLiveStatus status = source->next(frame, stop);
      if (status == GloveLiveStatus::Finished) {
        ending = "the recording ended";
        break;
      }
      if (status == GloveLiveStatus::Interrupted) {
        ending = "stopped by signal " + std::to_string(stopSignal);
        break;
      }
      const double readMs = epochMilliseconds();
      GloveRecording one;
      one.frames.push_back(frame.raw);
      const MappedPostures mapped = mapToJoints(calibrate(one, calibration), mapping, hand);
      clamped += mapped.clampedValues;
      Eigen::VectorXd posture = mapped.postures.row(0).transpose();
      if (filter) posture = filter->filter(posture);
      if (postures) postures->addRow(rowText(frame.timeS, posture));
      if (raw) {
        std::string row = exactNumberText(frame.timeS);
        for (const auto value : frame.raw) row += "," + std::to_string(value);
        raw->addRow(row);
      }
      if (server) {
        nlohmann::json event = {{"frame", frames},
                                {"t", frame.timeS},
                                {"read_ms", readMs},
                                {"positions", std::vector<double>(posture.data(), posture.data() + posture.size())}};
        server->publish("posture", event.dump());
      }
      ++frames;
    }
  } catch (const InputError& error) {
    if (server) server->publish("end", nlohmann::json({{"frames", frames}, {"reason", error.message()}}).dump());
    throw InputError(error.file(), error.field(), error.message() + finishFiles());
  }
  if (server) server->publish("end", nlohmann::json({{"frames", frames}, {"reason", ending}}).dump());
  const std::string kept = finishFiles();
  std::cout << frames << " frames from " << source->description() << "; " << ending << kept << "\n";
  if (clamped) std::cout << clamped << " joint values were beyond a limit and clamped to it\n";
  if (source->skippedBytes())
    std::cout << "skipped " << source->skippedBytes() << " bytes that were not part of a valid 'G' reply\n";
  return 0;
}

}  // namespace

std::function<int()> addGloveStreamCommand(CLI::App& glove) {
  auto o = std::make_shared<StreamOptions>();
  CLI::App* app = glove.add_subcommand("stream",
                                       "The glove live: a CyberGlove on a serial device (or a replayed recording) to "
                                       "the viewer and a recording, frame by frame");
  app->add_option("--device", o->device, "The glove's serial device (e.g. /dev/ttyUSB0)");
  app->add_option("--baud", o->deviceSettings.baud, "The glove's baud rate (default 115200)");
  app->add_option("--poll-rate", o->deviceSettings.pollRateHz,
                  "'G' requests per second (default 100; 0: the glove streams by itself)");
  app->add_option("--timeout", o->deviceSettings.timeoutS,
                  "Seconds without a valid reply before giving up (default 2)");
  app->add_option("--replay", o->replay,
                  "Play a recording (CSV, or a raw 'G'-reply stream .bin/.raw/.serial) at its recorded rate");
  app->add_option("--format", o->format, "With --replay: csv, serial or auto (by extension; default)");
  app->add_option("--rate", o->replayRate,
                  "With --replay of a recording without time_s: frames per second (default 100)");
  app->add_option("--speed", o->speed, "With --replay: playback speed (default 1: as recorded)");
  app->add_option("--frames", o->frames,
                  "Stop after this many frames (default 0: until the end, Ctrl-C or the device's end)");
  app->add_option("--calibration", o->calibration,
                  "Calibration YAML (required with --device; with --replay default REC's name with .calibration.yaml)");
  app->add_option("--mapping", o->mapping,
                  "Sensor -> joint mapping YAML (default data/glove/cyberglove22_to_sah.yaml)");
  app->add_option("--task", o->task,
                  "Task whose robot and scene the viewer shows (default can_on_table; the arm stays at its start)");
  app->add_option("--project-pmds", o->projectPmds,
                  "Filter each posture onto the own axes + the first K PMDs (the paper's filtering)");
  app->add_option("--synergies", o->synergies,
                  "Synergy model YAML for --project-pmds and the viewer (default: the robot's shipped model)");
  app->add_option("-o,--output", o->output,
                  "Posture recording to write (CSV: time_s and the hand joints in rad, row by row)");
  app->add_option("--raw-out", o->rawOutput,
                  "Raw glove recording to write (the glove CSV form, readable by synergies and --replay)");
  app->add_option("--serve", o->servePort,
                  "Serve the live viewer on 127.0.0.1:PORT while streaming (0: any free port)");
  app->add_option(
      "--out", o->out,
      "Viewer folder to write for --serve (default: the recording's name with -viewer, or glove-live-viewer)");
  addPackagePathOption(*app);
  return [o] { return runStream(*o); };
}

}  // namespace pmdplan::cli
