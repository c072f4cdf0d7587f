#include "pmdplan/io/servers/static_file_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <thread>

#include "pmdplan/core/input_error.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

/// Sends `request` to 127.0.0.1:port while the server answers one request; returns the reply.
std::string roundTrip(StaticFileServer& server, const std::string& request) {
  std::thread serving([&] { server.serveOne(); });
  const int client = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(server.port()));
  std::string reply;
  if (::connect(client, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
    ::send(client, request.data(), request.size(), 0);
    char buffer[4096];
    for (ssize_t n; (n = ::recv(client, buffer, sizeof buffer, 0)) > 0;)
      reply.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(client);
  serving.join();
  return reply;
}

std::string get(StaticFileServer& server, const std::string& target) {
  return roundTrip(server, "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
}

TEST(StaticFileServer, ServesTheFolderOnLoopbackWithContentTypes) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  dir.write("a b/data.js", "var x = 1;");
  StaticFileServer server(dir.path(), 0);
  ASSERT_GT(server.port(), 0);

  std::string reply = get(server, "/");
  EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << reply;
  EXPECT_NE(reply.find("Content-Type: text/html; charset=utf-8\r\n"), std::string::npos);
  EXPECT_NE(reply.find("Content-Length: 12\r\n"), std::string::npos);
  EXPECT_EQ(reply.substr(reply.size() - 12), "<p>hello</p>");

  reply = get(server, "/a%20b/data.js?v=2");
  EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << reply;
  EXPECT_NE(reply.find("Content-Type: text/javascript"), std::string::npos);

  reply = roundTrip(server, "HEAD /index.html HTTP/1.1\r\n\r\n");
  EXPECT_NE(reply.find("Content-Length: 12\r\n"), std::string::npos);
  EXPECT_EQ(reply.find("<p>"), std::string::npos) << "HEAD has no body";
}

TEST(StaticFileServer, RefusesWhatIsOutsideTheFolderAndAnswersMissingFiles) {
  test::TempDir dir;
  dir.write("site/index.html", "inside");
  dir.write("secret.txt", "outside");
  dir.write("site/.hidden", "temporary");
  StaticFileServer server(dir.path() / "site", 0);
  EXPECT_EQ(get(server, "/../secret.txt").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(get(server, "/%2e%2e/secret.txt").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(get(server, "/.hidden").rfind("HTTP/1.1 403", 0), 0u);
  EXPECT_EQ(get(server, "/nothing.js").rfind("HTTP/1.1 404", 0), 0u);
  EXPECT_EQ(roundTrip(server, "POST / HTTP/1.1\r\n\r\n").rfind("HTTP/1.1 405", 0), 0u);
}

TEST(StaticFileServer, ABadOrTakenPortIsAnInputErrorOnServe) {
  test::TempDir dir;
  EXPECT_THROW(StaticFileServer(dir.path(), 70000), InputError);
  StaticFileServer first(dir.path(), 0);
  try {
    StaticFileServer second(dir.path(), first.port());
    FAIL() << "two servers on one port";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "--serve");
  }
}

}  // namespace
}  // namespace pmdplan
