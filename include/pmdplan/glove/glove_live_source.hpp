#pragma once
// Where `pmdplan glove stream` gets its frames, one at a time as they happen: a CyberGlove on a
// serial line (polled with 'G' at a fixed rate, or streaming by itself) or a recording played back
// at its recorded rate. Both end cleanly on request (Ctrl-C); the device also ends when it closes
// (unplugged), falls silent or sends bytes that hold no reply, each an InputError that names it.
#include <functional>
#include <memory>
#include <string>

#include "pmdplan/glove/cyberglove_sensors.hpp"
#include "pmdplan/glove/glove_recording.hpp"

namespace pmdplan {

struct GloveLiveFrame {
  GloveFrame raw{};
  /// Seconds since the first frame (the device's arrival time, or the recording's time).
  double timeS = 0.0;
};

enum class GloveLiveStatus { Frame, Finished, Interrupted };

struct GloveDeviceSettings {
  /// The glove's line rate (CyberGlove default 115200).
  int baud = 115200;
  /// 'G' requests per second; 0 when the glove streams by itself and is sent nothing.
  double pollRateHz = 100.0;
  /// Seconds without a valid reply (from the opening, or from the last reply) before giving up.
  double timeoutS = 2.0;
  /// Bytes in a row that hold no valid reply before the stream is declared not a glove's.
  int maxSkippedBytes = 10 * (kCyberGloveSensorCount + 2);
};

class GloveLiveSource {
 public:
  virtual ~GloveLiveSource() = default;
  /// Waits for the next frame; returns Interrupted as soon as `stopRequested` says so (checked at
  /// least every 50 ms), Finished at the end of a recording. Throws InputError naming the device
  /// for a device that closes, times out or sends no valid reply in maxSkippedBytes bytes.
  virtual GloveLiveStatus next(GloveLiveFrame& frame, const std::function<bool()>& stopRequested) = 0;
  /// "device /dev/ttyUSB0 at 115200 baud" or "replay of rec.csv", for messages and the recording.
  virtual std::string description() const = 0;
  /// Bytes skipped to find replies (0 for a recording).
  virtual long long skippedBytes() const { return 0; }
};

std::unique_ptr<GloveLiveSource> openGloveDevice(const std::string& path, const GloveDeviceSettings& settings);

/// Replay speeds accepted (--speed): 0.01 to 100 times as recorded.
inline constexpr double kSmallestReplaySpeed = 0.01;
inline constexpr double kLargestReplaySpeed = 100.0;
/// The longest wait between two replayed frames as recorded (s): a longer gap in time_s (a typo such
/// as 1e9, 31 years) is an error, as is a time that goes back.
inline constexpr double kLongestReplayGapS = 60.0;

/// Plays `recording` at its time_s column (or at `rateHz` without one), times scaled by 1/`speed`.
/// Throws InputError naming the file and line of a time_s that goes back or jumps more than
/// kLongestReplayGapS ahead, before any frame plays.
std::unique_ptr<GloveLiveSource> replayGloveRecording(GloveRecording recording, double rateHz, double speed);

}  // namespace pmdplan
