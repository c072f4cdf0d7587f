#include "pmdplan/io/servers/event_stream_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

int connectTo(int port) {
  const int client = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  EXPECT_EQ(::connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  return client;
}

/// Reads from `client` until `text` has arrived (or 5 s pass); returns all that came.
std::string readUntil(int client, const std::string& text) {
  std::string got;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (got.find(text) == std::string::npos && std::chrono::steady_clock::now() < until) {
    pollfd watch{client, POLLIN, 0};
    if (::poll(&watch, 1, 50) <= 0) continue;
    char buffer[4096];
    const ssize_t n = ::recv(client, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    got.append(buffer, static_cast<std::size_t>(n));
  }
  return got;
}

/// Subscribes; `received` gets what came with the head (a late subscriber's last event).
int subscribe(EventStreamServer& server, std::string* received = nullptr) {
  const int client = connectTo(server.port());
  const std::string request = "GET /events HTTP/1.1\r\nHost: 127.0.0.1\r\nAccept: text/event-stream\r\n\r\n";
  ::send(client, request.data(), request.size(), 0);
  const std::string head = readUntil(client, "retry: 1000\n\n");
  EXPECT_EQ(head.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << head;
  EXPECT_NE(head.find("Content-Type: text/event-stream"), std::string::npos);
  if (received) *received = head;
  return client;
}

void waitForSubscribers(EventStreamServer& server, int count) {
  for (int i = 0; i < 500 && server.subscribers() < count; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(server.subscribers(), count);
}

TEST(EventStreamServer, EverySubscriberGetsEachEventAndALateOneTheLastFirst) {
  test::TempDir dir;
  EventStreamServer server(dir.path(), 0);
  const int first = subscribe(server);
  waitForSubscribers(server, 1);
  server.publish("posture", "{\"frame\":0}");
  EXPECT_NE(readUntil(first, "\n\n").find("event: posture\ndata: {\"frame\":0}\n\n"), std::string::npos);
  std::string late;
  const int second = subscribe(server, &late);  // the last event comes with the head
  waitForSubscribers(server, 2);
  server.publish("posture", "{\"frame\":1}");
  EXPECT_NE(readUntil(first, "\"frame\":1").find("data: {\"frame\":1}"), std::string::npos);
  late += readUntil(second, "\"frame\":1");
  EXPECT_NE(late.find("data: {\"frame\":0}"), std::string::npos);
  EXPECT_NE(late.find("data: {\"frame\":1}"), std::string::npos);
  ::close(first);
  ::close(second);
}

TEST(EventStreamServer, AGoneSubscriberIsDroppedAndFilesAreStillServed) {
  test::TempDir dir;
  dir.write("index.html", "<p>live</p>");
  EventStreamServer server(dir.path(), 0);
  const int gone = subscribe(server);
  waitForSubscribers(server, 1);
  ::close(gone);
  for (int i = 0; i < 50 && server.subscribers() > 0; ++i) {
    server.publish("posture", std::string(1000, 'x'));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(server.subscribers(), 0);
  const int client = connectTo(server.port());
  const std::string request = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
  ::send(client, request.data(), request.size(), 0);
  const std::string reply = readUntil(client, "<p>live</p>");
  EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK", 0), 0u);
  EXPECT_NE(reply.find("<p>live</p>"), std::string::npos);
  ::close(client);
}

}  // namespace
}  // namespace pmdplan
