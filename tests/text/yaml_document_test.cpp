// The one YAML loader: empty files, syntax errors, repeated keys at any depth and alias bombs are
// InputErrors naming the file, the line and, for a key, its field path; our own files' roots
// (parseYamlFile) check their keys, format and version.
#include <gtest/gtest.h>

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
