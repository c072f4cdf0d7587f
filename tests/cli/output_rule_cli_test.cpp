// The one output rule (docs/robustness.md, "Outputs"), run as the real program: an output never
// replaces an input (the task, its robot's files, the joint limits, a path file) nor another
// output; outputs honour the umask and keep a replaced file's mode; a command's outputs are
// renamed together; long names are checked up front; the default name never comes from a file's
// contents; a FIFO never makes pmdplan wait.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

namespace fs = std::filesystem;
using test::contents;
using test::quoted;

const fs::path kOutputRuleData = PMDPLAN_TEST_DATA_DIR;

/// Runs `pmdplan ARGUMENTS` in `dir` through sh, after `setup` (say "umask 077; ulimit -f 16"),
/// killed after 20 s so that a hang fails the test instead of stopping the suite.
test::CliResult runOutputRuleCli(const test::TempDir& dir, const std::string& setup, const std::string& arguments) {
  const auto out = dir.path() / "stdout.txt";
  const auto err = dir.path() / "stderr.txt";
  const std::string script = "cd " + quoted(dir.path()) + " && trap '' XFSZ && " + setup + " && exec timeout 20 " +
                             quoted(PMDPLAN_CLI_PATH) + " " + arguments;
  const std::string command = "sh -c \"" + script + "\" >" + quoted(out) + " 2>" + quoted(err);
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, contents(out), contents(err)};
}

void expectOutputRefused(const test::CliResult& result, const std::string& option, const std::string& text) {
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find(option), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(text), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;  // one line
}

mode_t outputModeOf(const fs::path& file) {
  struct stat status {};
  EXPECT_EQ(::stat(file.c_str(), &status), 0) << file;
  return status.st_mode & 0777;
}

/// A copy of the built-in robot and a task of it, so that the test may lose nothing of the repo's.
struct OutputRuleRobotCopy {
  explicit OutputRuleRobotCopy(const test::TempDir& dir) {
    fs::copy(kOutputRuleData / "robots/sah_tx90", dir.path() / "robot", fs::copy_options::recursive);
    std::string task = contents(kOutputRuleData / "scenes/can_on_table.yaml");
    const auto robotLine = task.find("robot:");
    task.replace(robotLine, task.find('\n', robotLine) - robotLine, "robot: robot/sah_tx90.urdf");
    taskFile = dir.write("task.yaml", task);
  }
  fs::path urdf(const test::TempDir& dir) const { return dir.path() / "robot/sah_tx90.urdf"; }
  fs::path taskFile;
};

TEST(OutputRule, NoOutputReplacesAnInputOfTheCommandNorItsRobotFiles) {
  test::TempDir dir;
  const OutputRuleRobotCopy robot(dir);
  const auto urdf = robot.urdf(dir), srdf = dir.path() / "robot/sah_tx90.srdf";
  const auto limits = dir.path() / "robot/sah_tx90.joint_limits.yaml";
  const std::string task = contents(robot.taskFile), urdfText = contents(urdf), srdfText = contents(srdf),
                    limitsText = contents(limits);
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml -o out.json --trajectory task.yaml"),
                      "--trajectory", "also an input");
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml -o robot/sah_tx90.urdf"), "-o", "sah_tx90.urdf");
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml --csv robot/sah_tx90.srdf"), "--csv",
                      "also an input");
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml --trajectory robot/sah_tx90.joint_limits.yaml"),
                      "--trajectory", "also an input");
  fs::create_hard_link(urdf, dir.path() / "hard.json");  // the same file under another name
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml -o hard.json"), "-o", "also an input");
  fs::create_symlink("task.yaml", dir.path() / "link.json");
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml -o link.json"), "-o", "also an input");
  EXPECT_EQ(contents(robot.taskFile), task);
  EXPECT_EQ(contents(urdf), urdfText);
  EXPECT_EQ(contents(srdf), srdfText);
  EXPECT_EQ(contents(limits), limitsText);
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link.json"));

  ASSERT_EQ(runOutputRuleCli(dir, "true", "plan task.yaml -o p.path.json").exitCode, 0);
  const std::string path = contents(dir.path() / "p.path.json");
  expectOutputRefused(runOutputRuleCli(dir, "true", "time p.path.json -o p.path.json"), "-o", "also an input");
  expectOutputRefused(runOutputRuleCli(dir, "true", "time p.path.json --task task.yaml -o task.yaml"), "-o",
                      "also an input");
  expectOutputRefused(
      runOutputRuleCli(dir, "true",
                       "time p.path.json --task task.yaml --joint-limits robot/sah_tx90.joint_limits.yaml "
                       "-o robot/sah_tx90.joint_limits.yaml"),
      "-o", "also an input");
  // The CSV beside the trajectory: `-o task.json` would write task.csv; here the CSV is the task.
  fs::copy_file(robot.taskFile, dir.path() / "t.csv");
  expectOutputRefused(runOutputRuleCli(dir, "true", "time p.path.json --task t.csv -o t.json"), "-o (its CSV)",
                      "also an input");
  EXPECT_EQ(contents(dir.path() / "p.path.json"), path);
  EXPECT_EQ(contents(dir.path() / "t.csv"), task);

  expectOutputRefused(
      runOutputRuleCli(dir, "true", "robot init robot/sah_tx90.urdf --palm palm -o robot/sah_tx90.urdf"), "-o",
      "also an input");
  expectOutputRefused(
      runOutputRuleCli(dir, "true", "collision-pairs robot/sah_tx90.urdf --samples 10 -o robot/sah_tx90.urdf"), "-o",
      "also an input");
  EXPECT_EQ(contents(urdf), urdfText);
  // Regenerating the SRDF in place stays what collision-pairs is for.
  const auto regenerated = runOutputRuleCli(dir, "true", "collision-pairs robot/sah_tx90.urdf --samples 10");
  EXPECT_EQ(regenerated.exitCode, 0) << regenerated.err;
}

TEST(OutputRule, TwoOutputsMayNotNameOneFile) {
  test::TempDir dir;
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan can_on_table -o same --csv same"), "--csv",
                      "also the output of -o");
  expectOutputRefused(runOutputRuleCli(dir, "true", "glove synth --frames 10 -o x.csv --calibration-out x.csv"),
                      "--calibration-out", "also the output of -o");
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan can_on_table -o a.json --trajectory a.json"), "--trajectory",
                      "also the output of -o");
  expectOutputRefused(
      runOutputRuleCli(dir, "true",
                       "glove stream --replay " + quoted(kOutputRuleData / "glove/synthetic_operator_sample.csv") +
                           " --frames 3 -o rec.csv --raw-out rec.csv.partial"),
      "--raw-out", "also the output of -o (its .partial file)");
  EXPECT_FALSE(fs::exists(dir.path() / "same"));
  EXPECT_FALSE(fs::exists(dir.path() / "x.csv"));
}

TEST(OutputRule, ANewOutputHonoursTheUmaskAndAReplacedFileKeepsItsMode) {
  test::TempDir dir;
  auto result = runOutputRuleCli(dir, "umask 077", "glove synth --frames 10 -o private.csv");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(outputModeOf(dir.path() / "private.csv"), 0600u);
  EXPECT_EQ(outputModeOf(dir.path() / "private.calibration.yaml"), 0600u);
  result = runOutputRuleCli(dir, "umask 002", "glove synth --frames 10 -o shared.csv");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_EQ(outputModeOf(dir.path() / "shared.csv"), 0664u);

  const auto secret = dir.write("secret.csv", "an earlier recording\n");
  fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);
  result = runOutputRuleCli(dir, "umask 022", "glove synth --frames 10 -o secret.csv");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_NE(contents(secret).find("SYNTHETIC"), std::string::npos);
  EXPECT_EQ(outputModeOf(secret), 0600u);  // never widened to 0644
}

TEST(OutputRule, OutputsAreRenamedTogetherOnlyOnceEveryOneIsWritten) {
  test::TempDir dir;
  const auto path = dir.write("p.json", "an earlier path\n");
  const auto trajectory = dir.write("t.json", "an earlier trajectory\n");
  // A file size limit of 8 KiB: the path file (about 2 KiB) fits, the trajectory (100 KiB) does not,
  // as on a disk that fills up between the two.
  const auto result = runOutputRuleCli(dir, "ulimit -f 16", "plan can_on_table -o p.json --trajectory t.json");
  expectOutputRefused(result, "t.json", "write failed");
  EXPECT_EQ(contents(path), "an earlier path\n");
  EXPECT_EQ(contents(trajectory), "an earlier trajectory\n");
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename().string().find(".pmdplan-"), std::string::npos) << entry.path();
}

TEST(OutputRule, ALongOutputNameWorksAndATooLongOneIsRefusedBeforeTheWork) {
  test::TempDir dir;
  const std::string name240 = std::string(235, 'a') + ".json";
  auto result = runOutputRuleCli(dir, "true", "plan can_on_table -o " + name240);
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(fs::exists(dir.path() / name240));
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan can_on_table -o " + std::string(251, 'b') + ".json"), "-o",
                      "at most 255 bytes");
  // The live recording's NAME.partial must fit too.
  expectOutputRefused(
      runOutputRuleCli(dir, "true",
                       "glove stream --replay " + quoted(kOutputRuleData / "glove/synthetic_operator_sample.csv") +
                           " -o " + std::string(246, 'c') + ".csv"),
      "-o", "at most 255 bytes");
  std::string longPath;
  for (int i = 0; i < 21; ++i) longPath += std::string(200, 'd') + "/";
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan can_on_table -o " + longPath + "x.json"), "-o",
                      "shorter than 4096");
}

TEST(OutputRule, TheDefaultOutputNameComesFromTheTaskFilesNameNotItsContents) {
  test::TempDir dir;
  std::string task = contents(kOutputRuleData / "scenes/can_on_table.yaml");
  ASSERT_NE(task.find("name: can_on_table"), std::string::npos);
  dir.write("mine.yaml", task);
  const auto result = runOutputRuleCli(dir, "true", "plan mine.yaml");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(fs::exists(dir.path() / "mine.path.json"));
  EXPECT_FALSE(fs::exists(dir.path() / "can_on_table.path.json"));
  const auto builtIn = runOutputRuleCli(dir, "true", "plan can_on_table");
  ASSERT_EQ(builtIn.exitCode, 0) << builtIn.err;
  EXPECT_TRUE(fs::exists(dir.path() / "can_on_table.path.json"));
}

TEST(OutputRule, APartialRecordingIsNeverOverwrittenNorWrittenThroughALinkOrIntoAFifo) {
  test::TempDir dir;
  const std::string replay = "glove stream --replay " +
                             quoted(kOutputRuleData / "glove/synthetic_operator_sample.csv") +
                             " --speed 100 --frames 20 -o rec.csv";
  const auto earlier = dir.write("rec.csv.partial", "# an earlier recording, killed\n");
  expectOutputRefused(runOutputRuleCli(dir, "true", replay), "rec.csv.partial", "earlier recording");
  EXPECT_EQ(contents(earlier), "# an earlier recording, killed\n");
  fs::remove(earlier);

  const auto victim = dir.write("victim.txt", "someone else's file\n");
  fs::create_symlink("victim.txt", dir.path() / "rec.csv.partial");
  expectOutputRefused(runOutputRuleCli(dir, "true", replay), "rec.csv.partial", "earlier recording");
  EXPECT_EQ(contents(victim), "someone else's file\n");
  fs::remove(dir.path() / "rec.csv.partial");

  ASSERT_EQ(::mkfifo((dir.path() / "rec.csv.partial").c_str(), 0600), 0);
  const auto started = std::chrono::steady_clock::now();
  expectOutputRefused(runOutputRuleCli(dir, "true", replay), "rec.csv.partial", "earlier recording");
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(10));
}

TEST(OutputRule, ARecordingCutShortByAFullDiskEndsInAWholeRow) {
  test::TempDir dir;
  // 2 KiB: the notes, the header and a few rows fit; then a row is cut short.
  const auto result =
      runOutputRuleCli(dir, "ulimit -f 4",
                       "glove stream --replay " + quoted(kOutputRuleData / "glove/synthetic_operator_sample.csv") +
                           " --speed 100 --frames 100 -o rec.csv");
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find("rec.csv.partial"), std::string::npos) << result.err;
  const std::string kept = contents(dir.path() / "rec.csv");
  ASSERT_FALSE(kept.empty()) << result.err;
  EXPECT_EQ(kept.back(), '\n');
  std::size_t columns = std::string::npos;
  std::size_t start = 0;
  for (std::size_t end; (end = kept.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = kept.substr(start, end - start);
    if (line.rfind('#', 0) == 0) continue;
    const auto commas = static_cast<std::size_t>(std::count(line.begin(), line.end(), ','));
    if (columns == std::string::npos) columns = commas;
    EXPECT_EQ(commas, columns) << line;
  }
}

TEST(OutputRule, AFifoAsAnInputIsRefusedAtOnce) {
  test::TempDir dir;
  ASSERT_EQ(::mkfifo((dir.path() / "task.yaml").c_str(), 0600), 0);
  expectOutputRefused(runOutputRuleCli(dir, "true", "plan task.yaml -o out.json"), "task.yaml", "pipe");
  fs::create_directories(dir.path() / "journal");
  ASSERT_EQ(::mkfifo((dir.path() / "journal/rank0.jsonl").c_str(), 0600), 0);
  expectOutputRefused(runOutputRuleCli(dir, "true", "bench can_on_table --runs 1 --journal journal --report"),
                      "--journal", "rank0.jsonl");
  // A pipe with a writer (as from process substitution) is read as a file is.
  const std::string command = "cat " + quoted(kOutputRuleData / "scenes/can_on_table.yaml") + " | timeout 20 " +
                              quoted(PMDPLAN_CLI_PATH) + " plan /dev/stdin -o " + quoted(dir.path() / "piped.json") +
                              " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_TRUE(fs::exists(dir.path() / "piped.json"));
  // An endless pipe stops at the input limit.
  const auto endless = runOutputRuleCli(dir, "true", "check /dev/stdin < /dev/zero");
  EXPECT_EQ(endless.exitCode, 2) << endless.err;
  const std::string yes = "yes | timeout 20 " + quoted(PMDPLAN_CLI_PATH) + " check /dev/stdin 2>" +
                          quoted(dir.path() / "endless.txt") + " >/dev/null";
  EXPECT_EQ(WEXITSTATUS(std::system(yes.c_str())), 2);
  EXPECT_NE(contents(dir.path() / "endless.txt").find("MiB"), std::string::npos)
      << contents(dir.path() / "endless.txt");
}

}  // namespace
}  // namespace pmdplan
