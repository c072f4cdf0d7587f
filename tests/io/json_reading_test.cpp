// The JSON readers (path and trajectory files): a key given twice in one object is refused naming
// it and its path, and no message shows the file's contents (a long key is measured, escapes are
// shown escaped, nlohmann's "last read: '...'" is left out).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/files/trajectory_file.hpp"
#include "support/input_error_matchers.hpp"

namespace pmdplan {
namespace {

using ::testing::HasSubstr;

/// A valid path file of one joint and two points, as pmdplan writes it.
std::string pathText() {
  PathFile path;
  path.task = "t";
  path.planner = "pmd";
  path.jointNames = {"a"};
  path.points = {Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1)};
  return formatPathFile(path, {});
}

/// `text` with `insert` after the `n`th (0-based) `after`, and after the next `until` if given.
std::string withInserted(std::string text, const std::string& after, const std::string& insert, int n = 0,
                         const std::string& until = "") {
  std::size_t at = text.find(after);
  for (int i = 0; i < n; ++i) at = text.find(after, at + 1);
  at += after.size();
  if (!until.empty()) at = text.find(until, at) + until.size();
  text.insert(at, insert);
  return text;
}

const std::string kSecret = "root:$6$saltsalt$" + std::string(86, 'h') + ":19000:0:99999:7:::";

TEST(JsonReading, AKeyGivenTwiceIsRefusedNamingItsPath) {
  const std::string path = pathText();
  test::expectInputError([&] { parsePathFile(withInserted(path, "{", R"("task": "other", )"), "p.json"); }, "p.json",
                         "task", "given twice in one object");
  for (const int point : {0, 1})
    test::expectInputError(
        [&] { parsePathFile(withInserted(path, R"("positions")", R"(, "positions": [5])", point, "]"), "p.json"); },
        "p.json", "points[" + std::to_string(point) + "].positions", "given twice");
  // Equal keys in different objects are fine.
  EXPECT_EQ(parsePathFile(path, "p.json").points.size(), 2u);
}

TEST(JsonReading, AKeyFromTheFileIsMeasuredOrEscapedNeverShownRaw) {
  try {
    parsePathFile(withInserted(pathText(), "{", "\"" + kSecret + "\": 1, "), "p.json");
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("saltsalt"), std::string::npos) << error.what();
    EXPECT_EQ(error.field(), "<a key of 122 characters>");
  }
  test::expectInputError([] { parsePathFile(withInserted(pathText(), "{", R"("\u001b[2J": 1, )"), "p.json"); },
                         "p.json", "\\x1b[2J", "unknown key");
  test::expectInputError(
      [] { parsePathFile(withInserted(pathText(), R"("mimic": {)", R"("\u001b[2J": 1)"), "p.json"); }, "p.json",
      "mimic.\\x1b[2J", "expected an array");
}

TEST(JsonReading, ASyntaxErrorNamesItsPlaceNotTheTextThere) {
  try {
    parsePathFile(kSecret + "\n", "p.json");
    ADD_FAILURE() << "not JSON was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("root"), std::string::npos) << error.what();
    EXPECT_THAT(error.message(), HasSubstr("not valid JSON ("));
    EXPECT_THAT(error.message(), HasSubstr("line 1, column 1"));
  }
  try {
    parsePathFile("[1e999" + std::string(100, '9') + "]", "p.json");
    ADD_FAILURE() << "an overflowing number was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).find("999"), std::string::npos) << error.what();
    EXPECT_THAT(error.message(), HasSubstr("a number is out of range"));
  }
}

TEST(JsonReading, ATrajectoryFileWithARepeatedKeyIsRefused) {
  test::expectInputError(
      [] { parseTrajectoryFile(R"({"format": "pmdplan-joint-trajectory", "format": "x", "version": 1})", "t.json"); },
      "t.json", "format", "given twice");
}

}  // namespace
}  // namespace pmdplan
