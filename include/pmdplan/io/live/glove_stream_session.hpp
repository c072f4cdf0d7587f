#pragma once
// The glove live, as one library service (`pmdplan glove stream` translates its flags into
// GloveStreamSettings and prints the summary). Each frame, as it arrives from a CyberGlove on a
// serial line or from a recording played at its recorded rate, is calibrated, mapped to the robot
// hand's joints, optionally filtered onto the first K PMDs, written to the recordings (LiveCsvFile:
// a crash or a stop keeps what was recorded) and published to the web viewer as a server-sent
// event ("posture" per frame, "end" with the reason at the end).
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "pmdplan/glove/glove_live_source.hpp"

namespace pmdplan {

/// What a glove stream reads and writes; the options named in messages are the CLI's.
struct GloveStreamSettings {
  std::filesystem::path device;       ///< the glove's serial device (--device), or
  std::filesystem::path replay;       ///< a recording to play (--replay); exactly one of the two
  std::string replayFormat = "auto";  ///< the recording's format (glove/glove_recording_file.hpp)
  GloveDeviceSettings deviceSettings;
  double replayRate = 100.0;  ///< frames per second of a recording without time_s
  double speed = 1.0;         ///< playback speed of a recording (1: as recorded)
  long long frameLimit = 0;   ///< stop after this many frames (--frames); 0: no limit
  /// The operator's calibration; default for a recording: the one beside it (required for a device).
  std::filesystem::path calibration;
  std::filesystem::path mapping;        ///< sensor -> joint mapping; default defaultHandMappingPath()
  std::string task = "can_on_table";    ///< the task whose robot hand and scene are used
  std::optional<int> projectPmds;       ///< filter each posture onto the own axes + the first K PMDs
  std::filesystem::path synergies;      ///< default: the robot's shipped model, if any
  std::filesystem::path postureOutput;  ///< CSV: time_s and the hand joints in rad (-o)
  std::filesystem::path rawOutput;      ///< CSV: time_s and the raw sensor values (--raw-out)
  std::optional<int> servePort;         ///< serve the live viewer on 127.0.0.1:PORT (0: any free port)
  std::filesystem::path viewerFolder;   ///< default: -o's name with -viewer, or glove-live-viewer
};

/// How a stream went.
struct GloveStreamSummary {
  long long frames = 0;
  long long clampedValues = 0;  ///< joint values beyond a limit, clamped to it
  long long skippedBytes = 0;   ///< bytes of the device that were not part of a valid 'G' reply
  /// Why it ended: "the recording ended", "stopped after --frames N", or the stop's reason.
  std::string ending;
  /// What became of each recording: "; N frames kept in FILE" or "; no frames, FILE not written".
  std::string kept;
};

/// Asked between frames and while waiting for one: nullopt to go on, else why the stream stops
/// (e.g. "stopped by signal 2").
using GloveStreamStop = std::function<std::optional<std::string>()>;

class GloveStreamSession {
 public:
  /// Reads and checks every input (task, calibration, mapping, synergy model, the recording), checks
  /// every output, opens the source, writes and serves the viewer folder (servePort) and opens the
  /// recordings. InputError naming the option for anything wrong, before anything is written.
  explicit GloveStreamSession(const GloveStreamSettings& settings);
  ~GloveStreamSession();
  GloveStreamSession(const GloveStreamSession&) = delete;
  GloveStreamSession& operator=(const GloveStreamSession&) = delete;

  std::string sourceDescription() const;
  /// The viewer folder served and its port, when serving.
  std::optional<std::filesystem::path> servedFolder() const;
  std::optional<int> servedPort() const;

  /// Streams until the source ends, the frame limit or `stop`; then finishes the recordings. A
  /// source that fails (InputError: the device closed, fell silent) ends the viewer's stream and the
  /// recordings, and is rethrown with what was kept appended to its message.
  GloveStreamSummary run(const GloveStreamStop& stop);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace pmdplan
