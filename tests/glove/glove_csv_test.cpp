#include "pmdplan/glove/glove_csv.hpp"

#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"
#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

std::string header(bool withTime = true) {
  std::string text = withTime ? "time_s" : "";
  for (const auto name : cyberGloveSensorNames()) text += (text.empty() ? "" : ",") + std::string(name);
  return text + "\n";
}

std::string row(const std::string& time, int base) {
  std::string text = time;
  for (int s = 0; s < kCyberGloveSensorCount; ++s)
    text += (text.empty() ? "" : ",") + std::to_string((base + 7 * s) % 256);
  return text + "\n";
}

TEST(GloveCsv, ReadsHeaderTimesAndFrames) {
  const auto recording = parseGloveCsv("# a note\n" + header() + row("0", 1) + row("0.01", 2), "rec.csv");
  ASSERT_EQ(recording.frameCount(), 2);
  EXPECT_EQ(recording.notes, std::vector<std::string>{"a note"});
  EXPECT_EQ(recording.timeS, (std::vector<double>{0.0, 0.01}));
  EXPECT_EQ(recording.frames[1][0], 2);
  EXPECT_EQ(recording.frames[1][21], (2 + 7 * 21) % 256);
  EXPECT_EQ(recording.dataLocation, "lines 3-4");
}

TEST(GloveCsv, TimeColumnIsOptionalAndColumnsMayComeInAnyOrder) {
  const auto recording = parseGloveCsv("WristYaw," + header(false).substr(0, header(false).rfind(",WristYaw")) + "\n" +
                                           "9,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21\r\n",
                                       "rec.csv");
  ASSERT_EQ(recording.frameCount(), 1);
  EXPECT_TRUE(recording.timeS.empty());
  EXPECT_EQ(recording.frames[0][21], 9);  // WristYaw came first
  EXPECT_EQ(recording.frames[0][0], 1);
}

TEST(GloveCsv, WriteThenReadGivesTheSameRecording) {
  GloveRecording recording;
  recording.notes = {"SYNTHETIC test"};
  for (int f = 0; f < 5; ++f) {
    GloveFrame frame{};
    for (int s = 0; s < kCyberGloveSensorCount; ++s)
      frame[static_cast<std::size_t>(s)] = static_cast<std::uint8_t>((f * 31 + s * 11) % 256);
    recording.frames.push_back(frame);
    recording.timeS.push_back(f / 100.0);
  }
  const auto back = parseGloveCsv(formatGloveCsv(recording), "x.csv");
  EXPECT_EQ(back.frames, recording.frames);
  EXPECT_EQ(back.timeS, recording.timeS);
  EXPECT_EQ(back.notes, recording.notes);
  EXPECT_EQ(formatGloveCsv(back), formatGloveCsv(recording));
}

TEST(GloveCsv, WrongColumnCountNamesTheLine) {
  test::expectInputError([] { parseGloveCsv(header() + row("0", 1) + "0.01,1,2,3\n", "rec.csv"); }, "rec.csv", "line 3",
                         "expected 23 columns");
}

TEST(GloveCsv, NonNumericCellNamesLineAndColumn) {
  std::string bad = row("0.01", 3);
  bad.replace(bad.find(',', bad.find(',') + 1) + 1, 1, "x");  // third cell: ThumbMPJ
  test::expectInputError([&] { parseGloveCsv(header() + bad, "rec.csv"); }, "rec.csv", "line 2, column ThumbMPJ",
                         "not an integer 0-255");
}

TEST(GloveCsv, RawValueOutsideTheByteRangeNamesLineAndColumn) {
  std::string high = header(false) + "256" + row("", 1).substr(row("", 1).find(','));
  test::expectInputError([&] { parseGloveCsv(high, "rec.csv"); }, "rec.csv", "line 2, column ThumbRotate",
                         "outside the raw sensor range 0-255");
  std::string negative = header(false) + "-3" + row("", 1).substr(row("", 1).find(','));
  test::expectInputError([&] { parseGloveCsv(negative, "rec.csv"); }, "rec.csv", "line 2, column ThumbRotate",
                         "outside the raw sensor range");
}

// A spreadsheet's UTF-8 export starts with a byte order mark: an encoding marker, not part of the
// first column's name (it was an invisible "unknown column 'time_s'"). One inside is shown escaped.
TEST(GloveCsv, ALeadingByteOrderMarkIsAnEncodingMarker) {
  const auto recording = parseGloveCsv("\xef\xbb\xbf" + header() + row("0", 1), "rec.csv");
  EXPECT_EQ(recording.frameCount(), 1);
  EXPECT_EQ(recording.timeS, std::vector<double>{0.0});
  EXPECT_EQ(parseGloveCsv("\xef\xbb\xbf# a note\n" + header() + row("0", 1), "rec.csv").notes,
            std::vector<std::string>{"a note"});
  test::expectInputError([] { parseGloveCsv("time_s,\xef\xbb\xbf" + header(false) + row("0", 1), "rec.csv"); },
                         "rec.csv", "line 1, column 2", "unknown column '\\ufeffThumbRotate'");
}

// A header cell is shown only when short and escaped: never a line of another file.
TEST(GloveCsv, AnUnknownColumnIsMeasuredOrEscapedNeverShownRaw) {
  const std::string secret = "root:$6$saltsalt$" + std::string(86, 'h') + ":19000:0:99999:7:::";
  try {
    parseGloveCsv(secret + "\n" + row("0", 1), "rec.csv");
    ADD_FAILURE() << "an unknown column was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("saltsalt"), std::string::npos) << error.what();
    EXPECT_NE(error.message().find("unknown column a text of 122 characters"), std::string::npos) << error.what();
  }
  test::expectInputError([] { parseGloveCsv("\x1b[2J" + header() + row("0", 1), "rec.csv"); }, "rec.csv",
                         "line 1, column 1", "unknown column '\\x1b[2Jtime_s'");
  test::expectInputError([&] { parseGloveCsv(header() + "\x1b[2J" + row("0", 1), "rec.csv"); }, "rec.csv",
                         "line 2, column time_s", "'\\x1b[2J0' is not a time");
}

TEST(GloveCsv, BadTimeNamesTheColumn) {
  test::expectInputError([] { parseGloveCsv(header() + row("soon", 1), "rec.csv"); }, "rec.csv",
                         "line 2, column time_s", "not a time");
}

TEST(GloveCsv, EmptyFileIsAnError) {
  test::expectInputError([] { parseGloveCsv("", "rec.csv"); }, "rec.csv", "line 1", "empty recording");
  test::expectInputError([] { parseGloveCsv("# only a comment\n\n", "rec.csv"); }, "rec.csv", "line 2",
                         "empty recording");
}

TEST(GloveCsv, HeaderWithoutFramesIsAnError) {
  test::expectInputError([] { parseGloveCsv(header(), "rec.csv"); }, "rec.csv", "line 1", "no frames");
}

TEST(GloveCsv, HeaderProblemsNameTheColumn) {
  test::expectInputError([] { parseGloveCsv("time_s,Thumb\n", "rec.csv"); }, "rec.csv", "line 1, column 2",
                         "unknown column 'Thumb'");
  test::expectInputError([] { parseGloveCsv("time_s,ThumbRotate\n", "rec.csv"); }, "rec.csv", "line 1",
                         "lacks the sensor columns ThumbMPJ");
  test::expectInputError([] { parseGloveCsv("ThumbRotate,ThumbRotate\n", "rec.csv"); }, "rec.csv", "line 1, column 2",
                         "appears twice");
}

TEST(GloveCsv, ReadsAFileAndNamesIt) {
  test::TempDir dir;
  const auto path = dir.write("rec.csv", header() + row("0", 5));
  EXPECT_EQ(readGloveCsv(path).frameCount(), 1);
  const auto bad = dir.write("bad.csv", header() + "1,2\n");
  test::expectInputError([&] { readGloveCsv(bad); }, bad.string(), "line 2", "columns");
  EXPECT_THROW(readGloveCsv(dir.path() / "missing.csv"), InputError);
}

}  // namespace
}  // namespace pmdplan
