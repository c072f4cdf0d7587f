#include "pmdplan/io/servers/event_stream_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "pmdplan/core/input_error.hpp"
#include "pmdplan/io/servers/static_file_server.hpp"

namespace pmdplan {
namespace {

/// Sends all of `bytes` without waiting on a full socket; false if the peer cannot take them.
bool sendNow(int connection, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(connection, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

EventStreamServer::EventStreamServer(std::filesystem::path root, int port) : root_(std::move(root)) {
  socket_ = listenOnLoopback(port, port_);
  thread_ = std::thread([this] { acceptLoop(); });
}

EventStreamServer::~EventStreamServer() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
  ::close(socket_);
  const std::lock_guard lock(mutex_);
  for (const int connection : subscribers_) ::close(connection);
}

void EventStreamServer::acceptLoop() {
  while (!stopping_) {
    pollfd watch{socket_, POLLIN, 0};
    if (::poll(&watch, 1, 100) <= 0) continue;
    const int connection = ::accept4(socket_, nullptr, nullptr, SOCK_CLOEXEC);
    if (connection >= 0) answer(connection);
  }
}

void EventStreamServer::answer(int connection) {
  const std::string request = readRequestHead(connection);
  if (requestTarget(request) != "/events") {
    sendAll(connection, staticFileResponse(root_, request));
    ::close(connection);
    return;
  }
  const int yes = 1;
  ::setsockopt(connection, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
  const std::lock_guard lock(mutex_);
  const std::string head =
      "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: keep-alive\r\n\r\n"
      "retry: 1000\n\n" +
      last_;
  if (!sendNow(connection, head)) {
    ::close(connection);
    return;
  }
  subscribers_.push_back(connection);
}

void EventStreamServer::publish(const std::string& event, const std::string& data) {
  const std::string message = "event: " + event + "\ndata: " + data + "\n\n";
  const std::lock_guard lock(mutex_);
  last_ = message;
  subscribers_.erase(std::remove_if(subscribers_.begin(), subscribers_.end(),
                                    [&](int connection) {
                                      if (sendNow(connection, message)) return false;
                                      ::close(connection);
                                      return true;
                                    }),
                     subscribers_.end());
}

int EventStreamServer::subscribers() {
  const std::lock_guard lock(mutex_);
  return static_cast<int>(subscribers_.size());
}

}  // namespace pmdplan
