#include "pmdplan/glove/glove_serial_device.hpp"

#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <utility>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

constexpr std::array<std::pair<int, speed_t>, 9> kRates{{{1200, B1200},
                                                         {2400, B2400},
                                                         {4800, B4800},
                                                         {9600, B9600},
                                                         {19200, B19200},
                                                         {38400, B38400},
                                                         {57600, B57600},
                                                         {115200, B115200},
                                                         {230400, B230400}}};

speed_t speedOf(int baud) {
  for (const auto& [rate, speed] : kRates)
    if (rate == baud) return speed;
  return B0;
}

}  // namespace

bool isSupportedBaudRate(int baud) { return speedOf(baud) != B0; }

std::string supportedBaudRates() {
  std::string list;
  for (const auto& rate : kRates) list += (list.empty() ? "" : ", ") + std::to_string(rate.first);
  return list;
}

GloveSerialDevice::GloveSerialDevice(const std::string& path, int baud) : path_(path) {
  if (!isSupportedBaudRate(baud))
    throw InputError(path, "--baud",
                     "unsupported baud rate " + std::to_string(baud) + "; expected one of " + supportedBaudRates());
  fd_ = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0)
    throw InputError(path, "--device",
                     std::string("cannot open the glove's serial device: ") + std::strerror(errno) +
                         " (is the glove plugged in, and may this user open the device?)");
  termios settings{};
  if (::tcgetattr(fd_, &settings) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    throw InputError(path, "--device",
                     "not a serial device (" + reason + "); to play a recorded file, use --replay FILE");
  }
  ::cfmakeraw(&settings);
  settings.c_cflag |= CLOCAL | CREAD;
  settings.c_cflag &= ~static_cast<tcflag_t>(CRTSCTS | CSTOPB | PARENB);
  settings.c_cc[VMIN] = 0;
  settings.c_cc[VTIME] = 0;
  ::cfsetispeed(&settings, speedOf(baud));
  ::cfsetospeed(&settings, speedOf(baud));
  if (::tcsetattr(fd_, TCSANOW, &settings) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    throw InputError(path, "--baud", "cannot set the line to " + std::to_string(baud) + " baud, raw: " + reason);
  }
  ::tcflush(fd_, TCIFLUSH);  // bytes from before we opened belong to no request of ours
}

GloveSerialDevice::~GloveSerialDevice() {
  if (fd_ >= 0) ::close(fd_);
}

GloveSerialDevice::Read GloveSerialDevice::read(std::string& bytes, int timeoutMs, std::string& reason) {
  pollfd watch{fd_, POLLIN, 0};
  const int ready = ::poll(&watch, 1, timeoutMs);
  if (ready < 0) {
    if (errno == EINTR) return Read::Interrupted;
    reason = std::string("poll failed: ") + std::strerror(errno);
    return Read::Closed;
  }
  if (ready == 0) return Read::Timeout;
  char buffer[4096];
  bool any = false;
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n > 0) {
      bytes.append(buffer, static_cast<std::size_t>(n));
      any = true;
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    // What was read before the end still counts; the end shows on the next call.
    if (any) return Read::Data;
    reason = n == 0 ? "end of file" : std::string(std::strerror(errno));
    return Read::Closed;
  }
  if (any) return Read::Data;
  if (watch.revents & (POLLHUP | POLLERR | POLLNVAL)) {
    reason = "hang-up";
    return Read::Closed;
  }
  return Read::Timeout;
}

void GloveSerialDevice::requestSample() {
  const char request = 'G';
  [[maybe_unused]] const ssize_t n = ::write(fd_, &request, 1);
}

}  // namespace pmdplan
