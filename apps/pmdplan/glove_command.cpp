// `pmdplan glove synth …`: a synthetic operator's glove recording (raw CyberGlove frames plus the
// calibration file they need) — NOT human data, and every file says so.
// `pmdplan glove convert IN -o OUT`: between the CSV form and the raw 'G'-reply serial stream.
// `pmdplan glove stream …`: the glove live (glove_stream_command.cpp).
#include <iostream>
#include <memory>

#include "command_registry.hpp"
#include "glove_stream_command.hpp"
#include "package_path_option.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/glove_calibration_file.hpp"
#include "pmdplan/glove/glove_csv.hpp"
#include "pmdplan/glove/glove_recording_file.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"
#include "pmdplan/synergy/synthetic_operator.hpp"

namespace pmdplan::cli::glove_command {
namespace {

struct SynthOptions {
  int frames = 13500;
  std::uint64_t seed = 1;
  std::string output;
  std::string calibrationOutput;
  std::string mapping;
  std::string robot = "sah_tx90";
};

int runSynth(const SynthOptions& o) {
  if (o.frames < 1 || o.frames > kMaxSyntheticFrames)
    throw InputError(
        "", "--frames",
        "expected 1 to " + std::to_string(kMaxSyntheticFrames) + " frames, got " + std::to_string(o.frames));
  const std::filesystem::path output = o.output;
  if (output.extension() != ".csv")
    throw InputError("", "-o", "the synthetic recording is written as CSV: give a .csv file name");
  const std::filesystem::path calibrationPath =
      o.calibrationOutput.empty() ? calibrationBesideRecording(output) : std::filesystem::path(o.calibrationOutput);
  checkOutputPath(output, "-o", {o.mapping});  // a bad output fails before the inputs are read
  checkOutputPath(calibrationPath, "--calibration-out", {o.mapping});
  const HandMapping mapping =
      loadHandMapping(o.mapping.empty() ? defaultHandMappingPath() : std::filesystem::path(o.mapping));
  const JointLimits hand = RobotModel::loadByNameOrPath(o.robot).groupJoints("hand");
  checkOutputPath(output, "-o");  // again, against the mapping and the robot's files now read
  checkOutputPath(calibrationPath, "--calibration-out");
  SyntheticOperatorSettings parameters;
  parameters.frames = o.frames;
  parameters.seed = o.seed;
  SyntheticGloveSession session = synthesiseGloveSession(parameters, mapping, hand);
  session.recording.notes.push_back("Calibration: " + calibrationPath.filename().string() + " (also synthetic).");
  StagedOutputs staged;  // both files or neither
  writeFileAtomically(output, formatGloveCsv(session.recording));
  writeFileAtomically(calibrationPath, formatGloveCalibration(session.calibration));
  staged.commit();
  std::cout << "wrote " << output.string() << ": " << o.frames << " SYNTHETIC glove frames (seed " << o.seed
            << ", not human data)\nwrote " << calibrationPath.string() << ": its synthetic calibration\n";
  return 0;
}

struct ConvertOptions {
  std::string input;
  std::string output;
  std::string from = "auto";
  std::string to = "auto";
};

int runConvert(const ConvertOptions& o) {
  checkOutputPath(o.output, "-o", {o.input});
  const GloveRecording recording = readGloveRecording(o.input, o.from, "--from");
  if (gloveRecordingFormat(o.output, o.to, "--to") == GloveRecordingFormat::Csv) {
    writeFileAtomically(o.output, formatGloveCsv(recording));
  } else {
    for (std::size_t f = 0; f < recording.frames.size(); ++f)
      for (const auto value : recording.frames[f])
        if (value == 0)
          throw InputError(o.input, "frame " + std::to_string(f + 1),
                           "a raw reading of 0 cannot be sent in a 'G' reply (the glove sends 1-255)");
    writeFileAtomically(o.output, formatGloveSerialStream(recording));
  }
  std::cout << "wrote " << o.output << ": " << recording.frameCount() << " frames\n";
  return 0;
}

const CommandRegistrar registrar{
    "glove", "Glove recordings: a synthetic operator (synth), format conversion (convert), the glove live (stream)",
    [](CLI::App& app) {
      app.require_subcommand(1);
      auto synth = std::make_shared<SynthOptions>();
      CLI::App* synthCommand = app.add_subcommand(
          "synth", "Write a SYNTHETIC operator's raw 22-sensor glove recording (CSV) and its calibration");
      synthCommand->add_option("--frames", synth->frames,
                               "Number of frames at 100 Hz (default 13500, as in the paper)");
      synthCommand->add_option("--seed", synth->seed, "Random seed (same seed, same bytes; default 1)")
          ->check(wholeNumber());
      synthCommand->add_option("-o,--output", synth->output, "Recording to write (.csv)")->required();
      synthCommand->add_option("--calibration-out", synth->calibrationOutput,
                               "Calibration file to write (default: the recording's name with .calibration.yaml)");
      synthCommand->add_option("--mapping", synth->mapping,
                               "Hand mapping to invert (default data/glove/cyberglove22_to_sah.yaml)");
      addPackagePathOption(*synthCommand);
      synthCommand->add_option("--robot", synth->robot, "Built-in robot name or .urdf file (default sah_tx90)");

      auto convert = std::make_shared<ConvertOptions>();
      CLI::App* convertCommand =
          app.add_subcommand("convert", "Convert a recording between CSV and the raw 'G'-reply stream");
      convertCommand->add_option("input", convert->input, "Recording to read")->required();
      convertCommand->add_option("-o,--output", convert->output, "Recording to write")->required();
      convertCommand->add_option("--from", convert->from, "Input format: csv, serial or auto (by extension)");
      convertCommand->add_option("--to", convert->to, "Output format: csv, serial or auto (by extension)");
      auto stream = addGloveStreamCommand(app);
      return [synth, convert, synthCommand, convertCommand, stream] {
        if (synthCommand->parsed()) return runSynth(*synth);
        return convertCommand->parsed() ? runConvert(*convert) : stream();
      };
    }};

}  // namespace
}  // namespace pmdplan::cli::glove_command
