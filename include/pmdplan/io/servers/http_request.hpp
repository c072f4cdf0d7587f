#pragma once
// The little of HTTP/1.1 pmdplan's loopback servers speak: a request head's request line and Host
// field, the check that the Host names this server (a page of another site that a rebinding DNS
// name points at 127.0.0.1 sends its own name, and is refused), and short text responses.
#include <string>

namespace pmdplan {

struct HttpRequest {
  /// A request line "METHOD TARGET HTTP/1.x" was found.
  bool valid = false;
  std::string method;
  std::string target;
  /// How many Host fields the head holds (exactly one is valid) and the last one's value, trimmed.
  int hostFields = 0;
  std::string host;
};

/// Parses a request head (all up to the blank line); never throws for any bytes but bad_alloc.
HttpRequest parseHttpRequest(const std::string& head);

/// True if `host` names this server: 127.0.0.1, localhost or [::1], with `port` or without a port.
bool isLoopbackHost(const std::string& host, int port);

/// Why a request is refused before its target is looked at (empty if it is not): a bad request
/// line or Host field (400), a Host that is not this server (403), a method other than GET or HEAD
/// (405). The whole response, as httpTextResponse makes it.
std::string refusedRequestResponse(const HttpRequest& request, int port);

/// A complete response with a short text/plain body (left out when `withBody` is false, as for HEAD).
std::string httpTextResponse(int status, const std::string& reason, const std::string& body, bool withBody = true,
                             const std::string& extraHeaders = "");

}  // namespace pmdplan
