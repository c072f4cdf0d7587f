#include "pmdplan/io/servers/event_stream_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include "support/http_client.hpp"
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

// The finding: a request the viewer's file rule could not resolve (a 256-character name, a link
// loop) threw on the accept thread and aborted `glove stream --serve` (SIGABRT), and "//etc/passwd"
// answered the file.
TEST(EventStreamServer, OtherPathsFollowTheStaticRuleAndNoRequestEndsTheStream) {
  test::TempDir dir;
  dir.write("site/index.html", "<p>live</p>");
  dir.write("secret.txt", "TOP-SECRET-BYTES");
  std::filesystem::create_symlink("loop", dir.path() / "site" / "loop");
  std::filesystem::create_symlink("../secret.txt", dir.path() / "site" / "out");
  EventStreamServer server(dir.path() / "site", 0);
  const int subscriber = subscribe(server);
  waitForSubscribers(server, 1);
  for (const std::string& target :
       {"//" + (dir.path() / "secret.txt").string(), "/%2f" + (dir.path() / "secret.txt").string().substr(1),
        std::string("//etc/passwd"), std::string("/%2Fetc/passwd"), "/" + std::string(256, 'a'),
        "/" + std::string(5000, 'a'), std::string("/loop"), std::string("/out"), std::string("/x%00")}) {
    const std::string reply = test::httpGet(server.port(), target);
    const int status = test::httpStatus(reply);
    EXPECT_TRUE(status == 404 || status == 400) << target.substr(0, 40) << ": " << reply.substr(0, 40);
    EXPECT_EQ(reply.find("TOP-SECRET"), std::string::npos);
  }
  EXPECT_EQ(test::httpStatus(test::httpGet(server.port(), "/")), 200);
  server.publish("posture", "{\"frame\":7}");
  EXPECT_NE(readUntil(subscriber, "frame\":7").find("data: {\"frame\":7}"), std::string::npos);
  ::close(subscriber);
}

TEST(EventStreamServer, AnotherHostCannotSubscribe) {
  test::TempDir dir;
  EventStreamServer server(dir.path(), 0);
  const std::string reply = test::httpExchange(
      server.port(), "GET /events HTTP/1.1\r\nHost: evil.example:" + std::to_string(server.port()) + "\r\n\r\n");
  EXPECT_EQ(test::httpStatus(reply), 403) << reply;
  EXPECT_EQ(test::httpStatus(test::httpExchange(server.port(), "GET /events HTTP/1.0\r\n\r\n")), 400);
  EXPECT_EQ(server.subscribers(), 0);
}

// The finding: every /events subscriber was kept, however many.
TEST(EventStreamServer, SubscribersBeyondTheCapAre503AndAGoneOneFreesItsPlace) {
  test::TempDir dir;
  dir.write("index.html", "<p>live</p>");
  ServerLimits limits;
  limits.maxSubscribers = 3;
  EventStreamServer server(dir.path(), 0, limits);
  std::vector<int> pages;
  for (int i = 0; i < 3; ++i) pages.push_back(subscribe(server));
  waitForSubscribers(server, 3);
  const std::string events = "GET /events HTTP/1.1\r\nHost: localhost:" + std::to_string(server.port()) + "\r\n\r\n";
  EXPECT_EQ(test::httpStatus(test::httpExchange(server.port(), events)), 503);
  EXPECT_EQ(server.subscribers(), 3);
  EXPECT_EQ(test::httpStatus(test::httpGet(server.port(), "/")), 200);  // pages are still served
  ::close(pages.back());  // a page closed: its place is free for the next one, published or not
  pages.pop_back();
  pages.push_back(subscribe(server));
  waitForSubscribers(server, 3);
  for (const int page : pages) ::close(page);
}

TEST(EventStreamServer, StoppingWithSubscribersAndSlowClientsEndsPromptly) {
  test::TempDir dir;
  std::vector<int> clients;
  const auto started = std::chrono::steady_clock::now();
  {
    EventStreamServer server(dir.path(), 0);
    clients.push_back(subscribe(server));
    clients.push_back(test::connectToLoopback(server.port()));  // says nothing
    waitForSubscribers(server, 1);
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 1.5);
  for (const int client : clients) ::close(client);
}

}  // namespace
}  // namespace pmdplan
