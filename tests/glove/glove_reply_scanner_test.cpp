#include "pmdplan/glove/glove_reply_scanner.hpp"

#include <gtest/gtest.h>

#include "pmdplan/glove/glove_serial_stream.hpp"

namespace pmdplan {
namespace {

GloveFrame frameOf(std::uint8_t first) {
  GloveFrame frame{};
  for (std::size_t s = 0; s < frame.size(); ++s) frame[s] = static_cast<std::uint8_t>(first + s);
  return frame;
}

std::string replyOf(const GloveFrame& frame) {
  GloveRecording recording;
  recording.frames = {frame};
  return formatGloveSerialStream(recording);
}

TEST(GloveReplyScanner, AReplySplitAcrossReadsComesOutWhole) {
  GloveReplyScanner scanner;
  const std::string bytes = replyOf(frameOf(10)) + replyOf(frameOf(40));
  std::vector<GloveFrame> frames;
  for (std::size_t at = 0; at < bytes.size(); at += 5) {
    scanner.feed(bytes.substr(at, 5));
    while (const auto frame = scanner.next()) frames.push_back(*frame);
  }
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0], frameOf(10));
  EXPECT_EQ(frames[1], frameOf(40));
  EXPECT_EQ(scanner.skippedBytes(), 0);
  EXPECT_EQ(scanner.offset(), 48);
}

TEST(GloveReplyScanner, GarbageAndBrokenRepliesAreSkippedAndCounted) {
  GloveReplyScanner scanner;
  std::string broken = replyOf(frameOf(60));
  broken[7] = '\0';  // a zero reading: this 'G' starts no reply
  scanner.feed("xy" + broken + replyOf(frameOf(90)));
  const auto frame = scanner.next();
  ASSERT_TRUE(frame);
  EXPECT_EQ(*frame, frameOf(90));
  EXPECT_EQ(scanner.skippedBytes(), 2 + 24);
  EXPECT_EQ(scanner.skippedSinceReply(), 0);
  EXPECT_FALSE(scanner.next());
}

TEST(GloveReplyScanner, AReadingThatLooksLikeTheLeadByteDoesNotFoolIt) {
  GloveReplyScanner scanner;
  GloveFrame withG = frameOf(100);
  withG[3] = 'G';
  scanner.feed(replyOf(withG).substr(4) + replyOf(withG));  // starts mid-reply, after a reading
  const auto frame = scanner.next();
  ASSERT_TRUE(frame);
  EXPECT_EQ(*frame, withG);
}

TEST(GloveReplyScanner, BytesWithoutAReplyAreCountedUntilOneComes) {
  GloveReplyScanner scanner;
  scanner.feed(std::string(100, 'U'));
  EXPECT_FALSE(scanner.next());
  EXPECT_EQ(scanner.skippedSinceReply(), 100);
  scanner.feed(replyOf(frameOf(1)));
  EXPECT_TRUE(scanner.next());
  EXPECT_EQ(scanner.skippedSinceReply(), 0);
  EXPECT_EQ(scanner.skippedBytes(), 100);
}

}  // namespace
}  // namespace pmdplan
