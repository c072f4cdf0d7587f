#pragma once
// The bounds every loopback HTTP server of pmdplan keeps (`view --serve`, `glove stream --serve`):
// how many clients it answers at once, how long one client may take to ask and to read its
// answer, how many live pages it streams to, and how long it waits when the system has no
// descriptors left. One slow or hostile client can never stall the others or the process.
#include <chrono>
#include <cstddef>

namespace pmdplan {

struct ServerLimits {
  /// Connections answered at once, each on a thread of its own; one more is answered
  /// 503 Service Unavailable and closed at once.
  int maxConnections = 32;
  /// The whole request head (request line and headers) must arrive within this time, however it
  /// trickles in; otherwise 408 Request Timeout.
  std::chrono::milliseconds headDeadline{5000};
  /// Longest request head; a longer one is answered 431 Request Header Fields Too Large.
  std::size_t maxHeadBytes = 16384;
  /// The whole response must be taken by the client within this time; otherwise the connection
  /// is closed (a client that never reads holds one thread for at most this long).
  std::chrono::milliseconds sendDeadline{10000};
  /// Pages subscribed to /events at once (EventStreamServer); one more is answered 503.
  int maxSubscribers = 32;
  /// The pause after accept() fails for want of descriptors or memory (EMFILE, ENFILE, ENOBUFS,
  /// ENOMEM): the waiting connection stays queued and is accepted once one is free, with no spinning.
  std::chrono::milliseconds acceptBackoff{100};
};

}  // namespace pmdplan
