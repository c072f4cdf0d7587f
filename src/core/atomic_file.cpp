#include "pmdplan/core/atomic_file.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

namespace fs = std::filesystem;

// Temporary files being written, for the signal handler to remove. Fixed slots: the handler may
// only read plain memory and call unlink.
constexpr std::size_t kSlots = 16;
std::array<std::array<char, PATH_MAX>, kSlots> pendingPaths{};
std::array<std::atomic<bool>, kSlots> pendingUsed{};
std::mutex pendingMutex;

extern "C" void removePendingAndReraise(int signal) {
  for (std::size_t i = 0; i < kSlots; ++i)
    if (pendingUsed[i].load()) ::unlink(pendingPaths[i].data());
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

void installCleanupHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction cleanup {};
      cleanup.sa_handler = removePendingAndReraise;
      sigemptyset(&cleanup.sa_mask);
      ::sigaction(signal, &cleanup, nullptr);
    }
  });
}

/// Registers a temporary file for removal on a signal while it exists.
class PendingTemporary {
 public:
  explicit PendingTemporary(const std::string& path) {
    std::lock_guard lock(pendingMutex);
    for (std::size_t i = 0; i < kSlots && !path.empty() && path.size() < PATH_MAX; ++i) {
      if (pendingUsed[i].load()) continue;
      std::memcpy(pendingPaths[i].data(), path.c_str(), path.size() + 1);
      pendingUsed[i].store(true);
      slot_ = static_cast<int>(i);
      return;
    }
  }
  ~PendingTemporary() {
    if (slot_ >= 0) pendingUsed[static_cast<std::size_t>(slot_)].store(false);
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

 private:
  int slot_ = -1;
};

std::string temporaryPrefix(const fs::path& target) {
  std::string prefix(1, '.');  // built by appending: GCC 12 warns falsely on "." + string
  prefix.append(target.filename().string()).append(".pmdplan-");
  return prefix;
}

/// Removes temporary files of `target` left by processes that no longer run (killed with SIGKILL).
void removeStaleTemporaries(const fs::path& target) {
  const std::string prefix = temporaryPrefix(target);
  std::error_code error;
  for (fs::directory_iterator it(target.parent_path(), error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const auto dash = rest.find('-');
    if (dash == std::string::npos || dash == 0) continue;
    long pid = 0;
    try {
      pid = std::stol(rest.substr(0, dash));
    } catch (const std::exception&) {
      continue;
    }
    if (pid > 0 && pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

/// The file a write to `path` replaces: symbolic links followed (at most 40, as the kernel does).
fs::path resolvedTarget(const fs::path& path) {
  fs::path target = path.has_parent_path() ? path : fs::path(".") / path;
  for (int hops = 0;; ++hops) {
    std::error_code error;
    if (!fs::is_symlink(fs::symlink_status(target, error))) return target;
    if (hops == 40) throw InputError(path.string(), "output", "too many levels of symbolic links");
    const fs::path link = fs::read_symlink(target, error);
    if (error) throw InputError(path.string(), "output", "cannot read the symbolic link: " + error.message());
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
}

[[noreturn]] void failWrite(const fs::path& path, const std::string& what, int error) {
  throw InputError(path.string(), "output", what + ": " + std::strerror(error));
}

fs::path checkedTarget(const fs::path& path, const std::string& option) {
  if (path.empty()) throw InputError("", option, "expected a file name, got an empty one");
  const fs::path target = resolvedTarget(path);
  std::error_code error;
  const fs::file_status status = fs::status(target, error);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(path.string(), option,
                     "exists and is not a regular file (a folder, device or pipe); pmdplan writes only regular files");
  const fs::path folder = target.parent_path();
  if (!fs::is_directory(folder, error))
    throw InputError(path.string(), option,
                     "the folder " + folder.string() + " does not exist (or is not a folder); create it first");
  if (::access(folder.c_str(), W_OK) != 0) failWrite(path, "cannot write into " + folder.string(), errno);
  return target;
}

}  // namespace

void checkOutputPath(const fs::path& path, const std::string& option, std::initializer_list<fs::path> inputs) {
  const fs::path target = checkedTarget(path, option);
  for (const fs::path& input : inputs) {
    std::error_code error;
    if (!input.empty() && fs::equivalent(target, input, error))
      throw InputError(path.string(), option,
                       "is also an input of this command (" + input.string() + "); write the output to another file");
  }
}

void createOutputFolder(const fs::path& directory, const std::string& option) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory))
    throw InputError(directory.string(), option,
                     "cannot create the folder" + (error ? ": " + error.message() : std::string()));
}

void writeFileAtomically(const fs::path& path, std::string_view content) {
  const fs::path target = checkedTarget(path, "output");
  installCleanupHandlers();
  removeStaleTemporaries(target);
  std::string pattern =
      (target.parent_path() / (temporaryPrefix(target) + std::to_string(::getpid()) + "-XXXXXX")).string();
  // The signals wait while the file is created and registered, so the handler always knows it.
  sigset_t cleanupSignals, previous;
  sigemptyset(&cleanupSignals);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&cleanupSignals, signal);
  ::pthread_sigmask(SIG_BLOCK, &cleanupSignals, &previous);
  const int fd = ::mkstemp(pattern.data());
  const int createError = errno;
  const PendingTemporary pending(fd >= 0 ? pattern : std::string());
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (fd < 0) failWrite(path, "cannot create a file in " + target.parent_path().string(), createError);
  const auto abandon = [&](const std::string& what, int error) {
    ::close(fd);
    ::unlink(pattern.c_str());
    failWrite(path, what, error);
  };
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) abandon("write failed", errno);
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) abandon("write failed", errno);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(pattern.c_str());
    failWrite(path, "write failed", err);
  }
  ::chmod(pattern.c_str(), 0644);
  if (std::rename(pattern.c_str(), target.c_str()) != 0) {
    const int err = errno;
    ::unlink(pattern.c_str());
    failWrite(path, "cannot replace the file", err);
  }
}

std::string readTextFile(const fs::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) throw InputError(path.string(), "", "is a folder; expected a file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw InputError(path.string(), "", std::string("cannot open the file for reading: ") + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw InputError(path.string(), "", std::string("read failed: ") + std::strerror(err));
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > kMaxInputFileBytes) {
      ::close(fd);
      throw InputError(
          path.string(), "",
          "longer than " + std::to_string(kMaxInputFileBytes >> 20) + " MiB, the largest input pmdplan reads");
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

}  // namespace pmdplan
