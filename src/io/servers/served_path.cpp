#include "pmdplan/io/servers/served_path.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <system_error>
#include <utility>

namespace pmdplan {
namespace {

/// Longest name of one component and longest relative path looked up at all (Linux's NAME_MAX and
/// PATH_MAX): a longer one cannot name a file, so it is not found without asking the file system.
constexpr std::size_t kMaxServedNameBytes = 255;
constexpr std::size_t kMaxServedPathBytes = 4096;

int hexDigitValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool isControlByte(unsigned char c) { return c < 0x20 || c == 0x7f; }

}  // namespace

ServedFile::~ServedFile() {
  if (descriptor >= 0) ::close(descriptor);
}

ServedFile::ServedFile(ServedFile&& other) noexcept
    : status(other.status),
      relative(std::move(other.relative)),
      resolved(std::move(other.resolved)),
      descriptor(std::exchange(other.descriptor, -1)),
      size(other.size) {}

ServedFile& ServedFile::operator=(ServedFile&& other) noexcept {
  if (this != &other) {
    if (descriptor >= 0) ::close(descriptor);
    status = other.status;
    relative = std::move(other.relative);
    resolved = std::move(other.resolved);
    descriptor = std::exchange(other.descriptor, -1);
    size = other.size;
  }
  return *this;
}

bool percentDecodePath(const std::string& target, std::string& decoded) {
  decoded.clear();
  decoded.reserve(target.size());
  for (std::size_t i = 0; i < target.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(target[i]);
    if (c == '%') {
      if (i + 2 >= target.size()) return false;
      const int high = hexDigitValue(target[i + 1]);
      const int low = hexDigitValue(target[i + 2]);
      if (high < 0 || low < 0) return false;
      c = static_cast<unsigned char>(high * 16 + low);
      i += 2;
    }
    if (isControlByte(c)) return false;
    decoded += static_cast<char>(c);
  }
  return true;
}

bool liesInside(const std::filesystem::path& resolved, const std::filesystem::path& root) {
  auto r = resolved.begin();
  for (auto part = root.begin(); part != root.end(); ++part, ++r) {
    if (r == resolved.end() || *r != *part) return false;
  }
  return true;
}

ServedFile openServedFile(const std::filesystem::path& root, const std::string& target) {
  ServedFile file;
  file.status = ServedPathStatus::BadRequest;
  const std::string path = target.substr(0, target.find_first_of("?#"));
  if (path.empty() || path.front() != '/') return file;  // origin form only ("http://host/x" is a proxy's)
  std::string decoded;
  if (!percentDecodePath(path, decoded)) return file;

  // The components, relative to the root: doubled slashes merged (so "//etc" is "etc" of the root,
  // never the absolute /etc); no parent step and no hidden name in what was asked.
  std::string relative;
  bool tooLong = false;
  for (std::size_t start = 0; start < decoded.size();) {
    const std::size_t end = std::min(decoded.find('/', start), decoded.size());
    const std::string part = decoded.substr(start, end - start);
    start = end + 1;
    if (part.empty()) continue;
    if (part.front() == '.') {
      file.status = ServedPathStatus::Forbidden;
      return file;
    }
    tooLong = tooLong || part.size() > kMaxServedNameBytes;
    relative += (relative.empty() ? "" : "/") + part;
  }
  if (relative.empty() || decoded.back() == '/') relative += relative.empty() ? "index.html" : "/index.html";
  file.status = ServedPathStatus::NotFound;
  file.relative = relative;
  if (tooLong || relative.size() > kMaxServedPathBytes) return file;

  // Resolved, every symbolic link followed, the file must still lie inside the resolved root.
  std::error_code error;
  const std::filesystem::path canonicalRoot = std::filesystem::canonical(root, error);
  if (error) return file;
  const std::filesystem::path resolved = std::filesystem::canonical(canonicalRoot / relative, error);
  if (error || !liesInside(resolved, canonicalRoot)) return file;
  for (const auto& part : resolved.lexically_relative(canonicalRoot))
    if (part.empty() || part.native().front() == '.') return file;

  // No following a link swapped in since, no waiting on a FIFO, nothing but a regular file.
  const int descriptor = ::open(resolved.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
  if (descriptor < 0) return file;
  struct stat info {};
  if (::fstat(descriptor, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(descriptor);
    return file;
  }
  file.status = ServedPathStatus::Found;
  file.resolved = resolved;
  file.descriptor = descriptor;
  file.size = static_cast<std::uintmax_t>(info.st_size);
  return file;
}

}  // namespace pmdplan
