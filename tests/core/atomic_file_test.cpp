#include "pmdplan/core/atomic_file.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pmdplan-atomic-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  int temporaries() const {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().filename().string().find(".pmdplan-") != std::string::npos) ++count;
    return count;
  }
  fs::path dir_;
};

TEST_F(AtomicFile, ATemporaryFileOfAKilledProcessIsRemovedByTheNextWrite) {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);  // a process id that no longer runs
  const fs::path stale = dir_ / (".out.txt.pmdplan-" + std::to_string(child) + "-abcdef");
  std::ofstream(stale) << "half a file";
  const fs::path mine = dir_ / (".out.txt.pmdplan-" + std::to_string(::getpid()) + "-abcdef");
  std::ofstream(mine) << "a write of this process in progress";
  writeFileAtomically(dir_ / "out.txt", "done\n");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(mine));
}

TEST_F(AtomicFile, ATerminatedWriteLeavesNeitherTheFileNorItsTemporary) {
  // The child writes 256 MiB; the parent sends SIGTERM as soon as the temporary file appears.
  bool caught = false;
  for (int attempt = 0; attempt < 5 && !caught; ++attempt) {
    const pid_t child = ::fork();
    if (child == 0) {
      writeFileAtomically(dir_ / "big.bin", std::string(std::size_t{256} << 20, 'x'));
      ::_exit(0);
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (temporaries() == 0 && std::chrono::steady_clock::now() < until && !fs::exists(dir_ / "big.bin"))
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    ::kill(child, SIGTERM);
    int status = 0;
    ::waitpid(child, &status, 0);
    caught = WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM;
    if (caught) {
      EXPECT_EQ(temporaries(), 0);
      EXPECT_FALSE(fs::exists(dir_ / "big.bin"));
    }
    fs::remove(dir_ / "big.bin");
  }
  EXPECT_TRUE(caught) << "the write finished before the signal in every attempt";
}

TEST_F(AtomicFile, PathsThatCannotBeWrittenAreInputErrors) {
  EXPECT_THROW(writeFileAtomically(dir_ / "missing" / "x.txt", "x"), InputError);
  EXPECT_THROW(writeFileAtomically("/dev/null", "x"), InputError);
  EXPECT_THROW(writeFileAtomically(dir_, "x"), InputError);
  const fs::path input = dir_ / "in.txt";
  std::ofstream(input) << "input";
  EXPECT_THROW(checkOutputPath(input, "-o", {input}), InputError);
  EXPECT_NO_THROW(checkOutputPath(dir_ / "other.txt", "-o", {input}));
  EXPECT_THROW(readTextFile("/dev/zero"), InputError);
  EXPECT_THROW(readTextFile(dir_), InputError);
}

}  // namespace
}  // namespace pmdplan
