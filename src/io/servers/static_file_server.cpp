#include "pmdplan/io/servers/static_file_server.hpp"

#include <unistd.h>

#include <cerrno>
#include <sstream>
#include <string>
#include <thread>

#include "pmdplan/io/servers/http_request.hpp"

namespace pmdplan {
namespace {

/// A file is read and sent in pieces of this size.
constexpr std::size_t kFilePieceBytes = 64 * 1024;

std::string staticContentType(const std::filesystem::path& file) {
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

/// The path for a message: at most 200 bytes of it.
std::string shownPath(const std::string& relative) {
  return relative.size() <= 200 ? relative : relative.substr(0, 200) + "...";
}

/// Reads up to `size` bytes at the descriptor's position; 0 at its end, -1 on an error.
ssize_t readPiece(int descriptor, char* buffer, std::size_t size) {
  for (;;) {
    const ssize_t n = ::read(descriptor, buffer, size);
    if (n >= 0 || errno != EINTR) return n;
  }
}

StaticAnswer answerFor(const std::filesystem::path& root, const std::string& requestHead, int port) {
  StaticAnswer answer;
  const HttpRequest request = parseHttpRequest(requestHead);
  answer.head = refusedRequestResponse(request, port);
  if (!answer.head.empty()) return answer;
  const bool withBody = request.method == "GET";
  answer.file = openServedFile(root, request.target);
  switch (answer.file.status) {
    case ServedPathStatus::BadRequest:
      answer.head = httpTextResponse(400, "Bad Request",
                                     "expected a path of the viewer folder: /NAME, %-escapes of two hex "
                                     "digits, no control bytes\n",
                                     withBody);
      return answer;
    case ServedPathStatus::Forbidden:
      answer.head = httpTextResponse(403, "Forbidden", "outside the viewer folder\n", withBody);
      return answer;
    case ServedPathStatus::NotFound:
      answer.head =
          httpTextResponse(404, "Not Found", "not found: " + shownPath(answer.file.relative) + "\n", withBody);
      return answer;
    case ServedPathStatus::Found:
      break;
  }
  std::ostringstream head;
  head << "HTTP/1.1 200 OK\r\n"
       << "Content-Type: " << staticContentType(answer.file.resolved) << "\r\n"
       << "Content-Length: " << answer.file.size << "\r\n"
       << "Cache-Control: no-store\r\n"
       << "X-Content-Type-Options: nosniff\r\n"
       << "Connection: close\r\n\r\n";
  answer.head = head.str();
  answer.sendFile = withBody;
  return answer;
}

}  // namespace

StaticAnswer staticFileAnswer(const std::filesystem::path& root, const std::string& requestHead, int port) {
  try {
    return answerFor(root, requestHead, port);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (...) {
    StaticAnswer answer;
    answer.head = httpTextResponse(500, "Internal Server Error", "the server failed to answer this request\n");
    return answer;
  }
}

std::string staticFileResponse(const std::filesystem::path& root, const std::string& requestHead, int port) {
  StaticAnswer answer = staticFileAnswer(root, requestHead, port);
  std::string response = answer.head;
  if (!answer.sendFile) return response;
  const std::size_t headSize = response.size();
  std::string piece(kFilePieceBytes, '\0');
  for (ssize_t n; (n = readPiece(answer.file.descriptor, piece.data(), piece.size())) > 0;)
    response.append(piece.data(), static_cast<std::size_t>(n));
  response.resize(std::min<std::size_t>(response.size(), headSize + answer.file.size));
  return response;
}

void sendStaticFileAnswer(LoopbackConnection& connection, const std::filesystem::path& root,
                          const std::string& requestHead, int port) {
  const StaticAnswer answer = staticFileAnswer(root, requestHead, port);
  if (!connection.send(answer.head) || !answer.sendFile) return;
  // Exactly Content-Length bytes: a file that shrank meanwhile ends the connection early (the
  // client sees a short body), one that grew is cut.
  std::string piece(kFilePieceBytes, '\0');
  for (std::uintmax_t left = answer.file.size; left > 0;) {
    const ssize_t n = readPiece(answer.file.descriptor, piece.data(), std::min<std::uintmax_t>(left, piece.size()));
    if (n <= 0 || !connection.send(piece.data(), static_cast<std::size_t>(n))) return;
    left -= static_cast<std::uintmax_t>(n);
  }
}

StaticFileServer::StaticFileServer(std::filesystem::path root, int port, ServerLimits limits)
    : root_(std::move(root)), server_(port, limits, [this](LoopbackConnection& connection, const std::string& head) {
        sendStaticFileAnswer(connection, root_, head, server_.port());
      }) {}

void StaticFileServer::serveForever() {
  for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
}

}  // namespace pmdplan
