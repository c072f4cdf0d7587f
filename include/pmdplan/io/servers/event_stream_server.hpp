#pragma once
// A viewer folder served on the loopback interface together with a live stream of server-sent
// events (text/event-stream) at /events: what `pmdplan glove stream --serve` runs. Every other
// path is answered as StaticFileServer would (static_file_server.hpp). Connections are accepted on
// a thread of its own; publish() sends an event to every page subscribed, and a page that subscribes
// late first gets the last event published. Not meant to face a network.
#include <atomic>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace pmdplan {

class EventStreamServer {
 public:
  /// Binds 127.0.0.1:`port` (0: any free port) and starts accepting. Throws InputError (field
  /// "--serve") if the port is out of range or cannot be bound.
  EventStreamServer(std::filesystem::path root, int port);
  /// Stops accepting and closes every connection.
  ~EventStreamServer();
  EventStreamServer(const EventStreamServer&) = delete;
  EventStreamServer& operator=(const EventStreamServer&) = delete;

  int port() const { return port_; }
  /// Sends `event` with `data` (one line, such as compact JSON) to every subscriber; a subscriber
  /// that cannot take it (gone, or too slow to read) is dropped.
  void publish(const std::string& event, const std::string& data);
  /// Pages subscribed now.
  int subscribers();

 private:
  void acceptLoop();
  void answer(int connection);

  std::filesystem::path root_;
  int socket_ = -1;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::vector<int> subscribers_;
  std::string last_;
  std::thread thread_;
};

}  // namespace pmdplan
