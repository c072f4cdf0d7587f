// `pmdplan glove stream (--device TTY | --replay REC) [-o postures.csv] [--raw-out raw.csv]
// [--project-pmds K] [--serve PORT]`: the glove live, a GloveStreamSession
// (io/live/glove_stream_session.hpp) with the flags as its settings. Ctrl-C ends it cleanly (exit
// 0); a device that closes, falls silent or sends no replies ends it with exit 2 and keeps what was
// recorded.
#include "glove_stream_command.hpp"

#include <csignal>
#include <iostream>
#include <memory>

#include "package_path_option.hpp"
#include "pmdplan/io/live/glove_stream_session.hpp"

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

int runStream(const GloveStreamSettings& settings) {
  GloveStreamSession session(settings);
  if (const auto port = session.servedPort())
    std::cout << "serving " << session.servedFolder()->string() << " at http://127.0.0.1:" << *port
              << "/ (live; Ctrl-C to stop)" << std::endl;
  catchStopSignals();
  std::cout << "streaming from " << session.sourceDescription() << std::endl;
  const GloveStreamSummary summary = session.run([]() -> std::optional<std::string> {
    if (stopSignal == 0) return std::nullopt;
    return "stopped by signal " + std::to_string(stopSignal);
  });
  std::cout << summary.frames << " frames from " << session.sourceDescription() << "; " << summary.ending
            << summary.kept << "\n";
  if (summary.clampedValues)
    std::cout << summary.clampedValues << " joint values were beyond a limit and clamped to it\n";
  if (summary.skippedBytes)
    std::cout << "skipped " << summary.skippedBytes << " bytes that were not part of a valid 'G' reply\n";
  return 0;
}

}  // namespace

std::function<int()> addGloveStreamCommand(CLI::App& glove) {
  auto o = std::make_shared<GloveStreamSettings>();
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
  app->add_option("--format", o->replayFormat, "With --replay: csv, serial or auto (by extension; default)");
  app->add_option("--rate", o->replayRate,
                  "With --replay of a recording without time_s: frames per second (default 100)");
  app->add_option("--speed", o->speed, "With --replay: playback speed (default 1: as recorded)");
  app->add_option("--frames", o->frameLimit,
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
  app->add_option("-o,--output", o->postureOutput,
                  "Posture recording to write (CSV: time_s and the hand joints in rad, row by row)");
  app->add_option("--raw-out", o->rawOutput,
                  "Raw glove recording to write (the glove CSV form, readable by synergies and --replay)");
  app->add_option("--serve", o->servePort,
                  "Serve the live viewer on 127.0.0.1:PORT while streaming (0: any free port)");
  app->add_option(
      "--out", o->viewerFolder,
      "Viewer folder to write for --serve (default: the recording's name with -viewer, or glove-live-viewer)");
  addPackagePathOption(*app);
  return [o] { return runStream(*o); };
}

}  // namespace pmdplan::cli
