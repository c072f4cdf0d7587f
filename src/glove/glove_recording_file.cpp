#include "pmdplan/glove/glove_recording_file.hpp"

#include <system_error>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/glove/glove_csv.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"

namespace pmdplan {

GloveRecordingFormat gloveRecordingFormat(const std::filesystem::path& file, const std::string& given,
                                          const std::string& option) {
  if (given == "csv") return GloveRecordingFormat::Csv;
  if (given == "serial") return GloveRecordingFormat::Serial;
  if (!given.empty() && given != "auto")
    throw InputError("", option, "expected csv, serial or auto, got '" + given + "'");
  const auto extension = file.extension();
  if (extension == ".csv" || extension == ".txt") return GloveRecordingFormat::Csv;
  if (extension == ".bin" || extension == ".raw" || extension == ".serial") return GloveRecordingFormat::Serial;
  throw InputError(
      file.string(), option,
      "cannot tell the format from the file name: use .csv or .bin/.raw/.serial, or give " + option + " csv|serial");
}

GloveRecording readGloveRecording(const std::filesystem::path& file, const std::string& given,
                                  const std::string& option) {
  return gloveRecordingFormat(file, given, option) == GloveRecordingFormat::Csv ? readGloveCsv(file)
                                                                                : readGloveSerialStream(file);
}

std::filesystem::path calibrationBesideRecording(const std::filesystem::path& recording) {
  return std::filesystem::path(recording).replace_extension(".calibration.yaml");
}

std::filesystem::path recordingCalibrationPath(const std::filesystem::path& recording,
                                               const std::filesystem::path& given) {
  if (!given.empty()) return given;
  const auto beside = calibrationBesideRecording(recording);
  std::error_code error;
  if (std::filesystem::exists(beside, error)) return beside;
  throw InputError(recording.string(), "--calibration",
                   "no calibration given and " + beside.filename().string() +
                       " is not beside the recording; pass --calibration FILE");
}

}  // namespace pmdplan
