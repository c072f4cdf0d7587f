// `pmdplan view --serve` and `pmdplan glove stream --serve`, run as the real program and asked what
// an attacker on the same machine (or a page of another site) would ask: absolute, encoded and
// overlong paths, a link loop, another Host, a client that never finishes its request. Every such
// request is refused with 4xx, no byte of a file outside the folder is served, and the program
// keeps serving (the next request answers 200, the process is alive).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <regex>
#include <thread>

#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/io/viewer/robot_mimic.hpp"
#include "pmdplan/world/task.hpp"
#include "support/http_client.hpp"
#include "support/run_cli.hpp"

namespace pmdplan {
namespace {

using namespace std::chrono_literals;
using test::contents;
using test::httpGet;
using test::httpStatus;

const std::filesystem::path kGloveSample =
    std::filesystem::path(PMDPLAN_TEST_DATA_DIR) / "glove" / "synthetic_operator_sample.csv";

/// A running pmdplan whose stdout and stderr go to files; killed when destroyed if still running.
class ServingProcess {
 public:
  ServingProcess(const test::TempDir& dir, std::vector<std::string> arguments)
      : out_(dir.path() / "serve.out"), err_(dir.path() / "serve.err") {
    arguments.insert(arguments.begin(), PMDPLAN_CLI_PATH);
    pid_ = ::fork();
    if (pid_ == 0) {
      const int outFd = ::open(out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
      const int errFd = ::open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
      ::dup2(outFd, 1);
      ::dup2(errFd, 2);
      std::vector<char*> argv;
      for (auto& argument : arguments) argv.push_back(argument.data());
      argv.push_back(nullptr);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
  }
  ~ServingProcess() {
    if (running()) stop(SIGKILL);
  }
  /// The port it prints ("http://127.0.0.1:PORT/"), 0 if none within 20 s.
  int port() const {
    const std::regex address("http://127\\.0\\.0\\.1:([0-9]+)/");
    for (const auto until = std::chrono::steady_clock::now() + 20s; std::chrono::steady_clock::now() < until;) {
      std::smatch match;
      const std::string out = contents(out_);
      if (std::regex_search(out, match, address)) return std::stoi(match[1]);
      if (!running()) return 0;
      std::this_thread::sleep_for(20ms);
    }
    return 0;
  }
  bool running() const {
    if (exited_) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == 0) return true;
    exited_ = true;
    status_ = status;
    return false;
  }
  /// Sends `signal` and returns the exit code (128 + the signal if one ended it; -1 after 5 s).
  int stop(int signal) {
    if (running()) ::kill(pid_, signal);
    for (const auto until = std::chrono::steady_clock::now() + 5s; running();) {
      if (std::chrono::steady_clock::now() > until) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
        exited_ = true;
        return -1;
      }
      std::this_thread::sleep_for(10ms);
    }
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
  }
  std::string err() const { return contents(err_); }

 private:
  std::filesystem::path out_, err_;
  pid_t pid_ = -1;
  mutable bool exited_ = false;
  mutable int status_ = 0;
};

/// The hostile requests of issue's findings; each must be refused and leave the server serving.
void expectEveryHostileRequestRefused(const ServingProcess& process, int port, const std::filesystem::path& folder) {
  std::filesystem::create_symlink("loop", folder / "loop");
  std::filesystem::create_symlink("/etc/passwd", folder / "passwd");
  const int silent = test::connectToLoopback(port);  // never finishes its request
  for (const std::string& target :
       {std::string("//etc/passwd"), std::string("/%2fetc/passwd"), std::string("/%2Fetc/passwd"),
        std::string("//proc/self/environ"), std::string("/%2e%2e/%2e%2e/etc/passwd"), "/" + std::string(256, 'a'),
        "/" + std::string(5000, 'a'), std::string("/loop"), std::string("/passwd"), std::string("/index.html%00")}) {
    const auto asked = std::chrono::steady_clock::now();
    const std::string reply = httpGet(port, target);
    const int status = httpStatus(reply);
    EXPECT_TRUE(status == 404 || status == 403 || status == 400) << target.substr(0, 40) << ": " << reply.substr(0, 40);
    EXPECT_EQ(reply.find("root:"), std::string::npos) << target.substr(0, 40);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count(), 2.0);
    ASSERT_TRUE(process.running()) << "after " << target.substr(0, 40) << ": " << process.err();
  }
  EXPECT_EQ(httpStatus(httpGet(port, "//etc/passwd")), 404);
  EXPECT_EQ(httpStatus(httpGet(port, "/%2fetc/passwd")), 404);
  const std::string rebound =
      test::httpExchange(port, "GET / HTTP/1.1\r\nHost: rebound.example:" + std::to_string(port) + "\r\n\r\n");
  EXPECT_EQ(httpStatus(rebound), 403);
  const std::string page = httpGet(port, "/");
  EXPECT_EQ(httpStatus(page), 200) << page.substr(0, 60);
  EXPECT_NE(page.find("pmdplan-viewer.js"), std::string::npos);
  ::close(silent);
  EXPECT_TRUE(process.running()) << process.err();
}

TEST(ServeCli, TheViewersServerRefusesHostileRequestsAndKeepsServing) {
  test::TempDir dir;
  const Task task = loadTaskByName("can_on_table");
  PathFile path;
  path.task = task.name;
  path.planner = "straight-line test path";
  path.jointNames = task.robot->activeJointNames();
  path.points = {task.start, task.goal};
  path.mimic = mimicRelations(*task.robot);
  writePathFile(dir.path() / "can.json", path);
  const auto folder = dir.path() / "viewer";
  ServingProcess view(dir, {"view", (dir.path() / "can.json").string(), "--out", folder.string(), "--serve", "0"});
  const int port = view.port();
  ASSERT_GT(port, 0) << view.err();
  expectEveryHostileRequestRefused(view, port, folder);
  EXPECT_EQ(view.stop(SIGTERM), 128 + SIGTERM);
}

TEST(ServeCli, TheGloveStreamsServerRefusesHostileRequestsAndTheRecordingEndsCleanly) {
  test::TempDir dir;
  const auto folder = dir.path() / "live";
  const auto recording = dir.path() / "rec.csv";
  ServingProcess stream(dir, {"glove", "stream", "--replay", kGloveSample.string(), "--speed", "0.2", "-o",
                              recording.string(), "--serve", "0", "--out", folder.string()});
  const int port = stream.port();
  ASSERT_GT(port, 0) << stream.err();
  expectEveryHostileRequestRefused(stream, port, folder);
  const int page = test::connectToLoopback(port);
  test::sendText(page, "GET /events HTTP/1.1\r\nHost: localhost:" + std::to_string(port) + "\r\n\r\n");
  EXPECT_NE(test::readReply(page, 5s, "event: posture").find("event: posture"), std::string::npos);
  ::close(page);
  EXPECT_EQ(stream.stop(SIGINT), 0) << stream.err();
  EXPECT_TRUE(std::filesystem::is_regular_file(recording));
  EXPECT_FALSE(std::filesystem::exists(recording.string() + ".partial"));
}

}  // namespace
}  // namespace pmdplan
