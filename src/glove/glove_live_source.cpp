#include "pmdplan/glove/glove_live_source.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/glove_reply_scanner.hpp"
#include "pmdplan/glove/glove_serial_device.hpp"
#include "pmdplan/text/number_text.hpp"

namespace pmdplan {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kStopCheck = std::chrono::milliseconds(50);

double secondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

class DeviceSource final : public GloveLiveSource {
 public:
  DeviceSource(const std::string& path, const GloveDeviceSettings& settings)
      : settings_(settings), device_(path, settings.baud) {}

  GloveLiveStatus next(GloveLiveFrame& frame, const std::function<bool()>& stopRequested) override {
    if (!started_) {  // the timeout runs from the first wait, not from the opening
      started_ = true;
      lastReply_ = nextRequest_ = Clock::now();
    }
    for (;;) {
      if (const auto reply = scanner_.next()) {
        const auto now = Clock::now();
        if (frames_ == 0) first_ = now;
        ++frames_;
        lastReply_ = now;
        frame.raw = *reply;
        frame.timeS = secondsBetween(first_, now);
        return GloveLiveStatus::Frame;
      }
      if (scanner_.skippedSinceReply() > settings_.maxSkippedBytes)
        throw InputError(
            device_.path(), "byte " + std::to_string(scanner_.offset()),
            std::to_string(scanner_.skippedSinceReply()) +
                " bytes in a row hold no valid 'G' reply ('G', 22 readings 1-255, "
                "a 0 byte): wrong --baud (the glove's rate), a glove without 22 sensors, or not a CyberGlove");
      if (stopRequested()) return GloveLiveStatus::Interrupted;
      auto now = Clock::now();
      if (settings_.pollRateHz > 0 && now >= nextRequest_) {
        device_.requestSample();
        const auto period =
            std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / settings_.pollRateHz));
        nextRequest_ = std::max(nextRequest_ + period, now);
      }
      const auto silentFor = secondsBetween(lastReply_, now);
      if (silentFor > settings_.timeoutS) throw silence();
      auto wait =
          std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(settings_.timeoutS - silentFor));
      wait = std::min<Clock::duration>(wait, kStopCheck);
      if (settings_.pollRateHz > 0) wait = std::min<Clock::duration>(wait, nextRequest_ - now);
      const int waitMs = static_cast<int>(
          std::ceil(std::chrono::duration<double, std::milli>(std::max(wait, Clock::duration::zero())).count()));
      std::string bytes, reason;
      switch (device_.read(bytes, waitMs, reason)) {
        case GloveSerialDevice::Read::Data:
          scanner_.feed(bytes);
          break;
        case GloveSerialDevice::Read::Closed:
          throw InputError(device_.path(), "--device",
                           "the glove's device closed (" + reason + ") after " + std::to_string(frames_) +
                               " frames: unplugged, switched off or the line dropped");
        case GloveSerialDevice::Read::Timeout:
        case GloveSerialDevice::Read::Interrupted:
          break;
      }
    }
  }

  std::string description() const override {
    return "device " + device_.path() + " at " + std::to_string(settings_.baud) + " baud" +
           (settings_.pollRateHz > 0 ? ", polled with 'G' at " + messageNumberText(settings_.pollRateHz) + " Hz"
                                     : ", streaming");
  }
  long long skippedBytes() const override { return scanner_.skippedBytes(); }

 private:
  InputError silence() const {
    const std::string seconds = messageNumberText(settings_.timeoutS) + " s";
    if (frames_ == 0)
      return InputError(device_.path(), "--timeout",
                        "no 'G' reply in the first " + seconds +
                            " of the stream: is the glove connected and switched on, at --baud " +
                            std::to_string(settings_.baud) +
                            (settings_.pollRateHz > 0 ? "?" : "? (with --poll-rate 0 it must stream by itself)"));
    return InputError(
        device_.path(), "--timeout",
        "the glove sent no reply for " + seconds + " after " + std::to_string(frames_) + " frames: it stopped sending");
  }

  GloveDeviceSettings settings_;
  GloveSerialDevice device_;
  GloveReplyScanner scanner_;
  bool started_ = false;
  Clock::time_point first_, lastReply_, nextRequest_;
  long long frames_ = 0;
};

class ReplaySource final : public GloveLiveSource {
 public:
  ReplaySource(GloveRecording recording, double rateHz, double speed)
      : recording_(std::move(recording)), rateHz_(rateHz), speed_(speed) {}

  GloveLiveStatus next(GloveLiveFrame& frame, const std::function<bool()>& stopRequested) override {
    if (next_ >= recording_.frames.size()) return GloveLiveStatus::Finished;
    if (next_ == 0) start_ = Clock::now();
    const double recorded = recording_.timeS.empty()
                                ? static_cast<double>(next_) / rateHz_
                                : std::max(0.0, recording_.timeS[next_] - recording_.timeS.front());
    const auto due =
        start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(recorded / speed_));
    for (auto now = Clock::now(); now < due; now = Clock::now()) {
      if (stopRequested()) return GloveLiveStatus::Interrupted;
      std::this_thread::sleep_for(std::min<Clock::duration>(due - now, kStopCheck));
    }
    if (stopRequested()) return GloveLiveStatus::Interrupted;
    frame.raw = recording_.frames[next_++];
    frame.timeS = recorded;
    return GloveLiveStatus::Frame;
  }

  std::string description() const override { return "replay of " + recording_.source; }

 private:
  GloveRecording recording_;
  double rateHz_;
  double speed_;
  std::size_t next_ = 0;
  Clock::time_point start_;
};

}  // namespace

std::unique_ptr<GloveLiveSource> openGloveDevice(const std::string& path, const GloveDeviceSettings& settings) {
  if (!(settings.timeoutS > 0) || !std::isfinite(settings.timeoutS))
    throw InputError("", "--timeout", "expected a time in seconds > 0");
  if (!(settings.pollRateHz >= 0) || settings.pollRateHz > 10000)
    throw InputError("", "--poll-rate", "expected 0 (the glove streams by itself) to 10000 requests per second");
  return std::make_unique<DeviceSource>(path, settings);
}

std::unique_ptr<GloveLiveSource> replayGloveRecording(GloveRecording recording, double rateHz, double speed) {
  if (!(rateHz > 0) || rateHz > 10000)
    throw InputError("", "--rate", "expected a frame rate in Hz, > 0 and at most 10000");
  if (!(speed >= kSmallestReplaySpeed && speed <= kLargestReplaySpeed))
    throw InputError("", "--speed", "expected a playback speed from 0.01 to 100 (1: as recorded)");
  // The whole recording is read before it plays: its times are checked here, before the first frame.
  for (std::size_t f = 1; f < recording.timeS.size(); ++f) {
    const double gap = recording.timeS[f] - recording.timeS[f - 1];
    if (gap >= 0.0 && gap <= kLongestReplayGapS) continue;
    const std::string field = f < recording.frameLines.size() ? "line " + std::to_string(recording.frameLines[f])
                                                              : "frame " + std::to_string(f + 1);
    char text[160];
    std::snprintf(text, sizeof text,
                  "time_s %s by %.6g s from the frame before; expected times that never go back "
                  "and gaps of at most %g s",
                  gap < 0.0 ? "goes back" : "jumps ahead", std::abs(gap), kLongestReplayGapS);
    throw InputError(recording.source, field + ", column time_s", text);
  }
  return std::make_unique<ReplaySource>(std::move(recording), rateHz, speed);
}

}  // namespace pmdplan
