// Concurrency and deadlines of the loopback servers (loopback_server.hpp), through StaticFileServer:
// a client that trickles its request, one that never reads its answer, more clients than the cap,
// accept() out of descriptors, and stopping with clients connected. None may stall anyone else.
#include "pmdplan/io/servers/loopback_server.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <thread>
#include <vector>

#include "pmdplan/io/servers/static_file_server.hpp"
#include "support/http_client.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using test::connectToLoopback;
using test::httpGet;
using test::httpStatus;
using test::readReply;
using test::sendText;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string requestFor(int port, const std::string& target) {
  return "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n";
}

bool eventually(const std::function<bool()>& condition, std::chrono::milliseconds limit = 3s) {
  const auto until = Clock::now() + limit;
  while (!condition()) {
    if (Clock::now() > until) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

// The finding: one client sending a byte every 2 s made everyone else wait (one thread, and a
// receive timeout per byte rather than for the whole head).
TEST(LoopbackServer, AClientTricklingItsRequestNeitherDelaysOthersNorOutlastsTheHeadDeadline) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  ServerLimits limits;
  limits.headDeadline = 1500ms;
  StaticFileServer server(dir.path(), 0, limits);
  const int slow = connectToLoopback(server.port());
  const auto started = Clock::now();
  std::thread trickling([&] {
    for (const char c : requestFor(server.port(), "/index.html")) {
      if (!sendText(slow, std::string(1, c))) return;
      std::this_thread::sleep_for(400ms);
    }
  });
  std::this_thread::sleep_for(300ms);
  const auto asked = Clock::now();
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/index.html")), 200);
  EXPECT_LT(secondsSince(asked), 1.0) << "another client waited for the slow one";
  const std::string reply = readReply(slow, 4s);
  EXPECT_EQ(httpStatus(reply), 408) << reply;
  EXPECT_LT(secondsSince(started), 2.5) << "the head deadline is for the whole head, not per byte";
  ::shutdown(slow, SHUT_RDWR);
  trickling.join();
  ::close(slow);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/")), 200);
}

// The finding: a client that asked for a large file and never read made everyone else wait.
TEST(LoopbackServer, AClientThatNeverReadsDoesNotDelayOthersAndIsCutOffAtTheSendDeadline) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  dir.write("big.bin", std::string(16 << 20, 'x'));
  ServerLimits limits;
  limits.sendDeadline = 1000ms;
  StaticFileServer server(dir.path(), 0, limits);
  std::vector<int> stuck;
  for (int i = 0; i < 3; ++i) {
    const int client = connectToLoopback(server.port());
    const int small = 4096;
    ::setsockopt(client, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    sendText(client, requestFor(server.port(), "/big.bin"));
    stuck.push_back(client);
  }
  ASSERT_TRUE(eventually([&] { return server.activeConnections() == 3; }));
  const auto asked = Clock::now();
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/index.html")), 200);
  EXPECT_LT(secondsSince(asked), 1.0);
  EXPECT_TRUE(eventually([&] { return server.activeConnections() == 0; }, 3s)) << "the send deadline cut no one off";
  for (const int client : stuck) ::close(client);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/")), 200);
}

TEST(LoopbackServer, ConnectionsBeyondTheCapAreAnswered503AndServingResumes) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  ServerLimits limits;
  limits.maxConnections = 4;
  StaticFileServer server(dir.path(), 0, limits);
  std::vector<int> silent;
  for (int i = 0; i < 4; ++i) silent.push_back(connectToLoopback(server.port()));
  ASSERT_TRUE(eventually([&] { return server.activeConnections() == 4; }));
  const int extra = connectToLoopback(server.port());
  const auto asked = Clock::now();
  const std::string reply = readReply(extra, 3s);
  EXPECT_EQ(httpStatus(reply), 503) << reply;
  EXPECT_LT(secondsSince(asked), 1.0);
  ::close(extra);
  for (const int client : silent) ::close(client);
  ASSERT_TRUE(eventually([&] { return server.activeConnections() == 0; }));
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/")), 200);
}

TEST(LoopbackServer, HeadsItCannotUseAreAnsweredAndTheServerGoesOn) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  StaticFileServer server(dir.path(), 0);
  const int port = server.port();
  EXPECT_EQ(httpStatus(test::httpExchange(port, "GET / HTTP/1.1\r\nHost: localhost\r\nX: " + std::string(20000, 'y'))),
            431);
  const int halfClosed = connectToLoopback(port);
  sendText(halfClosed, "GET / HTTP/1.1\r\n");
  ::shutdown(halfClosed, SHUT_WR);
  EXPECT_EQ(httpStatus(readReply(halfClosed)), 400);
  ::close(halfClosed);
  EXPECT_EQ(httpStatus(test::httpExchange(port, std::string("\0\xff\r\n\r\n", 6))), 400);
  EXPECT_EQ(httpStatus(test::httpExchange(port, "GET\r\n\r\n")), 400);
  const int gone = connectToLoopback(port);  // connects and goes without a word
  ::close(gone);
  EXPECT_EQ(httpStatus(httpGet(port, "/")), 200);
}

TEST(LoopbackServer, StoppingWithClientsConnectedEndsPromptly) {
  test::TempDir dir;
  dir.write("big.bin", std::string(8 << 20, 'x'));
  std::vector<int> clients;
  Clock::time_point stopping;
  {
    StaticFileServer server(dir.path(), 0);
    clients.push_back(connectToLoopback(server.port()));  // silent
    const int reader = connectToLoopback(server.port());  // never reads its 8 MiB
    sendText(reader, requestFor(server.port(), "/big.bin"));
    clients.push_back(reader);
    ASSERT_TRUE(eventually([&] { return server.activeConnections() == 2; }));
    stopping = Clock::now();
  }
  EXPECT_LT(secondsSince(stopping), 1.0);
  for (const int client : clients) ::close(client);
}

/// Lowers this process's descriptor limit to what is open now (and fills every gap below it), so
/// that accept() fails with EMFILE; restores it when destroyed.
class OutOfDescriptors {
 public:
  OutOfDescriptors() {
    ::getrlimit(RLIMIT_NOFILE, &saved_);
    int highest = 0;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/fd"))
      highest = std::max(highest, std::stoi(entry.path().filename().string()));
    rlimit lowered = saved_;
    lowered.rlim_cur = static_cast<rlim_t>(highest + 1);
    ::setrlimit(RLIMIT_NOFILE, &lowered);
    for (int fd; (fd = ::dup(0)) >= 0;) fillers_.push_back(fd);
  }
  ~OutOfDescriptors() { restore(); }
  void restore() {
    for (const int fd : fillers_) ::close(fd);
    fillers_.clear();
    ::setrlimit(RLIMIT_NOFILE, &saved_);
  }

 private:
  rlimit saved_{};
  std::vector<int> fillers_;
};

double processCpuSeconds() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The finding: out of descriptors, accept() failed at once again and again: 100 % CPU.
TEST(LoopbackServer, OutOfDescriptorsItWaitsInsteadOfSpinningAndAnswersOnceOneIsFree) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  StaticFileServer server(dir.path(), 0);
  const int client = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(server.port()));
  // One whole request first, so the accepting and serving threads are running before the limit: a
  // thread started while no descriptor is free can fail the sanitizers' own checks (they need one).
  {
    const int warm = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    ASSERT_EQ(::connect(warm, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    sendText(warm, requestFor(server.port(), "/index.html"));
    ASSERT_EQ(httpStatus(readReply(warm, 3s)), 200);
    ::close(warm);
  }
  double cpu = 0;
  {
    OutOfDescriptors limit;
    ASSERT_EQ(::connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    sendText(client, requestFor(server.port(), "/index.html"));
    const double before = processCpuSeconds();
    std::this_thread::sleep_for(1s);
    cpu = processCpuSeconds() - before;
  }
  EXPECT_LT(cpu, 0.3) << "the accept loop spun while out of descriptors";
  const std::string reply = readReply(client, 3s);
  EXPECT_EQ(httpStatus(reply), 200) << reply;
  ::close(client);
}

}  // namespace
}  // namespace pmdplan
