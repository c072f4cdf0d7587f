#pragma once
// The one rule by which pmdplan's HTTP servers turn a request target into a file: percent-decode,
// refuse control bytes, join to the served root, resolve every symbolic link, and serve only a
// regular file whose resolved path lies inside the resolved root and has no hidden component
// (a name starting with '.', such as the atomic writer's temporaries). Everything else is refused;
// nothing here throws for any target.
#include <cstdint>
#include <filesystem>
#include <string>

namespace pmdplan {

enum class ServedPathStatus {
  Found,       // `file` is open for reading
  BadRequest,  // not an origin-form path, a bad %-escape, or a control byte (NUL included): 400
  Forbidden,   // a hidden component or a parent step ("..") in the path as asked: 403
  NotFound,    // missing, not a regular file, unreadable, or resolving outside the root: 404
};

/// A file opened for serving; closes it when destroyed.
class ServedFile {
 public:
  ServedFile() = default;
  ~ServedFile();
  ServedFile(ServedFile&& other) noexcept;
  ServedFile& operator=(ServedFile&& other) noexcept;
  ServedFile(const ServedFile&) = delete;
  ServedFile& operator=(const ServedFile&) = delete;

  ServedPathStatus status = ServedPathStatus::NotFound;
  /// The decoded path asked for, relative to the root ("a b/c.js"; "index.html" for "/"), for messages.
  std::string relative;
  /// The resolved file, inside the resolved root (Found only).
  std::filesystem::path resolved;
  /// Its descriptor, open for reading, and its size in bytes (Found only).
  int descriptor = -1;
  std::uintmax_t size = 0;
};

/// "/a%20b/c.js?x" -> "/a b/c.js"; false for a bad %-escape or a decoded control byte (below 0x20,
/// or 0x7f).
bool percentDecodePath(const std::string& target, std::string& decoded);

/// True if `resolved` is `root` or lies below it (both already canonical).
bool liesInside(const std::filesystem::path& resolved, const std::filesystem::path& root);

/// Applies the rule of this header to `target` (the request line's second word) under `root`.
ServedFile openServedFile(const std::filesystem::path& root, const std::string& target);

}  // namespace pmdplan
