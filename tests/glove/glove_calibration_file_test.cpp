#include "pmdplan/glove/glove_calibration_file.hpp"

#include <gtest/gtest.h>

#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

GloveCalibration sample() {
  GloveCalibration calibration;
  calibration.description = "test \"glove\" #2";
  for (int s = 0; s < kCyberGloveSensorCount; ++s)
    calibration.sensors[static_cast<std::size_t>(s)] = {0.0061 + s * (0.1 + 0.2) * 1e-3, -0.52 + s / 7.0};
  calibration.crossTerms.push_back({0, 3, -6.1e-4});
  return calibration;
}

std::string sensorsBlock(const std::string& replaceFirst = "") {
  std::string text = "sensors:\n";
  for (const auto name : cyberGloveSensorNames())
    text += "  " + (replaceFirst.empty() || name != "ThumbRotate" ? std::string(name) : replaceFirst) +
            ": {gain: 0.01, offset: 0}\n";
  return text;
}

TEST(GloveCalibrationFile, RoundTripsToIdenticalValues) {
  const GloveCalibration calibration = sample();
  const std::string text = formatGloveCalibration(calibration);
  const GloveCalibration back = parseGloveCalibration(text, "c.yaml");
  for (int s = 0; s < kCyberGloveSensorCount; ++s) {
    EXPECT_EQ(back.sensors[static_cast<std::size_t>(s)].gain, calibration.sensors[static_cast<std::size_t>(s)].gain);
    EXPECT_EQ(back.sensors[static_cast<std::size_t>(s)].offset,
              calibration.sensors[static_cast<std::size_t>(s)].offset);
  }
  ASSERT_EQ(back.crossTerms.size(), 1u);
  EXPECT_EQ(back.crossTerms[0].sensor, 0);
  EXPECT_EQ(back.crossTerms[0].from, 3);
  EXPECT_EQ(back.crossTerms[0].gain, -6.1e-4);
  EXPECT_EQ(back.description, calibration.description);
  EXPECT_EQ(formatGloveCalibration(back), text);
}

TEST(GloveCalibrationFile, CrossTermsAreOptional) {
  const auto calibration = parseGloveCalibration(sensorsBlock(), "c.yaml");
  EXPECT_TRUE(calibration.crossTerms.empty());
  EXPECT_EQ(calibration.sensors[21].gain, 0.01);
}

TEST(GloveCalibrationFile, UnknownSensorNamesTheLine) {
  test::expectInputError(
      [] { parseGloveCalibration("format: pmdplan-glove-calibration\n" + sensorsBlock("ThumbRoll"), "c.yaml"); },
      "c.yaml", "line 3", "unknown sensor 'ThumbRoll'");
}

TEST(GloveCalibrationFile, EverySensorNeedsACalibration) {
  std::string text = sensorsBlock();
  text.erase(text.find("  WristYaw"));
  test::expectInputError([&] { parseGloveCalibration(text, "c.yaml"); }, "c.yaml", "sensors (line 2)",
                         "no calibration for sensor WristYaw");
}

TEST(GloveCalibrationFile, BadValuesNameLineAndKey) {
  std::string text = sensorsBlock();
  text.replace(text.find("gain: 0.01"), 10, "gain: fast");
  test::expectInputError([&] { parseGloveCalibration(text, "c.yaml"); }, "c.yaml", "sensors.ThumbRotate.gain (line 2)",
                         "expected a gain in rad/count, got 'fast'");
  test::expectInputError(
      [] {
        parseGloveCalibration(sensorsBlock() + "cross_terms:\n  - {sensor: ThumbRotate, from: Nope, gain: 1}\n",
                              "c.yaml");
      },
      "c.yaml", "line 25", "unknown sensor 'Nope'");
  test::expectInputError([] { parseGloveCalibration(sensorsBlock() + "colour: blue\n", "c.yaml"); }, "c.yaml",
                         "line 24", "unknown key 'colour'");
  test::expectInputError([] { parseGloveCalibration("format: pmdplan-hand-mapping\n" + sensorsBlock(), "c.yaml"); },
                         "c.yaml", "format (line 1)", "not a pmdplan-glove-calibration file");
}

TEST(GloveCalibrationFile, SyntaxErrorsAndEmptyFilesNameTheLine) {
  test::expectInputError([] { parseGloveCalibration("sensors: [1, 2\nx: 3\n", "c.yaml"); }, "c.yaml", "line 2",
                         "YAML syntax error");
  test::expectInputError([] { parseGloveCalibration("\n", "c.yaml"); }, "c.yaml", "line 1", "empty file");
}

}  // namespace
}  // namespace pmdplan
