#pragma once
// A minimal HTTP server for one folder on the loopback interface (`pmdplan view --serve`): GET and
// HEAD of the folder's files, one request per connection, nothing outside the folder. Enough for
// a browser on the same machine; not meant to face a network.
#include <filesystem>
#include <string>

namespace pmdplan {

/// A listening socket on 127.0.0.1:`port` (0: a free port the system picks); `boundPort` gets the
/// port it listens on. Throws InputError (field "--serve") if the port is out of range or cannot
/// be bound.
int listenOnLoopback(int port, int& boundPort);
/// Reads a request's head from a connected socket (at most 16 KiB, waiting at most 5 s).
std::string readRequestHead(int connection);
/// The path a GET request asks for ("/events" of "GET /events?x HTTP/1.1"), empty for others.
std::string requestTarget(const std::string& request);
/// The whole HTTP response to `request` from the files of `root` (the rules above).
std::string staticFileResponse(const std::filesystem::path& root, const std::string& request);
/// Sends all of `bytes` on a connected socket, waiting while its buffer is full (a page's script
/// is larger than one); stops quietly if the peer went away (there is no one left to tell).
void sendAll(int connection, const std::string& bytes);

class StaticFileServer {
 public:
  /// Binds 127.0.0.1:`port` (0: a free port the system picks). Throws InputError (field
  /// "--serve") if the port is out of range or cannot be bound.
  StaticFileServer(std::filesystem::path root, int port);
  ~StaticFileServer();
  StaticFileServer(const StaticFileServer&) = delete;
  StaticFileServer& operator=(const StaticFileServer&) = delete;

  int port() const { return port_; }
  /// Answers requests until the process is stopped.
  [[noreturn]] void serveForever();
  /// Accepts and answers one request (used by tests).
  void serveOne();

 private:
  std::filesystem::path root_;
  int socket_ = -1;
  int port_ = 0;
};

}  // namespace pmdplan
