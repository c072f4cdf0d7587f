#include "pmdplan/io/servers/event_stream_server.hpp"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include "pmdplan/io/servers/http_request.hpp"
#include "pmdplan/io/servers/static_file_server.hpp"

namespace pmdplan {
namespace {

/// Sends all of `bytes` without waiting on a full socket; false if the peer cannot take them.
bool sendEventNow(int connection, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(connection, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

/// True if the page hung up (or its connection failed): nothing else ever comes from a subscriber.
bool hungUp(int connection) {
  pollfd watch{connection, POLLIN | POLLRDHUP, 0};
  return ::poll(&watch, 1, 0) > 0 && (watch.revents & (POLLIN | POLLRDHUP | POLLHUP | POLLERR)) != 0;
}

/// The path of a GET request ("/events" of "GET /events?x HTTP/1.1"), empty for any other request.
std::string eventRequestPath(const HttpRequest& request) {
  return request.method == "GET" ? request.target.substr(0, request.target.find_first_of("?#")) : std::string();
}

}  // namespace

EventStreamServer::EventStreamServer(std::filesystem::path root, int port, ServerLimits limits)
    : root_(std::move(root)), server_(port, limits, [this](LoopbackConnection& connection, const std::string& head) {
        answer(connection, head);
      }) {}

EventStreamServer::~EventStreamServer() {
  server_.stop();
  const std::lock_guard lock(mutex_);
  for (const int connection : subscribers_) ::close(connection);
}

void EventStreamServer::answer(LoopbackConnection& connection, const std::string& head) {
  const HttpRequest request = parseHttpRequest(head);
  if (!refusedRequestResponse(request, server_.port()).empty() || eventRequestPath(request) != "/events") {
    sendStaticFileAnswer(connection, root_, head, server_.port());
    return;
  }
  const int yes = 1;
  ::setsockopt(connection.descriptor(), IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
  const std::lock_guard lock(mutex_);
  dropClosedSubscribers();
  if (static_cast<int>(subscribers_.size()) >= server_.limits().maxSubscribers) {
    connection.send(httpTextResponse(
        503, "Service Unavailable",
        "too many pages follow this stream (" + std::to_string(server_.limits().maxSubscribers) + "); close one\n",
        true, "Retry-After: 5\r\n"));
    return;
  }
  const std::string answerHead =
      "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: keep-alive\r\n\r\n"
      "retry: 1000\n\n" +
      last_;
  if (!sendEventNow(connection.descriptor(), answerHead)) return;
  subscribers_.push_back(connection.descriptor());
  connection.keep();
}

void EventStreamServer::dropClosedSubscribers() {
  subscribers_.erase(std::remove_if(subscribers_.begin(), subscribers_.end(),
                                    [](int connection) {
                                      if (!hungUp(connection)) return false;
                                      ::close(connection);
                                      return true;
                                    }),
                     subscribers_.end());
}

void EventStreamServer::publish(const std::string& event, const std::string& data) {
  const std::string message = "event: " + event + "\ndata: " + data + "\n\n";
  const std::lock_guard lock(mutex_);
  last_ = message;
  subscribers_.erase(std::remove_if(subscribers_.begin(), subscribers_.end(),
                                    [&](int connection) {
                                      if (sendEventNow(connection, message)) return false;
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
