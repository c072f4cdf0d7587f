// The one YAML loader: empty files, syntax errors, repeated keys at any depth and alias bombs are
// InputErrors naming the file, the line and, for a key, its field path.
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

}  // namespace
}  // namespace pmdplan
