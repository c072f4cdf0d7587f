#include "pmdplan/bench/forked_run.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace pmdplan {
namespace {

// The child's first byte says how the work ended; the rest is the output or the message.
constexpr char kResultMark = 'R';
constexpr char kErrorMark = 'E';

void writeAll(int fd, const std::string& text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void runChild(int fd, const std::function<std::string()>& work) {
  std::string message;
  try {
    message = kResultMark + work();
  } catch (const std::exception& e) {
    message = kErrorMark + std::string(e.what());
  } catch (...) {
    message = kErrorMark + std::string("unknown exception");
  }
  writeAll(fd, message);
  ::close(fd);
  ::_exit(0);
}

std::string signalText(int signal) {
  const char* name = ::strsignal(signal);
  return "crashed: signal " + std::to_string(signal) + (name ? " (" + std::string(name) + ")" : "");
}

}  // namespace

ChildOutcome runInChildProcess(const std::function<std::string()>& work, double deadlineSeconds) {
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (child == 0) {
    ::close(fds[0]);
    runChild(fds[1], work);
  }
  ::close(fds[1]);

  using Clock = std::chrono::steady_clock;
  const auto deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(deadlineSeconds));
  std::string received;
  bool timedOut = false;
  char buffer[4096];
  for (;;) {
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    if (left <= 0.0) {
      timedOut = true;
      break;
    }
    pollfd pfd{fds[0], POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(std::min(left * 1000.0 + 1.0, 60'000.0)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child closed its end or died
    received.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timedOut) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }

  ChildOutcome outcome;
  if (timedOut) {
    outcome.kind = ChildOutcome::Kind::TimedOut;
    char text[96];
    std::snprintf(text, sizeof text, "killed: no result within %.0f s", deadlineSeconds);
    outcome.problem = text;
  } else if (WIFSIGNALED(status)) {
    outcome.kind = ChildOutcome::Kind::Crashed;
    outcome.problem = signalText(WTERMSIG(status));
  } else if (!received.empty() && received.front() == kResultMark) {
    outcome.kind = ChildOutcome::Kind::Finished;
    outcome.output = received.substr(1);
  } else if (!received.empty() && received.front() == kErrorMark) {
    outcome.kind = ChildOutcome::Kind::Failed;
    outcome.problem = "error: " + received.substr(1);
  } else {
    outcome.kind = ChildOutcome::Kind::Failed;
    outcome.problem = "error: the run ended without a result (exit code " +
                      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")";
  }
  return outcome;
}

}  // namespace pmdplan
