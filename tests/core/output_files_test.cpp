// The output rule's core (core/atomic_file.hpp, core/command_files.hpp): the record of a command's
// inputs and outputs, staged outputs renamed together, the mode of new and replaced files, long
// names, and reads that never wait on a FIFO.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

namespace fs = std::filesystem;

class OutputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pmdplan-output-rule-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  static std::string read(const fs::path& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  static mode_t modeOf(const fs::path& path) {
    struct stat status {};
    EXPECT_EQ(::stat(path.c_str(), &status), 0);
    return status.st_mode & 0777;
  }
  fs::path dir_;
};

/// Sets the umask for one test and puts it back.
class ScopedUmask {
 public:
  explicit ScopedUmask(mode_t mask) : previous_(::umask(mask)) {}
  ~ScopedUmask() { ::umask(previous_); }

 private:
  mode_t previous_;
};

TEST_F(OutputFiles, AFileReadInACommandIsNeverReplacedByItsOutputsUnderAnyName) {
  const auto input = file("task.yaml", "an input\n");
  fs::create_hard_link(input, dir_ / "hard.yaml");
  fs::create_symlink("task.yaml", dir_ / "link.yaml");
  {
    const CommandFileScope scope;
    EXPECT_EQ(readTextFile(input), "an input\n");
    for (const char* name : {"task.yaml", "hard.yaml", "link.yaml"}) {
      EXPECT_THROW(checkOutputPath(dir_ / name, "-o"), InputError) << name;
      EXPECT_THROW(writeFileAtomically(dir_ / name, "lost"), InputError) << name;  // the last line of defence
    }
    EXPECT_NO_THROW(writeFileAtomically(dir_ / "other.yaml", "an output\n"));
  }
  EXPECT_EQ(read(input), "an input\n");
  // Outside a scope nothing is recorded: library code and tests write what they read.
  EXPECT_EQ(readTextFile(input), "an input\n");
  EXPECT_NO_THROW(writeFileAtomically(input, "replaced\n"));
}

TEST_F(OutputFiles, TwoOutputsOfOneCommandMayNotBeOneFile) {
  const CommandFileScope scope;
  EXPECT_NO_THROW(checkOutputPath(dir_ / "a.json", "-o"));
  EXPECT_NO_THROW(checkOutputPath(dir_ / "a.json", "-o"));                     // the same option may check again
  EXPECT_THROW(checkOutputPath(dir_ / "sub/../a.json", "--csv"), InputError);  // not there yet: by its path
  fs::create_directories(dir_ / "sub");
  EXPECT_THROW(checkOutputPath(dir_ / "sub/../a.json", "--csv"), InputError);
  writeFileAtomically(dir_ / "b.json", "first\n");
  EXPECT_THROW(writeFileAtomically(dir_ / "b.json", "second\n"), InputError);
  EXPECT_EQ(read(dir_ / "b.json"), "first\n");
  EXPECT_NO_THROW(writeFileAtomically(dir_ / "b.json", "first\n"));  // the same bytes again lose nothing
}

TEST_F(OutputFiles, AnInputTheCommandUpdatesOnPurposeMayBeReplaced) {
  const auto srdf = file("robot.srdf", "old pairs\n");
  const CommandFileScope scope;
  readTextFile(srdf);
  permitReplacingInput(srdf);
  EXPECT_NO_THROW(writeFileAtomically(srdf, "new pairs\n"));
  EXPECT_EQ(read(srdf), "new pairs\n");
}

TEST_F(OutputFiles, StagedOutputsAreRenamedTogetherOrNotAtAll) {
  const auto a = file("a.txt", "old a\n"), b = file("b.txt", "old b\n");
  {
    StagedOutputs staged;
    writeFileAtomically(a, "new a\n");
    EXPECT_EQ(read(a), "old a\n");  // written and flushed, not yet renamed
    EXPECT_THROW(writeFileAtomically(dir_ / "missing/b.txt", "x"), InputError);
  }  // no commit: the staged file is removed
  EXPECT_EQ(read(a), "old a\n");
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find(".pmdplan-"), std::string::npos) << entry.path();
  StagedOutputs staged;
  writeFileAtomically(a, "new a\n");
  writeFileAtomically(b, "new b\n");
  staged.commit();
  EXPECT_EQ(read(a), "new a\n");
  EXPECT_EQ(read(b), "new b\n");
}

TEST_F(OutputFiles, ANewFileHonoursTheUmaskAndAReplacedOneKeepsItsMode) {
  {
    const ScopedUmask mask(077);
    writeFileAtomically(dir_ / "private.txt", "x");
    EXPECT_EQ(modeOf(dir_ / "private.txt"), 0600u);
  }
  {
    const ScopedUmask mask(002);
    writeFileAtomically(dir_ / "shared.txt", "x");
    EXPECT_EQ(modeOf(dir_ / "shared.txt"), 0664u);
    const auto secret = file("secret.txt", "old");
    fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);
    writeFileAtomically(secret, "new");
    EXPECT_EQ(modeOf(secret), 0600u);
    const auto narrow = file("narrow.txt", "old");
    fs::permissions(narrow, fs::perms::owner_read | fs::perms::group_read);
    writeFileAtomically(narrow, "new");
    EXPECT_EQ(modeOf(narrow), 0440u);  // its own mode, not 0664
  }
}

TEST_F(OutputFiles, ALongNameGetsAShortTemporaryNameAndATooLongOneIsRefused) {
  const std::string longest(kMaxOutputNameBytes, 'n');
  writeFileAtomically(dir_ / longest, "fits\n");
  EXPECT_EQ(read(dir_ / longest), "fits\n");
  EXPECT_THROW(checkOutputPath(dir_ / (longest + "x"), "-o"), InputError);
  try {
    writeFileAtomically(dir_ / (longest + "x"), "x");
    ADD_FAILURE() << "a 256-byte name was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("at most 255 bytes"), std::string::npos) << error.what();
  }
  // A temporary file of a killed process is still found by the next write of the long name.
  const std::string stale = "." + longest.substr(0, kTemporaryNameBytes) + ".pmdplan-999999999-abcdef";
  file(stale, "half a file");
  writeFileAtomically(dir_ / longest, "again\n");
  EXPECT_FALSE(fs::exists(dir_ / stale));
}

TEST_F(OutputFiles, AFifoWithoutAWriterIsRefusedAtOnceAndAPipeWithOneIsRead) {
  const auto fifo = dir_ / "task.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto started = std::chrono::steady_clock::now();
  EXPECT_THROW(readTextFile(fifo), InputError);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));

  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  std::thread writer([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the reader waits for it
    EXPECT_EQ(::write(ends[1], "a: 1\n", 5), 5);
    ::close(ends[1]);
  });
  EXPECT_EQ(readTextFile("/proc/self/fd/" + std::to_string(ends[0])), "a: 1\n");
  writer.join();
  ::close(ends[0]);
  EXPECT_THROW(readTextFile("/dev/zero"), InputError);  // a device
}

}  // namespace
}  // namespace pmdplan
