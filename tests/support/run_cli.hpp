#pragma once
// Runs the real `pmdplan` binary (PMDPLAN_CLI_PATH) and captures its exit code and output.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pmdplan::test {

struct CliResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

inline CliResult runCli(const std::string& arguments) {
  const auto errFile = std::filesystem::temp_directory_path() /
                       ("pmdplan-cli-stderr-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
  const std::string command = std::string("'") + PMDPLAN_CLI_PATH + "' " + arguments + " 2>'" + errFile.string() + "'";
  CliResult result;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  std::ifstream err(errFile);
  std::ostringstream text;
  text << err.rdbuf();
  result.err = text.str();
  std::filesystem::remove(errFile);
  return result;
}

}  // namespace pmdplan::test
