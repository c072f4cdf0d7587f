#include "pmdplan/io/servers/static_file_server.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "pmdplan/core/input_error.hpp"
#include "support/http_client.hpp"
#include "support/temp_dir.hpp"

namespace pmdplan {
namespace {

using test::httpExchange;
using test::httpGet;
using test::httpStatus;

/// A served folder `site` with an index page, and a secret file beside it (outside the folder).
struct SiteBesideASecret {
  test::TempDir dir;
  std::filesystem::path site = dir.path() / "site";
  std::filesystem::path secret = dir.write("secret.txt", "TOP-SECRET-BYTES");
  SiteBesideASecret() { dir.write("site/index.html", "<p>inside</p>"); }
};

TEST(StaticFileServer, ServesTheFolderOnLoopbackWithContentTypes) {
  test::TempDir dir;
  dir.write("index.html", "<p>hello</p>");
  dir.write("a b/data.js", "var x = 1;");
  StaticFileServer server(dir.path(), 0);
  ASSERT_GT(server.port(), 0);

  std::string reply = httpGet(server.port(), "/");
  EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << reply;
  EXPECT_NE(reply.find("Content-Type: text/html; charset=utf-8\r\n"), std::string::npos);
  EXPECT_NE(reply.find("Content-Length: 12\r\n"), std::string::npos);
  EXPECT_EQ(reply.substr(reply.size() - 12), "<p>hello</p>");

  reply = httpGet(server.port(), "/a%20b/data.js?v=2");
  EXPECT_EQ(reply.rfind("HTTP/1.1 200 OK\r\n", 0), 0u) << reply;
  EXPECT_NE(reply.find("Content-Type: text/javascript"), std::string::npos);

  reply = httpExchange(server.port(), "HEAD /index.html HTTP/1.1\r\nHost: localhost\r\n\r\n");
  EXPECT_NE(reply.find("Content-Length: 12\r\n"), std::string::npos) << reply;
  EXPECT_EQ(reply.find("<p>"), std::string::npos) << "HEAD has no body";
}

TEST(StaticFileServer, RefusesWhatIsOutsideTheFolderAndAnswersMissingFiles) {
  SiteBesideASecret s;
  s.dir.write("site/.hidden", "temporary");
  StaticFileServer server(s.site, 0);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/../secret.txt")), 403);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/%2e%2e/secret.txt")), 403);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/.hidden")), 403);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/nothing.js")), 404);
  const std::string post = httpExchange(server.port(), "POST / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_EQ(httpStatus(post), 405);
  EXPECT_NE(post.find("Allow: GET, HEAD\r\n"), std::string::npos);
}

// The finding: "//etc/passwd" and "/%2fetc/passwd" answered 200 with the file, since the path was
// checked without its leading slashes but joined with them (an absolute path replaces the root).
TEST(StaticFileServer, DoubledAndEncodedSlashesNeverLeaveTheFolder) {
  SiteBesideASecret s;
  StaticFileServer server(s.site, 0);
  const std::string secret = s.secret.string();  // absolute: "/tmp/.../secret.txt"
  for (const std::string& target :
       {"/" + secret, "/%2f" + secret.substr(1), "/%2F" + secret.substr(1), "/%2F%2F" + secret.substr(1),
        std::string("//etc/passwd"), std::string("/%2fetc/passwd"), std::string("/%2Fetc/passwd"),
        std::string("//proc/self/environ"), std::string("///proc/self/environ"), std::string("/%2e%2e%2fsecret.txt"),
        std::string("/site/..%2f..%2fsecret.txt")}) {
    const std::string reply = httpGet(server.port(), target);
    EXPECT_TRUE(httpStatus(reply) == 404 || httpStatus(reply) == 403) << target << ": " << reply.substr(0, 60);
    EXPECT_EQ(reply.find("TOP-SECRET"), std::string::npos) << target;
    EXPECT_EQ(reply.find("root:"), std::string::npos) << target;
    EXPECT_EQ(reply.find("PATH="), std::string::npos) << target;
  }
  // Doubled slashes inside the folder are merged, as web servers do.
  EXPECT_EQ(httpStatus(httpGet(server.port(), "//index.html")), 200);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/")), 200);
}

TEST(StaticFileServer, EncodedNulControlBytesAndBadEscapesAreBadRequests) {
  SiteBesideASecret s;
  StaticFileServer server(s.site, 0);
  for (const std::string target : {"/index.html%00.js", "/%00", "/a%0d%0aSet-Cookie:x", "/%7f", "/%zz", "/%2",
                                   "/index.html%", "http://127.0.0.1/index.html", "*"})
    EXPECT_EQ(httpStatus(httpGet(server.port(), target)), 400) << target;
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/index.html")), 200);
}

// The finding: a 256-character name ended the viewer's server (exit 3, ENAMETOOLONG from
// status()), and so did a symbolic link loop (ELOOP).
TEST(StaticFileServer, LongNamesAndSymlinkLoopsAreNotFoundAndTheServerGoesOn) {
  SiteBesideASecret s;
  std::filesystem::create_symlink("loop-b", s.site / "loop-a");
  std::filesystem::create_symlink("loop-a", s.site / "loop-b");
  std::filesystem::create_symlink("self", s.site / "self");
  StaticFileServer server(s.site, 0);
  for (const std::string& target :
       {"/" + std::string(256, 'a'), "/" + std::string(5000, 'a'), "/x/" + std::string(300, 'b') + "/c",
        "/" + std::string(255, 'a'), std::string("/loop-a"), std::string("/loop-a/x"), std::string("/self"),
        std::string("/self/index.html")}) {
    EXPECT_EQ(httpStatus(httpGet(server.port(), target)), 404) << target.substr(0, 40);
    EXPECT_EQ(httpStatus(httpGet(server.port(), "/")), 200) << "after " << target.substr(0, 40);
  }
  std::string deep;
  for (int i = 0; i < 2000; ++i) deep += "/d";  // 4000 bytes of components, more than PATH_MAX joined
  EXPECT_EQ(httpStatus(httpGet(server.port(), deep)), 404);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/")), 200);
}

TEST(StaticFileServer, ASymbolicLinkIsFollowedOnlyToWhereTheFolderHoldsIt) {
  SiteBesideASecret s;
  s.dir.write("site/.partial", "temporary");
  std::filesystem::create_symlink(s.secret, s.site / "absolute.txt");
  std::filesystem::create_symlink("../secret.txt", s.site / "relative.txt");
  std::filesystem::create_symlink(s.dir.path(), s.site / "up");
  std::filesystem::create_symlink("/etc", s.site / "etc");
  std::filesystem::create_symlink(".partial", s.site / "visible");
  std::filesystem::create_symlink("index.html", s.site / "alias.html");
  StaticFileServer server(s.site, 0);
  for (const std::string target : {"/absolute.txt", "/relative.txt", "/up/secret.txt", "/etc/passwd", "/visible"}) {
    const std::string reply = httpGet(server.port(), target);
    EXPECT_EQ(httpStatus(reply), 404) << target;
    EXPECT_EQ(reply.find("TOP-SECRET"), std::string::npos) << target;
  }
  const std::string alias = httpGet(server.port(), "/alias.html");  // a link that stays inside is fine
  EXPECT_EQ(httpStatus(alias), 200);
  EXPECT_NE(alias.find("<p>inside</p>"), std::string::npos);
}

TEST(StaticFileServer, ServedThroughALinkedRootTheFolderIsStillServed) {
  SiteBesideASecret s;
  std::filesystem::create_symlink(s.site, s.dir.path() / "linked-site");
  StaticFileServer server(s.dir.path() / "linked-site", 0);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/index.html")), 200);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/%2e%2e/secret.txt")), 403);
}

TEST(StaticFileServer, WhatCannotBeReadIsNotFoundAndAFifoIsNotWaitedOn) {
  SiteBesideASecret s;
  ASSERT_EQ(::mkfifo((s.site / "fifo.js").c_str(), 0600), 0);
  std::filesystem::create_directories(s.site / "locked");
  s.dir.write("site/locked/file.js", "x");
  s.dir.write("site/unreadable.js", "x");
  StaticFileServer server(s.site, 0);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/fifo.js")), 404);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/locked")), 404);  // a folder is not a file
  if (::geteuid() == 0) GTEST_SKIP() << "root reads files whatever their mode";
  std::filesystem::permissions(s.site / "unreadable.js", std::filesystem::perms::none);
  std::filesystem::permissions(s.site / "locked", std::filesystem::perms::none);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/unreadable.js")), 404);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/locked/file.js")), 404);
  EXPECT_EQ(httpStatus(httpGet(server.port(), "/index.html")), 200);
  std::filesystem::permissions(s.site / "locked", std::filesystem::perms::owner_all);
}

// DNS rebinding: a page of another site whose name resolves to 127.0.0.1 sends its own name as Host.
TEST(StaticFileServer, OnlyAHostNamingThisServerIsAnswered) {
  SiteBesideASecret s;
  StaticFileServer server(s.site, 0);
  const std::string port = std::to_string(server.port());
  const auto withHost = [&](const std::string& fields) {
    return httpStatus(httpExchange(server.port(), "GET /index.html HTTP/1.1\r\n" + fields + "\r\n"));
  };
  for (const std::string& host : {"127.0.0.1:" + port, "localhost:" + port, "LocalHost:" + port, "[::1]:" + port,
                                  std::string("127.0.0.1"), std::string("localhost")})
    EXPECT_EQ(withHost("Host: " + host + "\r\n"), 200) << host;
  for (const std::string& host : {"evil.example:" + port, std::string("evil.example"), std::string("127.0.0.1:1"),
                                  "127.0.0.2:" + port, "localhost.evil.example:" + port, std::string("")})
    EXPECT_EQ(withHost("Host: " + host + "\r\n"), 403) << host;
  EXPECT_EQ(withHost(""), 400);  // no Host at all
  EXPECT_EQ(httpStatus(httpExchange(server.port(), "GET /index.html HTTP/1.0\r\n\r\n")), 400);
  EXPECT_EQ(withHost("Host: 127.0.0.1\r\nHost: evil.example\r\n"), 400);
  EXPECT_EQ(withHost("Host: localhost:" + port + "\r\n"), 200);
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

TEST(StaticFileServer, TheResponseFunctionNeverServesBytesFromOutsideTheRoot) {
  SiteBesideASecret s;
  std::filesystem::create_symlink("../secret.txt", s.site / "out");
  const auto response = [&](const std::string& target) {
    return staticFileResponse(s.site, "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n", 8000);
  };
  EXPECT_EQ(response("/index.html").substr(response("/index.html").size() - 13), "<p>inside</p>");
  for (const std::string& target : {"//" + s.secret.string(), std::string("/out"), std::string("/../secret.txt")})
    EXPECT_EQ(response(target).find("TOP-SECRET"), std::string::npos) << target;
}

}  // namespace
}  // namespace pmdplan
