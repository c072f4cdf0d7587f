// `pmdplan glove synth` and `pmdplan glove convert`, run as the real program.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using ::testing::HasSubstr;

using test::CliResult;
using test::contents;
using test::quoted;
using test::runCli;

const std::filesystem::path kGloveData = std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "glove";

TEST(GloveCli, SynthWritesARecordingAndItsCalibrationBothMarkedSynthetic) {
  test::TempDir dir;
  const auto result = runCli(dir, "glove synth --frames 300 --seed 4 -o " + quoted(dir.path() / "rec.csv"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_THAT(result.out, HasSubstr("SYNTHETIC"));
  const std::string csv = contents(dir.path() / "rec.csv");
  const std::string calibration = contents(dir.path() / "rec.calibration.yaml");
  EXPECT_EQ(csv.rfind("# SYNTHETIC glove recording", 0), 0u);
  EXPECT_THAT(csv, HasSubstr("Calibration: rec.calibration.yaml"));
  EXPECT_THAT(csv, HasSubstr("time_s,ThumbRotate,ThumbMPJ,"));
  EXPECT_THAT(calibration, HasSubstr("description: \"SYNTHETIC calibration"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4 + 1 + 300);  // notes, header, frames
}

TEST(GloveCli, SameSeedGivesByteIdenticalFiles) {
  test::TempDir dir;
  ASSERT_EQ(runCli(dir, "glove synth --frames 500 --seed 9 -o " + quoted(dir.path() / "a.csv") + " --calibration-out " +
                            quoted(dir.path() / "cal.yaml"))
                .exitCode,
            0);
  const std::string first = contents(dir.path() / "a.csv");
  const std::string firstCalibration = contents(dir.path() / "cal.yaml");
  ASSERT_EQ(runCli(dir, "glove synth --frames 500 --seed 9 -o " + quoted(dir.path() / "a.csv") + " --calibration-out " +
                            quoted(dir.path() / "cal.yaml"))
                .exitCode,
            0);
  EXPECT_EQ(contents(dir.path() / "a.csv"), first);
  EXPECT_EQ(contents(dir.path() / "cal.yaml"), firstCalibration);
  ASSERT_EQ(runCli(dir, "glove synth --frames 500 --seed 10 -o " + quoted(dir.path() / "a.csv") +
                            " --calibration-out " + quoted(dir.path() / "cal.yaml"))
                .exitCode,
            0);
  EXPECT_NE(contents(dir.path() / "a.csv"), first);
}

TEST(GloveCli, TheShippedSampleRecordingRegeneratesIdentically) {
  test::TempDir dir;
  ASSERT_EQ(runCli(dir, "glove synth --frames 200 --seed 1 -o " + quoted(dir.path() / "synthetic_operator_sample.csv"))
                .exitCode,
            0);
  EXPECT_EQ(contents(dir.path() / "synthetic_operator_sample.csv"),
            contents(kGloveData / "synthetic_operator_sample.csv"));
  EXPECT_EQ(contents(dir.path() / "synthetic_operator_sample.calibration.yaml"),
            contents(kGloveData / "synthetic_operator_sample.calibration.yaml"));
}

TEST(GloveCli, ConvertsBetweenCsvAndTheSerialStream) {
  test::TempDir dir;
  const auto stream = dir.path() / "sample.bin";
  const auto back = dir.path() / "back.csv";
  const auto toStream =
      runCli(dir, "glove convert " + quoted(kGloveData / "synthetic_operator_sample.csv") + " -o " + quoted(stream));
  ASSERT_EQ(toStream.exitCode, 0) << toStream.err;
  EXPECT_EQ(std::filesystem::file_size(stream), 200u * 24u);
  ASSERT_EQ(runCli(dir, "glove convert " + quoted(stream) + " -o " + quoted(back)).exitCode, 0);
  // The stream carries no times or notes; the sensor columns come back unchanged.
  const std::string original = contents(kGloveData / "synthetic_operator_sample.csv");
  const std::string firstRow = original.substr(
      original.find("\n0,") + 3, original.find('\n', original.find("\n0,") + 1) - original.find("\n0,") - 3);
  const std::string converted = contents(back);
  EXPECT_THAT(converted, HasSubstr("ThumbRotate,ThumbMPJ"));
  EXPECT_THAT(converted, HasSubstr("\n" + firstRow + "\n"));
}

TEST(GloveCli, BadInputExitsWith2AndNamesThePlace) {
  test::TempDir dir;
  auto result = runCli(dir, "glove synth --frames 0 -o " + quoted(dir.path() / "r.csv"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("--frames"));
  result = runCli(dir, "glove synth -o " + quoted(dir.path() / "r.txt"));
  EXPECT_EQ(result.exitCode, 2);
  const auto broken = dir.write("broken.bin", std::string("G") + std::string(22, '\x05') + std::string(1, '\0') + "X");
  result = runCli(dir, "glove convert " + quoted(broken) + " -o " + quoted(dir.path() / "out.csv"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("pmdplan: error: " + broken.string() + ": reply 2 (byte 24): truncated reply"));
  result = runCli(dir, "glove convert " + quoted(kGloveData / "synthetic_operator_sample.csv") + " -o " +
                           quoted(dir.path() / "out.dat"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("cannot tell the format"));
}

}  // namespace
}  // namespace pmdplan
