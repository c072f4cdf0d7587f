// `pmdplan glove stream`, run as the real program, with a pseudo-terminal pair from socat standing
// in for the glove: the test writes 'G' replies into one end, pmdplan reads the other. The
// recordings must hold exactly what the offline path (calibrate, mapToJoints) gives for the same
// bytes; unplugging (socat killed), garbage and silence end cleanly with a message.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <functional>
#include <sstream>
#include <thread>

#include "pmdplan/glove/glove_calibration_file.hpp"
#include "pmdplan/glove/glove_csv.hpp"
#include "pmdplan/glove/glove_serial_stream.hpp"
#include "pmdplan/model/robot_model.hpp"
#include "pmdplan/synergy/hand_mapping_file.hpp"
#include "pmdplan/synergy/pmd_posture_filter.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/text/number_text.hpp"
#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using namespace std::chrono_literals;
using test::contents;
using test::quoted;

const std::filesystem::path kGloveDataDir = std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "glove";
const std::filesystem::path kSample = kGloveDataDir / "synthetic_operator_sample.csv";
const std::filesystem::path kCalibration = kGloveDataDir / "synthetic_operator_sample.calibration.yaml";

pid_t spawn(const std::vector<std::string>& arguments, const std::filesystem::path& out,
            const std::filesystem::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int outFd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int errFd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(outFd, 1);
    ::dup2(errFd, 2);
    std::vector<char*> argv;
    for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

/// The exit code, or -1 after killing a process that did not end within `limit` (never a hang).
int waitFor(pid_t pid, std::chrono::milliseconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > until) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(10ms);
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool eventually(const std::function<bool()>& condition, std::chrono::milliseconds limit = 10s) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

/// socat's two pseudo-terminals: `glove` is the test's end, `host` the one pmdplan opens.
class GloveLine {
 public:
  explicit GloveLine(const test::TempDir& dir) : glove_(dir.path() / "glove"), host_(dir.path() / "host") {
    socat_ =
        spawn({"socat", "-d", "-d", "pty,raw,echo=0,link=" + glove_.string(), "pty,raw,echo=0,link=" + host_.string()},
              dir.path() / "socat.out", dir.path() / "socat.err");
    if (!eventually([&] { return std::filesystem::exists(glove_) && std::filesystem::exists(host_); }))
      throw std::runtime_error("socat made no pseudo-terminal pair: " + contents(dir.path() / "socat.err"));
    fd_ = ::open(glove_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd_ < 0) throw std::runtime_error("cannot open " + glove_.string());
  }
  ~GloveLine() {
    unplug();
    if (fd_ >= 0) ::close(fd_);
  }
  const std::filesystem::path& host() const { return host_; }
  int fd() const { return fd_; }
  void write(const std::string& bytes) const {
    for (std::size_t sent = 0; sent < bytes.size();) {
      const ssize_t n = ::write(fd_, bytes.data() + sent, bytes.size() - sent);
      if (n < 0 && errno == EAGAIN) {
        std::this_thread::sleep_for(1ms);
        continue;
      }
      if (n <= 0) throw std::runtime_error("cannot write to the glove's end");
      sent += static_cast<std::size_t>(n);
    }
  }
  /// Writes in small pieces with pauses, so replies arrive split across reads.
  void trickle(const std::string& bytes, std::size_t piece = 7) const {
    for (std::size_t at = 0; at < bytes.size(); at += piece) {
      write(bytes.substr(at, piece));
      std::this_thread::sleep_for(1ms);
    }
  }
  void unplug() {
    if (socat_ <= 0) return;
    ::kill(socat_, SIGTERM);
    ::waitpid(socat_, nullptr, 0);
    socat_ = 0;
  }

 private:
  std::filesystem::path glove_, host_;
  pid_t socat_ = 0;
  int fd_ = -1;
};

struct Stream {
  pid_t pid;
  std::filesystem::path out, err;
  std::string stdoutText() const { return contents(out); }
  std::string stderrText() const { return contents(err); }
};

Stream startStream(const test::TempDir& dir, const std::string& arguments) {
  std::vector<std::string> argv{PMDPLAN_CLI_PATH, "glove", "stream"};
  std::istringstream words(arguments);
  for (std::string word; words >> word;) argv.push_back(word);
  Stream stream{0, dir.path() / "stream.out", dir.path() / "stream.err"};
  stream.pid = spawn(argv, stream.out, stream.err);
  return stream;
}

/// Waits until pmdplan has opened the device (bytes written before that are flushed away).
void waitUntilStreaming(const Stream& stream) {
  ASSERT_TRUE(eventually([&] { return stream.stdoutText().find("streaming from") != std::string::npos; }))
      << stream.stdoutText() << stream.stderrText();
}

GloveRecording sampleFrames(int count) {
  GloveRecording recording = readGloveCsv(kSample);
  recording.frames.resize(static_cast<std::size_t>(count));
  recording.timeS.clear();
  return recording;
}

/// The data rows of a CSV written by the stream (no '#' notes, no header), cells as text.
std::vector<std::vector<std::string>> rows(const std::filesystem::path& file) {
  std::vector<std::vector<std::string>> table;
  std::istringstream in(contents(file));
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<std::string> cells;
    std::istringstream cellStream(line);
    for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
    table.push_back(cells);
  }
  return table;
}

/// What the offline path makes of these frames: calibration, the shipped mapping, the SAH hand.
Eigen::MatrixXd offlinePostures(const GloveRecording& recording) {
  const JointLimits hand = RobotModel::loadByNameOrPath("sah_tx90").groupJoints("hand");
  return mapToJoints(calibrate(recording, loadGloveCalibration(kCalibration)),
                     loadHandMapping(defaultHandMappingPath()), hand)
      .postures;
}

void expectPostures(const std::filesystem::path& file, const Eigen::MatrixXd& expected) {
  const auto table = rows(file);
  ASSERT_EQ(static_cast<Eigen::Index>(table.size()), expected.rows());
  for (Eigen::Index f = 0; f < expected.rows(); ++f) {
    ASSERT_EQ(static_cast<Eigen::Index>(table[static_cast<std::size_t>(f)].size()), expected.cols() + 1) << "row " << f;
    for (Eigen::Index j = 0; j < expected.cols(); ++j)
      EXPECT_EQ(table[static_cast<std::size_t>(f)][static_cast<std::size_t>(j + 1)], exactNumberText(expected(f, j)))
          << "frame " << f << ", joint " << j;
  }
}

TEST(GloveStreamCli, RecordsFromAPseudoTerminalExactlyWhatTheOfflinePathGivesForTheSameBytes) {
  test::TempDir dir;
  GloveLine line(dir);
  const GloveRecording sent = sampleFrames(60);
  const auto stream =
      startStream(dir, "--device " + line.host().string() + " --poll-rate 0 --timeout 5 --frames 60 --calibration " +
                           kCalibration.string() + " -o " + (dir.path() / "rec.csv").string() + " --raw-out " +
                           (dir.path() / "raw.csv").string());
  waitUntilStreaming(stream);
  line.trickle(formatGloveSerialStream(sent));
  ASSERT_EQ(waitFor(stream.pid, 20s), 0) << stream.stderrText();
  EXPECT_THAT(stream.stdoutText(), HasSubstr("60 frames from device"));
  expectPostures(dir.path() / "rec.csv", offlinePostures(sent));
  EXPECT_EQ(readGloveCsv(dir.path() / "raw.csv").frames, sent.frames);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv.partial"));
}

TEST(GloveStreamCli, AGloveThatAnswersEachRequestIsPolledWithG) {
  test::TempDir dir;
  GloveLine line(dir);
  const GloveRecording frames = sampleFrames(15);
  const auto stream =
      startStream(dir, "--device " + line.host().string() + " --poll-rate 200 --timeout 5 --frames 15 --calibration " +
                           kCalibration.string() + " -o " + (dir.path() / "rec.csv").string());
  // The glove: one reply per 'G' it is sent.
  std::size_t answered = 0;
  const auto until = std::chrono::steady_clock::now() + 15s;
  while (answered < frames.frames.size() && std::chrono::steady_clock::now() < until) {
    char request = 0;
    if (::read(line.fd(), &request, 1) != 1) {
      std::this_thread::sleep_for(1ms);
    } else if (request == 'G') {
      GloveRecording one;
      one.frames = {frames.frames[answered++]};
      line.write(formatGloveSerialStream(one));
    }
  }
  ASSERT_EQ(waitFor(stream.pid, 10s), 0) << stream.stderrText();
  EXPECT_THAT(stream.stdoutText(), HasSubstr("polled with 'G' at 200 Hz"));
  expectPostures(dir.path() / "rec.csv", offlinePostures(frames));
}

TEST(GloveStreamCli, UnpluggingMidStreamEndsCleanlyWithAMessageAndKeepsTheRecording) {
  test::TempDir dir;
  GloveLine line(dir);
  const GloveRecording sent = sampleFrames(20);
  const auto output = dir.path() / "rec.csv";
  const auto stream =
      startStream(dir, "--device " + line.host().string() + " --poll-rate 0 --timeout 30 --calibration " +
                           kCalibration.string() + " -o " + output.string());
  waitUntilStreaming(stream);
  line.trickle(formatGloveSerialStream(sent));
  ASSERT_TRUE(eventually([&] { return rows(dir.path() / "rec.csv.partial").size() == 20; })) << stream.stderrText();
  line.unplug();
  EXPECT_EQ(waitFor(stream.pid, 10s), 2);
  const std::string err = stream.stderrText();
  EXPECT_THAT(err, HasSubstr(line.host().string()));
  EXPECT_THAT(err, HasSubstr("the glove's device closed"));
  EXPECT_THAT(err, HasSubstr("after 20 frames"));
  EXPECT_THAT(err, HasSubstr("20 frames kept in " + output.string()));
  EXPECT_THAT(err, Not(HasSubstr("internal error")));
  expectPostures(output, offlinePostures(sent));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv.partial"));
}

TEST(GloveStreamCli, GarbageBetweenRepliesIsSkippedAndTheStreamResynchronises) {
  test::TempDir dir;
  GloveLine line(dir);
  const GloveRecording sent = sampleFrames(6);
  const std::string replies = formatGloveSerialStream(sent);
  constexpr std::size_t reply = kGloveSerialReplyBytes;
  // Noise first, a reply cut short, a lone 'G', a zero where a reading should be.
  std::string bytes = std::string("\x55\x13junk", 6) + replies.substr(0, reply);
  bytes += replies.substr(reply, 11) + replies.substr(2 * reply, reply);
  bytes += "G" + replies.substr(3 * reply, reply);
  std::string zeroed = replies.substr(4 * reply, reply);
  zeroed[5] = '\0';
  bytes += zeroed + replies.substr(4 * reply, 2 * reply);
  const auto stream =
      startStream(dir, "--device " + line.host().string() + " --poll-rate 0 --timeout 5 --frames 5 --calibration " +
                           kCalibration.string() + " --raw-out " + (dir.path() / "raw.csv").string());
  waitUntilStreaming(stream);
  line.trickle(bytes, 5);
  ASSERT_EQ(waitFor(stream.pid, 10s), 0) << stream.stderrText();
  const std::vector<GloveFrame> expected{sent.frames[0], sent.frames[2], sent.frames[3], sent.frames[4],
                                         sent.frames[5]};
  EXPECT_EQ(readGloveCsv(dir.path() / "raw.csv").frames, expected);
  EXPECT_THAT(stream.stdoutText(), HasSubstr("skipped "));
}

TEST(GloveStreamCli, BytesThatHoldNoReplyAreAClearErrorNamingTheDevice) {
  test::TempDir dir;
  GloveLine line(dir);
  const auto stream =
      startStream(dir, "--device " + line.host().string() + " --poll-rate 0 --timeout 5 --calibration " +
                           kCalibration.string() + " -o " + (dir.path() / "rec.csv").string());
  waitUntilStreaming(stream);
  line.trickle(std::string(400, '\x55'), 50);
  EXPECT_EQ(waitFor(stream.pid, 10s), 2);
  const std::string err = stream.stderrText();
  EXPECT_THAT(err, HasSubstr(line.host().string()));
  EXPECT_THAT(err, HasSubstr("hold no valid 'G' reply"));
  EXPECT_THAT(err, HasSubstr("--baud"));
  EXPECT_THAT(err, HasSubstr("rec.csv not written"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv.partial"));
}

TEST(GloveStreamCli, AGloveThatNeverSendsTimesOutWithAMessage) {
  test::TempDir dir;
  GloveLine line(dir);
  const auto stream = startStream(dir, "--device " + line.host().string() + " --timeout 0.5 --calibration " +
                                           kCalibration.string() + " -o " + (dir.path() / "rec.csv").string());
  EXPECT_EQ(waitFor(stream.pid, 10s), 2);
  EXPECT_THAT(stream.stderrText(), HasSubstr("no 'G' reply in the first 0.5 s of the stream"));
  EXPECT_THAT(stream.stderrText(), HasSubstr(line.host().string()));
}

TEST(GloveStreamCli, ANonTerminalDeviceAndAMissingCalibrationAreInputErrors) {
  test::TempDir dir;
  const auto file = dir.write("plain.bin", "G");
  auto result = test::runCli(dir, "glove stream --device " + quoted(file) + " --calibration " + quoted(kCalibration) +
                                      " -o " + quoted(dir.path() / "rec.csv"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("not a serial device"));
  EXPECT_THAT(result.err, HasSubstr("--replay"));
  result = test::runCli(dir, "glove stream --device /dev/null -o " + quoted(dir.path() / "rec.csv"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("--calibration"));
  result = test::runCli(dir, "glove stream --replay " + quoted(kSample));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("nothing to do"));
  result = test::runCli(dir, "glove stream --replay " + quoted(kSample) + " -o " + quoted(dir.path() / "a.csv") +
                                 " --raw-out " + quoted(dir.path() / "a.csv"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("must be two files"));
  result = test::runCli(dir, "glove stream --replay " + quoted(kSample) + " -o " + quoted(kSample));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("-o"));
  EXPECT_EQ(contents(kSample).rfind("# SYNTHETIC", 0), 0u);  // the input is untouched
}

TEST(GloveStreamCli, AReplayPlaysAtItsRecordedRateAndCanBeFilteredOntoThePmds) {
  test::TempDir dir;
  const auto started = std::chrono::steady_clock::now();
  auto result = test::runCli(
      dir, "glove stream --replay " + quoted(kSample) + " --frames 30 -o " + quoted(dir.path() / "rec.csv"));
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_GE(elapsed, 0.29);  // frame 30 is recorded at 0.29 s: a replay does not run ahead of its recording
  GloveRecording recording = readGloveCsv(kSample);
  recording.frames.resize(30);
  const Eigen::MatrixXd plain = offlinePostures(recording);
  expectPostures(dir.path() / "rec.csv", plain);
  EXPECT_EQ(rows(dir.path() / "rec.csv")[29][0], "0.29");

  result = test::runCli(dir, "glove stream --replay " + quoted(kSample) +
                                 " --speed 100 --frames 30 --project-pmds 2 -o " + quoted(dir.path() / "filtered.csv"));
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto modelFile = defaultSynergyModelPath("sah_tx90");
  const PmdPostureFilter filter(loadSynergyModel(modelFile),
                                RobotModel::loadByNameOrPath("sah_tx90").groupJoints("hand"), 2, modelFile.string(),
                                "--project-pmds");
  Eigen::MatrixXd filtered = plain;
  for (Eigen::Index f = 0; f < plain.rows(); ++f) filtered.row(f) = filter.filter(plain.row(f).transpose()).transpose();
  expectPostures(dir.path() / "filtered.csv", filtered);
  EXPECT_GT((filtered - plain).cwiseAbs().maxCoeff(), 1e-3);  // two PMDs do not hold the whole posture
  EXPECT_THAT(contents(dir.path() / "filtered.csv"), HasSubstr("first 2 PMDs of sah_tx90_default.yaml"));

  result = test::runCli(
      dir, "glove stream --replay " + quoted(kSample) + " --project-pmds 99 -o " + quoted(dir.path() / "x.csv"));
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_THAT(result.err, HasSubstr("--project-pmds"));
}

TEST(GloveStreamCli, CtrlCEndsAReplayCleanlyAndRenamesTheRecordingIntoPlace) {
  test::TempDir dir;
  const auto output = dir.path() / "rec.csv";
  const auto stream = startStream(dir, "--replay " + kSample.string() + " --speed 0.2 -o " + output.string());
  ASSERT_TRUE(eventually([&] { return rows(dir.path() / "rec.csv.partial").size() >= 3; })) << stream.stderrText();
  ::kill(stream.pid, SIGINT);
  ASSERT_EQ(waitFor(stream.pid, 5s), 0) << stream.stderrText();
  EXPECT_THAT(stream.stdoutText(), HasSubstr("stopped by signal 2"));
  const auto table = rows(output);
  EXPECT_GE(table.size(), 3u);
  EXPECT_LT(table.size(), 200u);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "rec.csv.partial"));
}

}  // namespace
}  // namespace pmdplan
