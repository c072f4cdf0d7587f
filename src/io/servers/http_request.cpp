#include "pmdplan/io/servers/http_request.hpp"

#include <cctype>
#include <sstream>

namespace pmdplan {
namespace {

std::string lowerCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string trimmedField(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

}  // namespace

HttpRequest parseHttpRequest(const std::string& head) {
  HttpRequest request;
  std::size_t end = head.find("\r\n");
  const std::string requestLine = head.substr(0, end);
  std::istringstream words(requestLine);
  std::string version, extra;
  words >> request.method >> request.target >> version;
  request.valid =
      !request.method.empty() && !request.target.empty() && version.rfind("HTTP/1.", 0) == 0 && !(words >> extra);
  while (end != std::string::npos) {
    const std::size_t start = end + 2;
    end = head.find("\r\n", start);
    const std::string line = head.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos || lowerCase(line.substr(0, colon)) != "host") continue;
    ++request.hostFields;
    request.host = trimmedField(line.substr(colon + 1));
  }
  return request;
}

bool isLoopbackHost(const std::string& host, int port) {
  const std::string name = lowerCase(host);
  for (const std::string allowed : {"127.0.0.1", "localhost", "[::1]"})
    if (name == allowed || name == allowed + ":" + std::to_string(port)) return true;
  return false;
}

std::string refusedRequestResponse(const HttpRequest& request, int port) {
  if (!request.valid) return httpTextResponse(400, "Bad Request", "expected a request line METHOD /PATH HTTP/1.1\n");
  const bool withBody = request.method != "HEAD";
  if (request.hostFields != 1) return httpTextResponse(400, "Bad Request", "expected one Host field\n", withBody);
  if (!isLoopbackHost(request.host, port))
    return httpTextResponse(403, "Forbidden",
                            "this server answers only Host 127.0.0.1:" + std::to_string(port) +
                                " or localhost:" + std::to_string(port) + "\n",
                            withBody);
  if (request.method != "GET" && request.method != "HEAD")
    return httpTextResponse(405, "Method Not Allowed", "only GET and HEAD\n", true, "Allow: GET, HEAD\r\n");
  return "";
}

std::string httpTextResponse(int status, const std::string& reason, const std::string& body, bool withBody,
                             const std::string& extraHeaders) {
  std::ostringstream head;
  head << "HTTP/1.1 " << status << " " << reason << "\r\n"
       << "Content-Type: text/plain; charset=utf-8\r\n"
       << "Content-Length: " << body.size() << "\r\n"
       << "Cache-Control: no-store\r\n"
       << extraHeaders << "Connection: close\r\n\r\n";
  return head.str() + (withBody ? body : std::string());
}

}  // namespace pmdplan
