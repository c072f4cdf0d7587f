#include "pmdplan/io/servers/static_file_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

std::string contentType(const std::filesystem::path& file) {
  const std::string extension = file.extension().string();
  if (extension == ".html") return "text/html; charset=utf-8";
  if (extension == ".js" || extension == ".mjs") return "text/javascript; charset=utf-8";
  if (extension == ".css") return "text/css; charset=utf-8";
  if (extension == ".json") return "application/json";
  if (extension == ".txt") return "text/plain; charset=utf-8";
  if (extension == ".png") return "image/png";
  if (extension == ".svg") return "image/svg+xml";
  if (extension == ".urdf" || extension == ".xml" || extension == ".dae") return "application/xml";
  return "application/octet-stream";
}

std::string response(int status, const std::string& reason, const std::string& type, const std::string& body,
                     bool withBody) {
  std::ostringstream head;
  head << "HTTP/1.1 " << status << " " << reason << "\r\n"
       << "Content-Type: " << type << "\r\n"
       << "Content-Length: " << body.size() << "\r\n"
       << "Cache-Control: no-store\r\n"
       << "Connection: close\r\n\r\n";
  return head.str() + (withBody ? body : std::string());
}

/// "/a%20b/c.js?x" -> "a b/c.js"; false for a target to refuse.
bool decodeTarget(const std::string& target, std::string& relative) {
  std::string path = target.substr(0, target.find_first_of("?#"));
  if (path.empty() || path.front() != '/') return false;
  std::string decoded;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '%' && i + 2 < path.size() && std::isxdigit(static_cast<unsigned char>(path[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(path[i + 2]))) {
      decoded += static_cast<char>(std::stoi(path.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      decoded += path[i];
    }
  }
  if (decoded.find('\0') != std::string::npos) return false;
  // Nothing outside the folder: no parent steps, no hidden files (the atomic writer's temporaries).
  for (const auto& part : std::filesystem::path(decoded).relative_path())
    if (part == ".." || (!part.empty() && part.string().front() == '.')) return false;
  relative = decoded.substr(1);
  if (relative.empty() || relative.back() == '/') relative += "index.html";
  return true;
}

}  // namespace

void sendAll(int connection, const std::string& bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(connection, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    sent += static_cast<std::size_t>(n);
  }
}

int listenOnLoopback(int port, int& boundPort) {
  if (port < 0 || port > 65535) throw InputError("", "--serve", "expected a port number 0-65535 (0: any free port)");
  const int listening = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listening < 0) throw InputError("", "--serve", std::string("cannot open a socket: ") + std::strerror(errno));
  const int yes = 1;
  ::setsockopt(listening, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  if (::bind(listening, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || ::listen(listening, 16) != 0) {
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

StaticFileServer::StaticFileServer(std::filesystem::path root, int port) : root_(std::move(root)) {
  socket_ = listenOnLoopback(port, port_);
}

StaticFileServer::~StaticFileServer() {
  if (socket_ >= 0) ::close(socket_);
}

void StaticFileServer::serveForever() {
  for (;;) serveOne();
}

std::string readRequestHead(int connection) {
  // A client that connects and says nothing must not hang the server for everyone else.
  timeval timeout{5, 0};
  ::setsockopt(connection, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  std::string request;
  char buffer[4096];
  while (request.find("\r\n\r\n") == std::string::npos && request.size() < 16384) {
    const ssize_t n = ::recv(connection, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    request.append(buffer, static_cast<std::size_t>(n));
  }
  return request;
}

std::string requestTarget(const std::string& request) {
  std::istringstream line(request.substr(0, request.find("\r\n")));
  std::string method, target;
  line >> method >> target;
  return method == "GET" ? target.substr(0, target.find_first_of("?#")) : std::string();
}

std::string staticFileResponse(const std::filesystem::path& root, const std::string& request) {
  std::istringstream line(request.substr(0, request.find("\r\n")));
  std::string method, target;
  line >> method >> target;
  std::string relative;
  if (method != "GET" && method != "HEAD")
    return response(405, "Method Not Allowed", "text/plain", "only GET and HEAD\n", true);
  if (!decodeTarget(target, relative))
    return response(403, "Forbidden", "text/plain", "outside the viewer folder\n", method == "GET");
  const std::filesystem::path file = root / relative;
  std::ifstream in(file, std::ios::binary);
  if (!std::filesystem::is_regular_file(file) || !in)
    return response(404, "Not Found", "text/plain", "not found: " + relative + "\n", method == "GET");
  std::ostringstream body;
  body << in.rdbuf();
  return response(200, "OK", contentType(file), body.str(), method == "GET");
}

void StaticFileServer::serveOne() {
  const int connection = ::accept(socket_, nullptr, nullptr);
  if (connection < 0) return;
  sendAll(connection, staticFileResponse(root_, readRequestHead(connection)));
  ::close(connection);
}

}  // namespace pmdplan
