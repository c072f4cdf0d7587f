#pragma once
// A glove recording file in either of its forms, as one service for every command that reads one
// (`pmdplan synergies`, `glove convert`, `glove stream --replay`): the CSV form (glove_csv.hpp) or
// the raw 'G'-reply stream (glove_serial_stream.hpp), told by a format name or the file's
// extension; and the calibration file a recording is read with.
#include <filesystem>
#include <string>

#include "pmdplan/glove/glove_recording.hpp"

namespace pmdplan {

enum class GloveRecordingFormat { Csv, Serial };

/// The format `given` names: "csv", "serial", or "auto" (or empty) for the extension of `file`:
/// .csv and .txt are CSV, .bin, .raw and .serial the raw stream. InputError naming `option` for
/// another name, and naming `file` and `option` for an extension that tells nothing.
GloveRecordingFormat gloveRecordingFormat(const std::filesystem::path& file, const std::string& given,
                                          const std::string& option);

/// readGloveCsv or readGloveSerialStream of `file`, by gloveRecordingFormat(file, given, option).
GloveRecording readGloveRecording(const std::filesystem::path& file, const std::string& given = "auto",
                                  const std::string& option = "--format");

/// Where a recording's calibration is written beside it: its name with .calibration.yaml.
std::filesystem::path calibrationBesideRecording(const std::filesystem::path& recording);

/// The calibration to read `recording` with: `given` when not empty, otherwise the one beside the
/// recording, which must exist (InputError naming the recording and "--calibration").
std::filesystem::path recordingCalibrationPath(const std::filesystem::path& recording,
                                               const std::filesystem::path& given);

}  // namespace pmdplan
