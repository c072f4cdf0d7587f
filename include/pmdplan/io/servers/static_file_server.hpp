#pragma once
// A minimal HTTP server for one folder on the loopback interface (`pmdplan view --serve`): GET and
// HEAD of the folder's files (served_path.hpp's rule: nothing outside the folder, symbolic links
// resolved), one request per connection, only for a Host naming this server (http_request.hpp),
// several clients at once within the bounds of server_limits.hpp (loopback_server.hpp). Enough for
// a browser on the same machine; not meant to face a network.
#include <filesystem>
#include <string>

#include "pmdplan/io/servers/loopback_server.hpp"
#include "pmdplan/io/servers/served_path.hpp"
#include "pmdplan/io/servers/server_limits.hpp"

namespace pmdplan {

/// The answer to one request of a server on `port` for the files of `root`: the response's head
/// (or a whole short response) and, for a GET of a file, the file to send after it.
struct StaticAnswer {
  std::string head;
  ServedFile file;
  bool sendFile = false;
};
/// Never throws but bad_alloc (an unexpected failure is a 500 answer).
StaticAnswer staticFileAnswer(const std::filesystem::path& root, const std::string& requestHead, int port);

/// The whole HTTP response (head and every byte of the file) to `requestHead`, as the server sends it.
std::string staticFileResponse(const std::filesystem::path& root, const std::string& requestHead, int port);

/// Sends staticFileAnswer's answer on `connection` (the file in pieces, within the send deadline).
void sendStaticFileAnswer(LoopbackConnection& connection, const std::filesystem::path& root,
                          const std::string& requestHead, int port);

class StaticFileServer {
 public:
  /// Binds 127.0.0.1:`port` (0: a free port the system picks) and answers on threads of its own
  /// until destroyed. Throws InputError (field "--serve") if the port is out of range or cannot
  /// be bound.
  StaticFileServer(std::filesystem::path root, int port, ServerLimits limits = {});

  int port() const { return server_.port(); }
  /// Connections being answered now.
  int activeConnections() const { return server_.activeConnections(); }
  /// Blocks the calling thread until the process is stopped.
  [[noreturn]] void serveForever();

 private:
  std::filesystem::path root_;
  LoopbackServer server_;  // last: its threads stop before root_ goes
};

}  // namespace pmdplan
