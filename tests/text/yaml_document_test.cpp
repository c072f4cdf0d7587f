// The one YAML loader: empty files, syntax errors, repeated keys at any depth and alias bombs are
// InputErrors naming the file, the line and, for a key, its field path; our own files' roots
// (parseYamlFile) check their keys, format and version.
#include <gtest/gtest.h>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/text/yaml_field.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

TEST(YamlDocument, AnEmptyFileIsLineOne) {
  test::expectInputError([] { parseYamlDocument(" \n\n", "a.yaml"); }, "a.yaml", "line 1", "empty file");
}

TEST(YamlDocument, ASyntaxErrorNamesLineAndColumn) {
  test::expectInputError([] { parseYamlDocument("a: [1, 2\nb: 3\n", "a.yaml"); }, "a.yaml", "line 2, column",
                         "YAML syntax error");
}

TEST(YamlDocument, AKeyGivenTwiceAnywhereNamesItsPathAndBothLines) {
  const std::string text = "top: 1\nlist:\n  - {x: 1}\n  - x: 1\n    y: 2\n    x: 3\n";
  test::expectInputError([&] { parseYamlDocument(text, "a.yaml"); }, "a.yaml", "list[1].x (line 6)",
                         "given twice (first on line 4)");
  EXPECT_EQ(YamlField("a.yaml", parseYamlDocument("a: {b: 1, c: 2}\n", "a.yaml")).child("a", "a map").line(), 1);
}

TEST(YamlDocument, AliasesThatRepeatASubtreeTooOftenAreRefused) {
  std::string text = "a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  for (int i = 1; i <= 8; ++i)
    text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
            std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + ", *a" +
            std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + ", *a" +
            std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + ", *a" + std::to_string(i - 1) + "]\n";
  test::expectInputError([&] { parseYamlDocument(text, "a.yaml"); }, "a.yaml", "document", "through aliases");
}

TEST(YamlDocument, AnAliasInsideTheValueItNamesIsACycleRefusedAtTheAlias) {
  // Each of these made yaml-cpp build a node that contains itself: the repeated-key walk never ended.
  test::expectInputError([] { parseYamlDocument("a: &r [*r]", "a.yaml"); }, "a.yaml", "a[0] (line 1)",
                         "the alias 'r' is inside the value it names (anchor on line 1)");
  test::expectInputError([] { parseYamlDocument("a: &r {b: *r}\n", "a.yaml"); }, "a.yaml", "a.b (line 1)",
                         "a value cannot contain itself");
  test::expectInputError([] { parseYamlDocument("- &x [*x]\n", "a.yaml"); }, "a.yaml", "[0][0] (line 1)",
                         "a value cannot contain itself");
  test::expectInputError([] { parseYamlDocument("a: &m\n  *m : 1\n", "a.yaml"); }, "a.yaml", "a (line 2)",
                         "a value cannot contain itself");
  test::expectInputError([] { parseYamlDocument("a: &o\n  b: &i [1, *o]\n", "a.yaml"); }, "a.yaml", "a.b[1] (line 2)",
                         "anchor on line 1");
  // An alias after its anchor has ended is no cycle, even inside a later anchor.
  const YAML::Node fine = parseYamlDocument("a: &r [1]\nb: &s [*r, *r]\nc: [*s]\n", "a.yaml");
  EXPECT_EQ(fine["c"][0][1][0].as<int>(), 1);
}

TEST(YamlDocument, ValuesAndNestingAreCountedThroughAliases) {
  // 20 levels of pairs: 2^20 copies of the innermost list, about 3 million values: within the bound.
  std::string text = "a0: &a0 [1]\n";
  for (int i = 1; i <= 20; ++i)
    text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
            std::to_string(i - 1) + "]\n";
  EXPECT_NO_THROW(parseYamlDocument(text, "a.yaml"));
  // Three levels more: over 10^7.
  for (int i = 21; i <= 23; ++i)
    text += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
            std::to_string(i - 1) + "]\n";
  test::expectInputError([&] { parseYamlDocument(text, "a.yaml"); }, "a.yaml", "document", "more than 10000000 values");
  // 100 levels as written, repeated 30 times by aliases: 3000 levels.
  std::string deep = "l0: &l0 " + std::string(100, '[') + std::string(100, ']') + "\n";
  for (int i = 1; i <= 30; ++i)
    deep += "l" + std::to_string(i) + ": &l" + std::to_string(i) + " " + std::string(99, '[') + "*l" +
            std::to_string(i - 1) + std::string(99, ']') + "\n";
  test::expectInputError([&] { parseYamlDocument(deep, "a.yaml"); }, "a.yaml", "line", "more than 2000 levels deep");
}

TEST(YamlDocument, KeysAndValuesFromTheFileAreMeasuredWhenLongAndEscapedAlways) {
  const std::string hash = "$6$saltsalt$" + std::string(86, 'h');
  const std::string shadow = "root:" + hash + ":19000:0:99999:7:::";
  const auto parse = [](const std::string& text) {
    return parseYamlFile(text, "x.yaml", "pmdplan-x", {"format", "flag"}, "an x file");
  };
  try {
    parse(shadow + ": 1\n");
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("saltsalt"), std::string::npos) << e.what();
    EXPECT_THAT(e.what(), ::testing::HasSubstr("unknown key a text of 122 characters"));
    EXPECT_THAT(e.field(), ::testing::HasSubstr("<a key of 122 characters> (line 1)"));
  }
  try {
    parse("\"\\e[2J\\rx\": 1\n");  // ESC [ 2 J clears a terminal
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\x1b'), std::string::npos);
    EXPECT_EQ(std::string(e.what()).find('\r'), std::string::npos);
    EXPECT_THAT(e.message(), ::testing::HasSubstr("unknown key '\\x1b[2J\\rx'"));
  }
  test::expectInputError([&] { parse("flag: 1\n" + shadow + ": 2\nflag: 3\n"); }, "x.yaml", "line 3", "given twice");
}

TEST(YamlDocument, OurOwnFilesCheckTheirKeysFormatAndVersion) {
  const auto parse = [](const std::string& text) {
    return parseYamlFile(text, "x.yaml", "pmdplan-x", {"format", "version", "flag"}, "an x file");
  };
  EXPECT_TRUE(parse("format: pmdplan-x\nversion: 1\nflag: true\n").child("flag", "a flag").boolean("flag"));
  test::expectInputError([&] { parse("format: pmdplan-y\n"); }, "x.yaml", "format (line 1)", "not a pmdplan-x file");
  test::expectInputError([&] { parse("version: 2\n"); }, "x.yaml", "version (line 1)", "unsupported version '2'");
  test::expectInputError([&] { parse("- 1\n"); }, "x.yaml", "document", "expected an x file, got a list");
  test::expectInputError([&] { parse("colour: 1\n"); }, "x.yaml", "colour (line 1)", "unknown key 'colour'");
  test::expectInputError([&] { parse("flag: yes\n").child("flag", "").boolean("flag"); }, "x.yaml", "flag (line 1)",
                         "expected flag (true or false), got 'yes'");
  test::expectInputError([&] { parse("flag: 'true'\n").child("flag", "").boolean("flag"); }, "x.yaml", "flag",
                         "true or false");
}

}  // namespace
}  // namespace pmdplan
