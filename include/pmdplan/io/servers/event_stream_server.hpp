#pragma once
// A viewer folder served on the loopback interface together with a live stream of server-sent
// events (text/event-stream) at /events: what `pmdplan glove stream --serve` runs. Every other
// path is answered as StaticFileServer would (static_file_server.hpp), and so is every request
// whose Host is not this server's; connections are handled as loopback_server.hpp does.
// publish() sends an event to every page subscribed, and a page that subscribes late first gets
// the last event published. At most ServerLimits::maxSubscribers pages subscribe at once; one more
// is answered 503. Not meant to face a network.
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "pmdplan/io/servers/loopback_server.hpp"
#include "pmdplan/io/servers/server_limits.hpp"

namespace pmdplan {

class EventStreamServer {
 public:
  /// Binds 127.0.0.1:`port` (0: any free port) and starts accepting. Throws InputError (field
  /// "--serve") if the port is out of range or cannot be bound.
  EventStreamServer(std::filesystem::path root, int port, ServerLimits limits = {});
  /// Stops accepting, joins every connection's thread and closes every subscriber.
  ~EventStreamServer();
  EventStreamServer(const EventStreamServer&) = delete;
  EventStreamServer& operator=(const EventStreamServer&) = delete;

  int port() const { return server_.port(); }
  /// Sends `event` with `data` (one line, such as compact JSON) to every subscriber; a subscriber
  /// that cannot take it (gone, or too slow to read) is dropped.
  void publish(const std::string& event, const std::string& data);
  /// Pages subscribed now.
  int subscribers();
  /// Connections being answered now (subscribers, once subscribed, are not among them).
  int activeConnections() const { return server_.activeConnections(); }

 private:
  void answer(LoopbackConnection& connection, const std::string& head);
  void dropClosedSubscribers();

  std::filesystem::path root_;
  std::mutex mutex_;
  std::vector<int> subscribers_;
  std::string last_;
  LoopbackServer server_;  // last: its threads stop before the members above go
};

}  // namespace pmdplan
