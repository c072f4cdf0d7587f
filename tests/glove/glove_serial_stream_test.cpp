#include "pmdplan/glove/glove_serial_stream.hpp"

#include <gtest/gtest.h>

#include "support/input_error_matchers.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

std::string reply(int base) {
  std::string bytes = "G";
  for (int s = 0; s < kCyberGloveSensorCount; ++s) bytes += static_cast<char>(1 + (base + 13 * s) % 255);
  bytes += '\0';
  return bytes;
}

TEST(GloveSerialStream, ReadsReplies) {
  const auto recording = parseGloveSerialStream(reply(0) + reply(100) + reply(254), "glove.bin");
  ASSERT_EQ(recording.frameCount(), 3);
  EXPECT_EQ(recording.frames[1][0], 101);
  EXPECT_EQ(recording.frames[2][1], 1 + (254 + 13) % 255);
  EXPECT_TRUE(recording.timeS.empty());
  EXPECT_EQ(recording.dataLocation, "replies 1-3");
}

TEST(GloveSerialStream, EachReplyIs24Bytes) {
  EXPECT_EQ(reply(0).size(), 24u);
  EXPECT_EQ(kGloveSerialReplyBytes, 24);
}

TEST(GloveSerialStream, WriteThenReadGivesTheSameFrames) {
  const auto recording = parseGloveSerialStream(reply(3) + reply(77), "a.bin");
  EXPECT_EQ(formatGloveSerialStream(recording), reply(3) + reply(77));
}

TEST(GloveSerialStream, AZeroReadingCannotBeWritten) {
  GloveRecording recording;
  recording.frames.push_back(GloveFrame{});
  EXPECT_THROW(formatGloveSerialStream(recording), std::invalid_argument);
}

TEST(GloveSerialStream, ErrorsNameTheReplyAndByte) {
  test::expectInputError([] { parseGloveSerialStream("", "g.bin"); }, "g.bin", "byte 0", "empty stream");
  test::expectInputError([] { parseGloveSerialStream(reply(0) + reply(1).substr(0, 10), "g.bin"); }, "g.bin",
                         "reply 2 (byte 24)", "truncated");
  std::string wrongLead = reply(0) + reply(1);
  wrongLead[24] = 'X';
  test::expectInputError([&] { parseGloveSerialStream(wrongLead, "g.bin"); }, "g.bin", "reply 2 (byte 24)",
                         "start with 'G'");
  std::string noTerminator = reply(0);
  noTerminator[23] = 5;
  test::expectInputError([&] { parseGloveSerialStream(noTerminator, "g.bin"); }, "g.bin", "reply 1 (byte 23)",
                         "end with a 0 byte");
  std::string zeroReading = reply(0);
  zeroReading[3] = '\0';
  test::expectInputError([&] { parseGloveSerialStream(zeroReading, "g.bin"); }, "g.bin", "reply 1 (byte 3)",
                         "ThumbIJ reads 0");
}

TEST(GloveSerialStream, ReadsABinaryFile) {
  test::TempDir dir;
  const auto path = dir.write("glove.bin", reply(9) + reply(10));
  EXPECT_EQ(readGloveSerialStream(path).frameCount(), 2);
}

}  // namespace
}  // namespace pmdplan
