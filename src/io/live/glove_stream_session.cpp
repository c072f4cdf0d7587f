#include "pmdplan/io/live/glove_stream_session.hpp"

#include <chrono>
#include <nlohmann/json.hpp>
#include <vector>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/glove_calibration.hpp"
#include "pmdplan/glove/glove_calibration_file.hpp"
#include "pmdplan/glove/glove_recording_file.hpp"
#include "pmdplan/io/files/live_csv_file.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/servers/event_stream_server.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/io/viewer/viewer_data.hpp"
#include "pmdplan/io/viewer/viewer_folder.hpp"
#include "pmdplan/io/viewer/viewer_folder_outputs.hpp"
#include "pmdplan/synergy/hand_mapping.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"
#include "pmdplan/synergy/pmd_posture_filter.hpp"
#include "pmdplan/synergy/synergy_model_resolution.hpp"
#include "pmdplan/text/number_text.hpp"
#include "pmdplan/world/task.hpp"

namespace pmdplan {
namespace {

std::filesystem::path streamCalibrationPath(const GloveStreamSettings& s) {
  if (!s.calibration.empty() || !s.replay.empty()) return recordingCalibrationPath(s.replay, s.calibration);
  throw InputError(s.device.string(), "--calibration",
                   "a live glove needs its operator's calibration: pass --calibration FILE.yaml");
}

/// The page: the task's scene with the robot at the task's start; the live hand replaces its hand.
ViewerData liveGloveViewerData(const Task& task, const ResolvedSynergyModel& synergies, const JointLimits& hand,
                               const std::string& source, const std::optional<int>& projectPmds) {
  PathFile still;
  still.task = task.name;
  still.planner = "glove";
  for (const auto& joint : task.robot->activeJoints()) still.jointNames.push_back(joint.name);
  still.points = {task.start, task.start};
  still.mimic = mimicRelations(*task.robot);
  ViewerData data = viewerData(task, still, synergies.get(), {"glove stream", synergies.file});
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

std::string livePostureRow(double timeS, const Eigen::VectorXd& values) {
  std::string row = exactNumberText(timeS);
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    row += ',';
    row += exactNumberText(values(i));
  }
  return row;
}

double epochMillisecondsNow() {
  return std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

struct GloveStreamSession::State {
  GloveStreamSettings settings;
  Task task;
  JointLimits hand;
  GloveCalibration calibration;
  HandMapping mapping;
  ResolvedSynergyModel synergies;
  std::optional<PmdPostureFilter> filter;
  std::unique_ptr<GloveLiveSource> source;
  std::optional<std::filesystem::path> folder;
  std::unique_ptr<EventStreamServer> server;
  std::optional<LiveCsvFile> postures, raw;

  /// Finishes the recordings: what was kept, as GloveStreamSummary::kept.
  std::string finishRecordings() {
    std::string kept;
    for (auto* file : {postures ? &*postures : nullptr, raw ? &*raw : nullptr}) {
      if (!file) continue;
      const long long rows = file->finish();
      kept += rows ? "; " + std::to_string(rows) + " frames kept in " + file->target().string()
                   : "; no frames, " + file->target().string() + " not written";
    }
    return kept;
  }
};

GloveStreamSession::GloveStreamSession(const GloveStreamSettings& settings) : state_(std::make_unique<State>()) {
  State& st = *state_;
  st.settings = settings;
  const GloveStreamSettings& s = st.settings;
  if (s.device.empty() == s.replay.empty())
    throw InputError(
        "", "--device",
        "give one source: the glove's serial device (--device /dev/ttyUSB0) or a recording to play (--replay REC.csv)");
  if (s.postureOutput.empty() && s.rawOutput.empty() && !s.servePort)
    throw InputError("", "-o",
                     "nothing to do: give -o POSTURES.csv (the recording), --raw-out RAW.csv, --serve PORT (the live "
                     "viewer), or several");
  if (s.frameLimit < 0) throw InputError("", "--frames", "expected 0 (no limit) or a number of frames to stop after");
  st.task = loadTaskByName(s.task);
  st.hand = st.task.robot->groupJoints("hand");
  const std::filesystem::path calibrationFile = streamCalibrationPath(s);
  st.calibration = loadGloveCalibration(calibrationFile);
  const std::filesystem::path mappingFile = s.mapping.empty() ? defaultHandMappingPath() : s.mapping;
  st.mapping = loadHandMapping(mappingFile);
  rulesForJoints(st.mapping, st.hand);  // a mapping of another hand fails here, not at the first frame

  // The robot's shipped model, if any, serves the filter and the viewer's synergy panel.
  if (!s.synergies.empty() || s.projectPmds || s.servePort)
    st.synergies = resolveSynergyModel(st.task.robot->name(), s.synergies, SynergyModelNeed::Optional);
  if (s.projectPmds && !st.synergies.model)
    throw InputError("", "--synergies",
                     "--project-pmds needs a synergy model and robot " + st.task.robot->name() +
                         " has none shipped: pass --synergies MODEL.yaml");
  if (s.projectPmds)
    st.filter.emplace(*st.synergies.model, st.hand, *s.projectPmds, st.synergies.file.string(), "--project-pmds");

  st.source = s.device.empty()
                  ? replayGloveRecording(readGloveRecording(s.replay, s.replayFormat), s.replayRate, s.speed)
                  : openGloveDevice(s.device.string(), s.deviceSettings);

  std::vector<std::string> notes{"pmdplan glove stream: " + st.source->description(),
                                 "calibration " + calibrationFile.filename().string() + ", mapping " +
                                     mappingFile.filename().string() + ", robot " + st.task.robot->name()};
  if (st.filter)
    notes.push_back("filtered onto the own axes + the first " + std::to_string(st.filter->directions()) + " PMDs of " +
                    st.synergies.file.filename().string());
  const std::initializer_list<std::filesystem::path> inputs{s.replay, calibrationFile, mappingFile, st.synergies.file};
  if (!s.postureOutput.empty() && !s.rawOutput.empty() &&
      std::filesystem::weakly_canonical(s.postureOutput) == std::filesystem::weakly_canonical(s.rawOutput))
    throw InputError(s.postureOutput.string(), "--raw-out",
                     "the posture recording (-o) and the raw one (--raw-out) must be two files");
  // Before the viewer folder is written: every input is read, and no NAME.partial may be in the way.
  if (!s.postureOutput.empty()) LiveCsvFile::checkTarget(s.postureOutput, "-o", inputs);
  if (!s.rawOutput.empty()) LiveCsvFile::checkTarget(s.rawOutput, "--raw-out", inputs);
  if (s.servePort) {
    const std::filesystem::path folder =
        !s.viewerFolder.empty() ? s.viewerFolder
        : !s.postureOutput.empty()
            ? std::filesystem::path(std::filesystem::path(s.postureOutput).replace_extension("").string() + "-viewer")
            : std::filesystem::path("glove-live-viewer");
    const ViewerData page =
        liveGloveViewerData(st.task, st.synergies, st.hand, st.source->description(), s.projectPmds);
    checkViewerFolderOutputs(folder, page, viewerAssetDirectory(), "--out");  // no file of it may be an input
    writeViewerFolder(folder, page, viewerAssetDirectory());
    st.server = std::make_unique<EventStreamServer>(folder, *s.servePort);
    st.folder = folder;
  }
  if (!s.postureOutput.empty()) {
    std::vector<std::string> postureNotes = notes;
    postureNotes.push_back("hand joint positions in rad; time_s from the first frame");
    std::string header = "time_s";
    for (const auto& joint : st.hand) header += "," + joint.name;
    st.postures.emplace(s.postureOutput, "-o", postureNotes, header, inputs);
  }
  if (!s.rawOutput.empty()) {
    std::string header = "time_s";
    for (const auto name : cyberGloveSensorNames()) header += "," + std::string(name);
    st.raw.emplace(s.rawOutput, "--raw-out", notes, header, inputs);
  }
}

GloveStreamSession::~GloveStreamSession() = default;

std::string GloveStreamSession::sourceDescription() const { return state_->source->description(); }

std::optional<std::filesystem::path> GloveStreamSession::servedFolder() const { return state_->folder; }

std::optional<int> GloveStreamSession::servedPort() const {
  return state_->server ? std::optional<int>(state_->server->port()) : std::nullopt;
}

GloveStreamSummary GloveStreamSession::run(const GloveStreamStop& stop) {
  State& st = *state_;
  GloveStreamSummary summary;
  std::string stopReason;
  const auto stopRequested = [&] {
    if (const auto reason = stop ? stop() : std::nullopt) {
      stopReason = *reason;
      return true;
    }
    return false;
  };
  const auto publishEnd = [&](const std::string& reason) {
    if (st.server) st.server->publish("end", nlohmann::json({{"frames", summary.frames}, {"reason", reason}}).dump());
  };
  try {
    GloveLiveFrame frame;
    for (;;) {
      if (st.settings.frameLimit > 0 && summary.frames >= st.settings.frameLimit) {
        summary.ending = "stopped after --frames " + std::to_string(st.settings.frameLimit);
        break;
      }
      const GloveLiveStatus status = st.source->next(frame, stopRequested);
      if (status == GloveLiveStatus::Finished) {
        summary.ending = "the recording ended";
        break;
      }
      if (status == GloveLiveStatus::Interrupted) {
        summary.ending = stopReason;
        break;
      }
      const double readMs = epochMillisecondsNow();
      GloveRecording one;
      one.frames.push_back(frame.raw);
      const MappedPostures mapped = mapToJoints(calibrate(one, st.calibration), st.mapping, st.hand);
      summary.clampedValues += mapped.clampedValues;
      Eigen::VectorXd posture = mapped.postures.row(0).transpose();
      if (st.filter) posture = st.filter->filter(posture);
      if (st.postures) st.postures->addRow(livePostureRow(frame.timeS, posture));
      if (st.raw) {
        std::string row = exactNumberText(frame.timeS);
        for (const auto value : frame.raw) {
          row += ',';
          row += std::to_string(value);
        }
        st.raw->addRow(row);
      }
      if (st.server) {
        nlohmann::json event = {{"frame", summary.frames},
                                {"t", frame.timeS},
                                {"read_ms", readMs},
                                {"positions", std::vector<double>(posture.data(), posture.data() + posture.size())}};
        st.server->publish("posture", event.dump());
      }
      ++summary.frames;
    }
  } catch (const InputError& error) {
    publishEnd(error.message());
    throw InputError(error.file(), error.field(), error.message() + st.finishRecordings());
  }
  publishEnd(summary.ending);
  summary.kept = st.finishRecordings();
  summary.skippedBytes = st.source->skippedBytes();
  return summary;
}

}  // namespace pmdplan
