#pragma once
// The connection handling both of pmdplan's HTTP servers share: a socket on 127.0.0.1, a thread
// that accepts, and one thread per connection (at most ServerLimits::maxConnections; one more is
// answered 503) that reads the request head within its deadline and hands it to the server's
// handler, whose answer must be taken within the send deadline. No exception leaves a
// connection's thread; accept() failing for want of descriptors waits instead of spinning; the
// destructor stops accepting and joins every thread. Not meant to face a network.
#include <atomic>
#include <chrono>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <thread>

#include "pmdplan/io/servers/server_limits.hpp"

namespace pmdplan {

/// A listening socket on 127.0.0.1:`port` (0: a free port the system picks); `boundPort` gets the
/// port it listens on. Throws InputError (field "--serve") if the port is out of range or cannot
/// be bound.
int listenOnLoopback(int port, int& boundPort);

/// One accepted connection as a handler sees it.
class LoopbackConnection {
 public:
  LoopbackConnection(int descriptor, std::chrono::steady_clock::time_point sendBy, const std::atomic<bool>& stopping)
      : descriptor_(descriptor), sendBy_(sendBy), stopping_(stopping) {}
  int descriptor() const { return descriptor_; }
  /// Sends all the bytes before the send deadline; false if the client went away, did not take
  /// them in time, or the server is stopping (the connection is then of no further use).
  bool send(const char* data, std::size_t size);
  bool send(const std::string& bytes) { return send(bytes.data(), bytes.size()); }
  /// The handler keeps the descriptor open past its return (and closes it itself later).
  void keep() { kept_ = true; }
  bool kept() const { return kept_; }

 private:
  int descriptor_;
  std::chrono::steady_clock::time_point sendBy_;
  const std::atomic<bool>& stopping_;
  bool kept_ = false;
};

class LoopbackServer {
 public:
  /// Called on a connection's thread with the complete request head (up to and with its blank
  /// line). It may be called on several threads at once. What it throws is caught (the connection
  /// is closed).
  using Handler = std::function<void(LoopbackConnection& connection, const std::string& head)>;

  /// Binds (listenOnLoopback) and starts accepting.
  LoopbackServer(int port, ServerLimits limits, Handler handler);
  /// stop().
  ~LoopbackServer();
  LoopbackServer(const LoopbackServer&) = delete;
  LoopbackServer& operator=(const LoopbackServer&) = delete;

  int port() const { return port_; }
  const ServerLimits& limits() const { return limits_; }
  /// Connections being answered now.
  int activeConnections() const { return active_.load(); }
  /// Stops accepting, lets every connection's thread end (within 0.1 s) and joins them all.
  void stop();

 private:
  struct Worker {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> finished;
  };
  void acceptLoop();
  void startWorker(int connection);
  void serve(int connection);
  void reapFinishedWorkers();
  void backOff();

  ServerLimits limits_;
  Handler handler_;
  int socket_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::atomic<int> active_{0};
  std::list<Worker> workers_;  // the accept thread's alone while it runs
  std::thread acceptor_;
};

}  // namespace pmdplan
