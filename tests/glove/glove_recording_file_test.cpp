// readGloveRecording and recordingCalibrationPath (glove/glove_recording_file.hpp): a recording in
// either form, told by its format name or extension, and the calibration beside it.
#include "pmdplan/glove/glove_recording_file.hpp"

#include <gtest/gtest.h>

#include "pmdplan/glove/glove_csv.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

GloveRecording twoFrames() {
  GloveRecording recording;
  GloveFrame a{}, b{};
  for (int s = 0; s < kCyberGloveSensorCount; ++s) {
    a[static_cast<std::size_t>(s)] = static_cast<std::uint8_t>(1 + s);
    b[static_cast<std::size_t>(s)] = static_cast<std::uint8_t>(200 - s);
  }
  recording.frames = {a, b};
  return recording;
}

TEST(GloveRecordingFile, TheExtensionTellsTheFormatUnlessOneIsNamed) {
  EXPECT_EQ(gloveRecordingFormat("r.csv", "auto", "--format"), GloveRecordingFormat::Csv);
  EXPECT_EQ(gloveRecordingFormat("r.txt", "", "--format"), GloveRecordingFormat::Csv);
  for (const char* name : {"r.bin", "r.raw", "r.serial"})
    EXPECT_EQ(gloveRecordingFormat(name, "auto", "--format"), GloveRecordingFormat::Serial) << name;
  EXPECT_EQ(gloveRecordingFormat("r.csv", "serial", "--format"), GloveRecordingFormat::Serial);
  EXPECT_EQ(gloveRecordingFormat("r.dat", "csv", "--format"), GloveRecordingFormat::Csv);
  test::expectInputError([] { gloveRecordingFormat("r.dat", "auto", "--from"); }, "r.dat", "--from",
                         "cannot tell the format from the file name");
  test::expectInputError([] { gloveRecordingFormat("r.csv", "xml", "--format"); }, "", "--format",
                         "expected csv, serial or auto, got 'xml'");
}

TEST(GloveRecordingFile, BothFormsReadAsTheSameFrames) {
  const test::TempDir dir;
  const GloveRecording recording = twoFrames();
  const auto csv = dir.write("r.csv", formatGloveCsv(recording));
  const auto serial = dir.write("r.bin", formatGloveSerialStream(recording));
  const auto unnamed = dir.write("r.dat", formatGloveSerialStream(recording));
  EXPECT_EQ(readGloveRecording(csv).frames, recording.frames);
  EXPECT_EQ(readGloveRecording(serial).frames, recording.frames);
  EXPECT_EQ(readGloveRecording(unnamed, "serial").frames, recording.frames);
  test::expectInputError([&] { readGloveRecording(unnamed); }, unnamed.string(), "--format", "cannot tell");
}

TEST(GloveRecordingFile, TheCalibrationIsTheOneGivenElseTheOneBesideTheRecording) {
  const test::TempDir dir;
  const auto recording = dir.path() / "session.csv";
  EXPECT_EQ(calibrationBesideRecording(recording), dir.path() / "session.calibration.yaml");
  EXPECT_EQ(recordingCalibrationPath(recording, "given.yaml"), "given.yaml");
  test::expectInputError([&] { recordingCalibrationPath(recording, {}); }, recording.string(), "--calibration",
                         "session.calibration.yaml is not beside the recording");
  const auto beside = dir.write("session.calibration.yaml", "");
  EXPECT_EQ(recordingCalibrationPath(recording, {}), beside);
}

}  // namespace
}  // namespace pmdplan
