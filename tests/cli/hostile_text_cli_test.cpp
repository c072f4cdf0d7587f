// The text readers against hostile files, through the real binary: a YAML alias inside the value
// it names (an 11-byte file that made every YAML reader walk for ever), file contents in messages
// (a line of /etc/shadow as a key, column or first line, a terminal escape sequence) and a folder
// where a bench journal keeps its files. Each ends in exit 2 with one line naming the file, quickly.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

// A namespace of its own: the unity build puts several test files in one translation unit.
namespace pmdplan::hostile_text_test {
namespace {

using test::quoted;

const std::filesystem::path kData = PMDPLAN_TEST_DATA_DIR;
const std::string kHash = "$6$saltsalt$" + std::string(86, 'h');
const std::string kShadowLine = "root:" + kHash + ":19000:0:99999:7:::";

/// Runs `arguments` (killed after 20 s: a hang fails instead of stalling the suite) and expects
/// exit 2 within 10 s, one line on stderr naming every `expected` text and never the hash.
void expectBadInput(const test::TempDir& dir, const std::string& arguments, const std::vector<std::string>& expected) {
  const auto out = dir.path() / "stdout.txt", err = dir.path() / "stderr.txt";
  const std::string command = "timeout -s KILL 20 " + quoted(PMDPLAN_CLI_PATH) + " " + arguments + " >" + quoted(out) +
                              " 2>" + quoted(err) + " </dev/null";
  const auto began = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  const std::string message = test::contents(err);
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << arguments << "\n" << message;
  EXPECT_EQ(message.rfind("pmdplan: error: ", 0), 0u) << arguments << "\n" << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << arguments << "\n" << message;
  EXPECT_EQ(message.find("saltsalt"), std::string::npos) << arguments << "\n" << message;
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << arguments << "\n" << message;
  for (const auto& text : expected) EXPECT_NE(message.find(text), std::string::npos) << arguments << "\n" << message;
  EXPECT_LT(seconds, 10.0) << arguments;
}

/// A two-joint robot with groups, beside `robot.joint_limits.yaml` if given, and a task using it.
std::filesystem::path writeOwnRobotTask(const test::TempDir& dir) {
  dir.write("robot.urdf",
            "<robot name=\"r\"><link name=\"base\"/><link name=\"upper\"/><link name=\"tip\"/>"
            "<joint name=\"a\" type=\"revolute\"><parent link=\"base\"/><child link=\"upper\"/><axis xyz=\"0 0 1\"/>"
            "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"
            "<joint name=\"b\" type=\"revolute\"><parent link=\"upper\"/><child link=\"tip\"/><axis xyz=\"0 1 0\"/>"
            "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint></robot>\n");
  dir.write("robot.srdf",
            "<robot name=\"r\"><group name=\"arm\"><joint name=\"a\"/></group><group name=\"hand\"><joint "
            "name=\"b\"/></group><end_effector name=\"e\" parent_link=\"upper\" group=\"hand\"/></robot>\n");
  return dir.write("task.yaml",
                   "name: t\nrobot: robot.urdf\nbase: {xyz: [0, 0, 0], rpy_deg: [0, 0, 0]}\n"
                   "obstacles: []\nstart: {joints: {a: 0, b: 0}}\ngoal: {joints: {a: 0.5, b: 0.5}}\n");
}

// `a: &r [*r]` made yaml-cpp build a list that holds itself; every YAML reader walked it for ever.
TEST(HostileText, AnAliasInsideItsOwnValueIsRefusedByEveryYamlReader) {
  test::TempDir dir;
  const std::string cycle = "a: &r [*r]\n";
  const std::vector<std::string> expected = {"a[0] (line 1)", "a value cannot contain itself"};
  const auto task = dir.write("cycle_task.yaml", cycle);
  expectBadInput(dir, "plan " + quoted(task), {"cycle_task.yaml", expected[0], expected[1]});
  const auto calibration = dir.write("cycle.calibration.yaml", cycle);
  expectBadInput(
      dir,
      "synergies " + quoted(kData / "glove/synthetic_operator_sample.csv") + " --calibration " + quoted(calibration),
      {"cycle.calibration.yaml", expected[1]});
  const auto mapping = dir.write("cycle_mapping.yaml", cycle);
  expectBadInput(dir, "glove synth --frames 10 -o " + quoted(dir.path() / "x.csv") + " --mapping " + quoted(mapping),
                 {"cycle_mapping.yaml", expected[1]});
  const auto model = dir.write("cycle_model.yaml", "format: &f {m: *f}\n");
  expectBadInput(dir, "synergies --show " + quoted(model), {"cycle_model.yaml", "format.m (line 1)", expected[1]});
  const auto ownTask = writeOwnRobotTask(dir);
  dir.write("robot.joint_limits.yaml", "- &x [*x]\n");
  expectBadInput(dir,
                 "plan " + quoted(ownTask) + " --planner full -o " + quoted(dir.path() / "p.json") + " --trajectory",
                 {"robot.joint_limits.yaml", "[0][0] (line 1)", expected[1]});
}

// A line of /etc/shadow read as a file: the message measures it, never shows it.
TEST(HostileText, AFileLineIsNeverQuotedInAMessage) {
  test::TempDir dir;
  const auto task = dir.write("shadow_task.yaml", kShadowLine + ": 1\nname: t\n");
  expectBadInput(dir, "plan " + quoted(task), {"shadow_task.yaml", "<a key of 122 characters>", "a text of 122"});
  const auto calibration = dir.write("shadow.calibration.yaml", kShadowLine + ": 1\n");
  expectBadInput(
      dir,
      "synergies " + quoted(kData / "glove/synthetic_operator_sample.csv") + " --calibration " + quoted(calibration),
      {"shadow.calibration.yaml", "a text of 122 characters"});
  const auto recording = dir.write("shadow.csv", kShadowLine + "\n1,2\n");
  expectBadInput(dir, "glove convert " + quoted(recording) + " -o " + quoted(dir.path() / "x.bin"),
                 {"shadow.csv", "line 1, column 1", "unknown column a text of"});
  expectBadInput(dir, "synergies --postures " + quoted(recording), {"shadow.csv", "header column a text of"});
  const auto path = dir.write("shadow.json", "{\"" + kShadowLine + "\": 1}\n");
  expectBadInput(dir, "validate can_on_table " + quoted(path), {"shadow.json", "<a key of 122 characters>"});
  dir.write("journal/rank0.jsonl", kShadowLine + "\n");
  expectBadInput(dir, "bench can_on_table --planners pmd --runs 1 --journal " + quoted(dir.path() / "journal"),
                 {"rank0.jsonl", "its first line is a text of 122 characters"});
}

// ESC [ 2 J clears the terminal the message is printed on: it is shown escaped.
TEST(HostileText, ATerminalEscapeInAKeyIsShownEscaped) {
  test::TempDir dir;
  const auto task = dir.write("escape_task.yaml", "\"\\e[2J\": 1\n");
  expectBadInput(dir, "plan " + quoted(task), {"escape_task.yaml", "\\x1b[2J (line 1)", "unknown key '\\x1b[2J'"});
  const auto recording = dir.write("escape.csv", "\x1b[2J\n1\n");
  expectBadInput(dir, "glove convert " + quoted(recording) + " -o " + quoted(dir.path() / "x.bin"),
                 {"escape.csv", "unknown column '\\x1b[2J'"});
}

// A folder named like a rank's journal file was exit 3 (std::filesystem's file_size threw).
TEST(HostileText, AFolderInsideAJournalNamedLikeARankFileIsBadInput) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "journal" / "rank0.jsonl");
  expectBadInput(dir, "bench can_on_table --planners pmd --runs 1 --journal " + quoted(dir.path() / "journal"),
                 {"rank0.jsonl", "--journal", "is not a regular file"});
}

}  // namespace
}  // namespace pmdplan::hostile_text_test
