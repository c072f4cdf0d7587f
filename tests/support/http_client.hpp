#pragma once
// A raw HTTP client for the tests of pmdplan's loopback servers: connects to 127.0.0.1:PORT, sends
// bytes exactly as given (hostile ones included) and reads the reply, never waiting without bound.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>

namespace pmdplan::test {

/// A connected socket to 127.0.0.1:`port`, or -1.
inline int connectToLoopback(int port) {
  const int client = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (client < 0) return -1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    ::close(client);
    return -1;
  }
  return client;
}

inline bool sendText(int client, const std::string& bytes) {
  for (std::size_t sent = 0; sent < bytes.size();) {
    const ssize_t n = ::send(client, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

/// Reads until the server closes the connection, `text` has arrived (if not empty), or `limit` passed.
inline std::string readReply(int client, std::chrono::milliseconds limit = std::chrono::seconds(5),
                             const std::string& text = "") {
  std::string reply;
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until && (text.empty() || reply.find(text) == std::string::npos)) {
    pollfd watch{client, POLLIN, 0};
    if (::poll(&watch, 1, 20) <= 0) continue;
    char buffer[65536];
    const ssize_t n = ::recv(client, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    reply.append(buffer, static_cast<std::size_t>(n));
  }
  return reply;
}

/// Sends `request` on a new connection and returns the whole reply (empty if none came).
inline std::string httpExchange(int port, const std::string& request,
                                std::chrono::milliseconds limit = std::chrono::seconds(5)) {
  const int client = connectToLoopback(port);
  if (client < 0) return "";
  sendText(client, request);
  const std::string reply = readReply(client, limit);
  ::close(client);
  return reply;
}

/// `GET target` with the Host a browser on this machine sends.
inline std::string httpGet(int port, const std::string& target) {
  return httpExchange(port, "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n");
}

/// The status code of a reply ("HTTP/1.1 404 Not Found..." -> 404), 0 for none.
inline int httpStatus(const std::string& reply) {
  if (reply.rfind("HTTP/1.1 ", 0) != 0 || reply.size() < 12) return 0;
  return std::stoi(reply.substr(9, 3));
}

}  // namespace pmdplan::test
