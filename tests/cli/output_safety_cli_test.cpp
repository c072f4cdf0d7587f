// Outputs: a bad output path is exit 2 before any file is replaced; an output never overwrites an
// input; symbolic links are written through, devices refused; a failed write (a full disk, a file
// size limit) is exit 2 naming the path and leaves no temporary file.
#include <gtest/gtest.h>
#include <sys/stat.h>

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
using test::runCli;

void expectExitTwoNaming(const test::CliResult& result, const std::string& text) {
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find(text), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
}

/// Hidden temporary files (".NAME.pmdplan-…") left in `dir`.
int temporaries(const fs::path& dir) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".pmdplan-") != std::string::npos) ++count;
  return count;
}

TEST(OutputSafety, AnOutputInAMissingFolderIsBadInputAndReplacesNothing) {
  test::TempDir dir;
  const auto good = dir.write("good.json", "an earlier result\n");
  auto result = runCli(dir, "plan can_on_table -o " + quoted(good) + " --csv " + quoted(dir.path() / "nodir/x.csv"));
  expectExitTwoNaming(result, "nodir");
  EXPECT_EQ(contents(good), "an earlier result\n");

  const auto recording = dir.write("rec.csv", "an earlier recording\n");
  result = runCli(dir, "glove synth --frames 10 -o " + quoted(recording) + " --calibration-out " +
                           quoted(dir.path() / "nodir/c.yaml"));
  expectExitTwoNaming(result, "nodir");
  EXPECT_EQ(contents(recording), "an earlier recording\n");
  expectExitTwoNaming(runCli(dir, "glove synth --frames 10 -o " + quoted(dir.path() / "nodir/x.csv")), "nodir");

  const auto model = dir.write("m.yaml", "an earlier model\n");
  const auto notAFolder = dir.write("plots", "a file where the plots folder should be\n");
  result =
      runCli(dir, "synergies --show " + quoted(fs::path(PMDPLAN_TEST_DATA_DIR) / "synergies/sah_tx90_default.yaml") +
                      " --plots " + quoted(notAFolder / "sub"));
  expectExitTwoNaming(result, "--plots");
  const auto xml = dir.write("e.xml",
                             "<EigenGrasps dimensions=\"1\">\n<EG><EigenValue value=\"1\"/><DimVals d0=\"1\"/></EG>\n"
                             "<ORIGIN><EigenValue value=\"0\"/><DimVals d0=\"0\"/></ORIGIN>\n</EigenGrasps>\n");
  result = runCli(dir, "synergies --from-graspit " + quoted(xml) + " --joints index_proximal -o " +
                           quoted(dir.path() / "nodir/m.yaml"));
  expectExitTwoNaming(result, "nodir");
  EXPECT_EQ(contents(model), "an earlier model\n");
  EXPECT_EQ(temporaries(dir.path()), 0);
}

TEST(OutputSafety, AnOutputMayNotBeAnInput) {
  test::TempDir dir;
  const std::string task = contents(fs::path(PMDPLAN_TEST_DATA_DIR) / "scenes/can_on_table.yaml");
  const auto taskFile = dir.write("task.yaml", task);
  expectExitTwoNaming(runCli(dir, "plan " + quoted(taskFile) + " -o " + quoted(taskFile)), "also an input");
  EXPECT_EQ(contents(taskFile), task);
  const auto recording = fs::path(PMDPLAN_TEST_DATA_DIR) / "glove/synthetic_operator_sample.csv";
  const auto copy = dir.path() / "rec.csv";
  fs::copy_file(recording, copy);
  expectExitTwoNaming(runCli(dir, "glove convert " + quoted(copy) + " -o " + quoted(copy)), "also an input");
  EXPECT_EQ(contents(copy), contents(recording));
}

TEST(OutputSafety, ASymbolicLinkIsWrittenThroughAndADeviceIsRefused) {
  test::TempDir dir;
  const auto real = dir.write("real.csv", "old\n");
  fs::create_symlink("real.csv", dir.path() / "link.csv");
  const auto result = runCli(dir, "glove synth --frames 10 -o " + quoted(dir.path() / "link.csv") +
                                      " --calibration-out " + quoted(dir.path() / "c.yaml"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link.csv"));
  EXPECT_NE(contents(real).find("SYNTHETIC"), std::string::npos);

  const auto deviceLink = dir.path() / "null.csv";
  fs::create_symlink("/dev/null", deviceLink);
  expectExitTwoNaming(runCli(dir, "glove synth --frames 10 -o " + quoted(deviceLink) + " --calibration-out " +
                                      quoted(dir.path() / "c2.yaml")),
                      "not a regular file");
  struct stat device {};
  ASSERT_EQ(::stat("/dev/null", &device), 0);
  EXPECT_TRUE(S_ISCHR(device.st_mode));
  expectExitTwoNaming(runCli(dir, "plan can_on_table -o /dev/full"), "not a regular file");
}

TEST(OutputSafety, AFailedWriteIsBadInputNamingThePathAndLeavesNoTemporaryFile) {
  test::TempDir dir;
  const auto output = dir.write("rec.csv", "an earlier recording\n");
  // A file size limit of 8 KiB (with SIGXFSZ ignored, a longer write fails with EFBIG), as a full
  // disk would make it fail with ENOSPC.
  const auto err = dir.path() / "stderr.txt";
  const std::string command = "sh -c \"trap '' XFSZ; ulimit -f 16; exec " + quoted(PMDPLAN_CLI_PATH) +
                              " glove synth --frames 2000 -o " + quoted(output) + " >/dev/null 2>" + quoted(err) + "\"";
  const int status = std::system(command.c_str());
  const test::CliResult result{WIFEXITED(status) ? WEXITSTATUS(status) : -1, "", contents(err)};
  expectExitTwoNaming(result, output.string());
  EXPECT_NE(result.err.find("write failed"), std::string::npos) << result.err;
  EXPECT_EQ(contents(output), "an earlier recording\n");
  EXPECT_EQ(temporaries(dir.path()), 0);
}

}  // namespace
}  // namespace pmdplan
