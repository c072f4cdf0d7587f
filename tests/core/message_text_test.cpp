// How messages show text from files: control characters, invisible characters and bytes that are
// not UTF-8 escaped, long or multi-line values measured, and every InputError escaped whole.
#include "pmdplan/core/message_text.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

TEST(MessageText, EscapesWhatATerminalWouldActOn) {
  EXPECT_EQ(escapedText("plain text, 42 °C"), "plain text, 42 °C");
  EXPECT_EQ(escapedText("\x1b[2J\r\n\t\x7f"), "\\x1b[2J\\r\\n\\t\\x7f");
  EXPECT_EQ(escapedText("\xef\xbb\xbftime_s"), "\\ufefftime_s");  // byte order mark
  EXPECT_EQ(escapedText("a\xe2\x80\xae"
                        "b"),
            "a\\u202eb");  // right-to-left override
  EXPECT_EQ(escapedText("\xc2\x9b"
                        "2J"),
            "\\u009b2J");  // C1 control sequence introducer
  EXPECT_EQ(escapedText("\x9b\xff\xc0\xaf\xed\xa0\x80"), "\\x9b\\xff\\xc0\\xaf\\xed\\xa0\\x80");  // not UTF-8
  EXPECT_EQ(escapedText("\xe2\x82"), "\\xe2\\x82");                                               // cut short
  EXPECT_EQ(escapedText(escapedText("\x1b")), "\\x1b");  // escaping twice changes nothing
}

TEST(MessageText, QuotesShortValuesAndMeasuresLongOnes) {
  EXPECT_EQ(quotedText("colour"), "'colour'");
  EXPECT_EQ(quotedText(std::string(40, 'x')), "'" + std::string(40, 'x') + "'");
  EXPECT_EQ(quotedText(std::string(41, 'x')), "a text of 41 characters");
  EXPECT_EQ(quotedText("two\nlines"), "a text of 9 characters");
  EXPECT_EQ(quotedText("\x1b[2J"), "'\\x1b[2J'");
  EXPECT_EQ(fieldKeyText("box"), "box");
  EXPECT_EQ(fieldKeyText(std::string(50, 'k')), "<a key of 50 characters>");
  EXPECT_EQ(fieldKeyText("a\rb"), "a\\rb");
}

TEST(MessageText, AnInputErrorIsEscapedWhole) {
  const InputError error("task\x1b].yaml", "key\r", "value\n\x1b[2J");
  EXPECT_STREQ(error.what(), "task\\x1b].yaml: key\\r: value\\n\\x1b[2J");
  EXPECT_EQ(error.file(), "task\\x1b].yaml");
  EXPECT_EQ(error.field(), "key\\r");
  EXPECT_EQ(error.message(), "value\\n\\x1b[2J");
}

}  // namespace
}  // namespace pmdplan
