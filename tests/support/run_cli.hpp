#pragma once
// Runs the real `pmdplan` binary (PMDPLAN_CLI_PATH) and captures its exit code and output.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/temp_dir.hpp"

namespace pmdplan::test {

struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

/// The source tree (viewer/, data/) and the build folder (test-output/) of the CLI tests.
inline const std::filesystem::path kSourceTree = std::filesystem::path(PMDPLAN_TEST_DATA_DIR).parent_path();
inline const std::filesystem::path kBuildDirectory = std::filesystem::path(PMDPLAN_CLI_PATH).parent_path();

inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

inline std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Output is captured in files inside `dir`.
inline CliResult runCli(const TempDir& dir, const std::string& arguments) {
  const auto out = dir.path() / "stdout.txt";
  const auto err = dir.path() / "stderr.txt";
  const std::string command = quoted(PMDPLAN_CLI_PATH) + " " + arguments + " >" + quoted(out) + " 2>" + quoted(err);
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, contents(out), contents(err)};
}

inline CliResult runCli(const std::string& arguments) {
  const TempDir dir;
  return runCli(dir, arguments);
}

/// can_on_table's path planned with seed 1, written to DIR/NAME: the input of path-file tests.
inline std::filesystem::path plannedPath(const TempDir& dir, const std::string& name = "p.path.json") {
  const auto path = dir.path() / name;
  const auto result = runCli(dir, "plan can_on_table --seed 1 -o " + quoted(path));
  EXPECT_EQ(result.exitCode, 0) << result.err;
  return path;
}

}  // namespace pmdplan::test
