// GloveStreamSession (io/live/glove_stream_session.hpp): the glove live behind `pmdplan glove
// stream`, here replaying the shipped synthetic sample fast: every frame reaches the recordings,
// the frame limit and a stop end it with their reason, bad settings fail before anything is written.
#include "pmdplan/io/live/glove_stream_session.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/glove/glove_csv.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using ::testing::HasSubstr;

std::filesystem::path sampleRecording() { return dataDirectory() / "glove" / "synthetic_operator_sample.csv"; }

/// Data rows (not '#' notes, not the header) of a CSV file.
long long dataRows(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  long long rows = -1;  // the header
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') ++rows;
  return rows;
}

GloveStreamSettings replaySettings(const test::TempDir& dir) {
  GloveStreamSettings settings;
  settings.replay = sampleRecording();
  settings.speed = 100.0;  // 200 frames at 100 Hz in 20 ms
  settings.postureOutput = dir.path() / "postures.csv";
  settings.rawOutput = dir.path() / "raw.csv";
  return settings;
}

TEST(GloveStreamSession, AReplayReachesTheRecordingsFrameByFrame) {
  const test::TempDir dir;
  const GloveRecording sample = readGloveCsv(sampleRecording());
  GloveStreamSession session(replaySettings(dir));
  EXPECT_THAT(session.sourceDescription(), HasSubstr("synthetic_operator_sample.csv"));
  EXPECT_FALSE(session.servedPort());
  const GloveStreamSummary summary = session.run({});
  EXPECT_EQ(summary.frames, sample.frameCount());
  EXPECT_EQ(summary.ending, "the recording ended");
  EXPECT_EQ(summary.kept, "; " + std::to_string(sample.frameCount()) + " frames kept in " +
                              (dir.path() / "postures.csv").string() + "; " + std::to_string(sample.frameCount()) +
                              " frames kept in " + (dir.path() / "raw.csv").string());
  EXPECT_EQ(dataRows(dir.path() / "postures.csv"), sample.frameCount());
  EXPECT_EQ(readGloveCsv(dir.path() / "raw.csv").frames, sample.frames) << "the raw recording is the input again";
}

TEST(GloveStreamSession, TheFrameLimitAndAStopEndItWithTheirReason) {
  const test::TempDir dir;
  GloveStreamSettings limited = replaySettings(dir);
  limited.frameLimit = 7;
  const GloveStreamSummary seven = GloveStreamSession(limited).run({});
  EXPECT_EQ(seven.frames, 7);
  EXPECT_EQ(seven.ending, "stopped after --frames 7");
  EXPECT_EQ(dataRows(dir.path() / "postures.csv"), 7);

  GloveStreamSettings stopped = replaySettings(dir);
  stopped.speed = 1.0;
  int asked = 0;
  const GloveStreamSummary summary = GloveStreamSession(stopped).run([&]() -> std::optional<std::string> {
    if (++asked < 3) return std::nullopt;
    return "stopped by the test";
  });
  EXPECT_EQ(summary.ending, "stopped by the test");
  EXPECT_LT(summary.frames, 200);
}

TEST(GloveStreamSession, BadSettingsFailBeforeAnythingIsWritten) {
  const test::TempDir dir;
  GloveStreamSettings nothing = replaySettings(dir);
  nothing.postureOutput.clear();
  nothing.rawOutput.clear();
  test::expectInputError([&] { GloveStreamSession{nothing}; }, "", "-o", "nothing to do");
  GloveStreamSettings twoSources = replaySettings(dir);
  twoSources.device = "/dev/null";
  test::expectInputError([&] { GloveStreamSession{twoSources}; }, "", "--device", "give one source");
  GloveStreamSettings noModel = replaySettings(dir);
  noModel.projectPmds = 2;
  noModel.synergies = dir.path() / "missing.yaml";
  EXPECT_THROW(GloveStreamSession{noModel}, InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "postures.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "raw.csv"));
}

}  // namespace
}  // namespace pmdplan
