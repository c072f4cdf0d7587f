#pragma once
// A CyberGlove's serial line (a USB serial adapter, /dev/ttyUSB0, or a pseudo-terminal standing
// in for one): opened raw (no echo, no line editing, 8 data bits, no parity, one stop bit, no flow
// control) at the glove's baud rate, read without blocking past a timeout, and the 'G' request
// (one sample) written to it.
#include <string>

namespace pmdplan {

/// The rates termios offers that CyberGloves use (the glove's default is 115200).
bool isSupportedBaudRate(int baud);
/// "1200, 2400, ... 230400" for messages.
std::string supportedBaudRates();

class GloveSerialDevice {
 public:
  /// Opens and configures `path`. Throws InputError (file `path`, field "--device" or "--baud")
  /// when it cannot be opened, is not a terminal (a plain file: replay it with --replay), or the
  /// rate is not one termios supports.
  GloveSerialDevice(const std::string& path, int baud);
  ~GloveSerialDevice();
  GloveSerialDevice(const GloveSerialDevice&) = delete;
  GloveSerialDevice& operator=(const GloveSerialDevice&) = delete;

  enum class Read { Data, Timeout, Closed, Interrupted };
  /// Waits up to `timeoutMs` for bytes and appends what is there to `bytes`. Closed: the device
  /// went away (end of file, EIO or a hang-up: unplugged); `reason` then says which.
  /// Interrupted: a signal arrived while waiting.
  Read read(std::string& bytes, int timeoutMs, std::string& reason);
  /// Sends 'G' (ask for one sample). A line whose output is full drops the request: the next one
  /// follows within a period, and a glove that answers none of them times out.
  void requestSample();

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace pmdplan
