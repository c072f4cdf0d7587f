#include "pmdplan/io/servers/loopback_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/servers/http_request.hpp"

namespace pmdplan {
namespace {

using Clock = std::chrono::steady_clock;

/// The longest a connection's thread waits at once before it looks whether the server stops.
constexpr std::chrono::milliseconds kStopCheckInterval{100};

/// Milliseconds to wait in poll(): until `until`, at most kStopCheckInterval; 0 once it passed.
int pollSlice(Clock::time_point until) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now());
  return static_cast<int>(std::clamp(left, std::chrono::milliseconds(0), kStopCheckInterval).count());
}

enum class HeadStatus { Complete, TooLarge, TimedOut, Closed, Stopped };

/// Reads a request head: all of it within `limits.headDeadline`, however slowly it arrives.
HeadStatus readHead(int connection, const ServerLimits& limits, const std::atomic<bool>& stopping, std::string& head) {
  const Clock::time_point until = Clock::now() + limits.headDeadline;
  char buffer[4096];
  for (;;) {
    if (stopping) return HeadStatus::Stopped;
    if (Clock::now() >= until) return HeadStatus::TimedOut;
    pollfd watch{connection, POLLIN, 0};
    const int ready = ::poll(&watch, 1, pollSlice(until));
    if (ready < 0 && errno != EINTR) return HeadStatus::Closed;
    if (ready <= 0) continue;
    const ssize_t n = ::recv(connection, buffer, sizeof buffer, MSG_DONTWAIT);
    if (n < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
    if (n <= 0) return HeadStatus::Closed;
    const std::size_t searchFrom = head.size() >= 3 ? head.size() - 3 : 0;
    head.append(buffer, static_cast<std::size_t>(n));
    const std::size_t end = head.find("\r\n\r\n", searchFrom);
    if (end != std::string::npos && end + 4 <= limits.maxHeadBytes) {
      head.resize(end + 4);
      return HeadStatus::Complete;
    }
    if (head.size() >= limits.maxHeadBytes) return HeadStatus::TooLarge;
  }
}

/// A connection beyond the cap: 503 if the socket takes it at once, then closed.
void refuseBusy(int connection) {
  const std::string busy =
      httpTextResponse(503, "Service Unavailable", "too many connections; try again\n", true, "Retry-After: 1\r\n");
  ::send(connection, busy.data(), busy.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  ::shutdown(connection, SHUT_WR);
  char buffer[4096];  // what already came is read, so closing does not reset the answer away
  while (::recv(connection, buffer, sizeof buffer, MSG_DONTWAIT) > 0) {
  }
  ::close(connection);
}

}  // namespace

int listenOnLoopback(int port, int& boundPort) {
  if (port < 0 || port > 65535) throw InputError("", "--serve", "expected a port number 0-65535 (0: any free port)");
  const int listening = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (listening < 0) throw InputError("", "--serve", std::string("cannot open a socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(listening, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::bind(listening, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(listening, 64) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(listening);
    throw InputError("", "--serve",
                     "cannot listen on 127.0.0.1:" + std::to_string(port) + " (" + reason +
                         "); pick another port, or 0 for any free one");
  }
  socklen_t length = sizeof address;
  ::getsockname(listening, reinterpret_cast<sockaddr*>(&address), &length);
  boundPort = ntohs(address.sin_port);
  return listening;
}

bool LoopbackConnection::send(const char* data, std::size_t size) {
  std::size_t sent = 0;
  while (sent < size) {
    if (stopping_ || Clock::now() >= sendBy_) return false;
    const ssize_t n = ::send(descriptor_, data + sent, size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) return false;
    pollfd watch{descriptor_, POLLOUT, 0};
    ::poll(&watch, 1, pollSlice(sendBy_));
  }
  return true;
}

LoopbackServer::LoopbackServer(int port, ServerLimits limits, Handler handler)
    : limits_(limits), handler_(std::move(handler)) {
  socket_ = listenOnLoopback(port, port_);
  try {
    acceptor_ = std::thread([this] { acceptLoop(); });
  } catch (...) {
    ::close(socket_);
    throw;
  }
}

LoopbackServer::~LoopbackServer() { stop(); }

void LoopbackServer::stop() {
  stopping_ = true;
  if (acceptor_.joinable()) acceptor_.join();
  for (Worker& worker : workers_)
    if (worker.thread.joinable()) worker.thread.join();
  workers_.clear();
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
}

void LoopbackServer::backOff() {
  const Clock::time_point until = Clock::now() + limits_.acceptBackoff;
  while (!stopping_ && Clock::now() < until)
    std::this_thread::sleep_for(std::min<Clock::duration>(until - Clock::now(), kStopCheckInterval));
}

void LoopbackServer::reapFinishedWorkers() {
  for (auto worker = workers_.begin(); worker != workers_.end();) {
    if (!worker->finished->load()) {
      ++worker;
      continue;
    }
    worker->thread.join();
    worker = workers_.erase(worker);
  }
}

void LoopbackServer::acceptLoop() {
  while (!stopping_) {
    reapFinishedWorkers();
    pollfd watch{socket_, POLLIN, 0};
    if (::poll(&watch, 1, static_cast<int>(kStopCheckInterval.count())) <= 0) continue;
    const int connection = ::accept4(socket_, nullptr, nullptr, SOCK_CLOEXEC);
    if (connection >= 0) {
      startWorker(connection);
    } else if (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK && errno != ECONNABORTED) {
      backOff();  // EMFILE, ENFILE, ENOBUFS, ENOMEM: the connection waits in the queue meanwhile
    }
  }
}

void LoopbackServer::startWorker(int connection) {
  reapFinishedWorkers();
  if (static_cast<int>(workers_.size()) >= limits_.maxConnections) {
    refuseBusy(connection);
    return;
  }
  try {
    workers_.emplace_back();  // the list's node first: moving the thread into it cannot fail
    workers_.back().finished = std::make_shared<std::atomic<bool>>(false);
  } catch (...) {
    refuseBusy(connection);
    backOff();
    return;
  }
  Worker& worker = workers_.back();
  ++active_;
  try {
    worker.thread = std::thread([this, connection, finished = worker.finished] {
      serve(connection);
      --active_;
      *finished = true;
    });
  } catch (...) {  // no thread to spare: as busy, and a pause
    --active_;
    workers_.pop_back();
    refuseBusy(connection);
    backOff();
  }
}

void LoopbackServer::serve(int connection) {
  bool kept = false;
  try {
    std::string head;
    const HeadStatus status = readHead(connection, limits_, stopping_, head);
    LoopbackConnection answer(connection, Clock::now() + limits_.sendDeadline, stopping_);
    try {
      if (status == HeadStatus::Complete)
        handler_(answer, head);
      else if (status == HeadStatus::TooLarge)
        answer.send(httpTextResponse(431, "Request Header Fields Too Large",
                                     "request head longer than " + std::to_string(limits_.maxHeadBytes) + " bytes\n"));
      else if (status == HeadStatus::TimedOut)
        answer.send(httpTextResponse(
            408, "Request Timeout",
            "request head not complete within " + std::to_string(limits_.headDeadline.count()) + " ms\n"));
      else if (status == HeadStatus::Closed && !head.empty())
        answer.send(httpTextResponse(400, "Bad Request", "the request head ended before its blank line\n"));
    } catch (...) {  // a connection's failure is that connection's alone
    }
    kept = answer.kept();
  } catch (...) {
  }
  if (!kept) ::close(connection);
}

}  // namespace pmdplan
