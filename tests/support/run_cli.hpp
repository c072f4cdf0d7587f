#pragma once
// Runs the real `pmdplan` binary (PMDPLAN_CLI_PATH) and captures its exit code and output.
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

}  // namespace pmdplan::test
