#include "pmdplan/core/atomic_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstring>
#include <functional>
#include <mutex>
#include <random>
#include <string>

#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

namespace fs = std::filesystem;

// Temporary files being written, for the signal handler to remove. Fixed slots: the handler may
// only read plain memory and call unlink.
constexpr std::size_t kPendingSlots = 64;
std::array<std::array<char, PATH_MAX>, kPendingSlots> pendingPaths{};
std::array<std::atomic<bool>, kPendingSlots> pendingUsed{};
std::mutex pendingMutex;
thread_local StagedOutputs* currentStagedOutputs = nullptr;

extern "C" void removePendingAndReraise(int signal) {
  for (std::size_t i = 0; i < kPendingSlots; ++i)
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

/// Registers a temporary file for removal on a signal; -1 when every slot is taken.
int registerPending(const std::string& path) {
  std::lock_guard lock(pendingMutex);
  for (std::size_t i = 0; i < kPendingSlots && !path.empty() && path.size() < PATH_MAX; ++i) {
    if (pendingUsed[i].load()) continue;
    std::memcpy(pendingPaths[i].data(), path.c_str(), path.size() + 1);
    pendingUsed[i].store(true);
    return static_cast<int>(i);
  }
  return -1;
}

void releasePending(int slot) {
  if (slot >= 0) pendingUsed[static_cast<std::size_t>(slot)].store(false);
}

std::string temporaryPrefix(const fs::path& target) {
  std::string prefix(1, '.');  // built by appending: GCC 12 warns falsely on "." + string
  prefix.append(target.filename().string().substr(0, kTemporaryNameBytes)).append(".pmdplan-");
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
  checkOutputNameLength(path, option);
  const fs::path target = resolvedTarget(path);
  checkOutputNameLength(target, option);
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

/// Refuses to replace an input of the command (the last line of defence behind checkOutputPath).
void refuseReplacingInput(const fs::path& path, const fs::path& target, const std::string& option) {
  if (const auto input = recordedInputAt(target))
    throw InputError(path.string(), option,
                     "is also an input of this command (" + input->string() +
                         "); pmdplan never replaces its inputs: write the output to another file");
}

/// Six random letters and digits for a temporary file's name.
std::string randomSuffix() {
  static constexpr char kLetters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  thread_local std::mt19937_64 random(
      std::random_device{}() ^ static_cast<std::uint64_t>(::getpid()) ^
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()));
  std::string suffix(6, 'x');
  for (char& c : suffix) c = kLetters[random() % (sizeof kLetters - 1)];
  return suffix;
}

/// Writes `content` to a new temporary file beside `target` and flushes it to disk.
StagedOutputs::Staged stageFile(const fs::path& path, std::string_view content) {
  const fs::path target = checkedTarget(path, "output");
  refuseReplacingInput(path, target, "output");
  if (!recordWrittenFile(target, std::hash<std::string_view>{}(content)))
    throw InputError(path.string(), "output",
                     "is written twice by this command (two outputs name one file); give each output its own file");
  installCleanupHandlers();
  removeStaleTemporaries(target);
  const std::string prefix =
      (target.parent_path() / (temporaryPrefix(target) + std::to_string(::getpid()) + "-")).string();
  // The signals wait while the file is created and registered, so the handler always knows it.
  sigset_t cleanupSignals, previous;
  sigemptyset(&cleanupSignals);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&cleanupSignals, signal);
  ::pthread_sigmask(SIG_BLOCK, &cleanupSignals, &previous);
  StagedOutputs::Staged staged{path, target, std::string(), -1};
  int fd = -1, createError = 0;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    staged.temporary = prefix + randomSuffix();
    // Mode 0666: the kernel takes the umask off, as for any new file.
    fd = ::open(staged.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    createError = errno;
    if (fd < 0 && createError != EEXIST) break;
  }
  if (fd >= 0) staged.slot = registerPending(staged.temporary);
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (fd < 0) failWrite(path, "cannot create a file in " + target.parent_path().string(), createError);
  const auto abandon = [&](const std::string& what, int error) {
    ::close(fd);
    ::unlink(staged.temporary.c_str());
    releasePending(staged.slot);
    failWrite(path, what, error);
  };
  keepOwnerAndMode(fd, target);
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) abandon("write failed", errno);
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) abandon("write failed", errno);
  if (::close(fd) != 0) {
    fd = -1;
    const int err = errno;
    ::unlink(staged.temporary.c_str());
    releasePending(staged.slot);
    failWrite(path, "write failed", err);
  }
  return staged;
}

void discardStaged(StagedOutputs::Staged& staged) {
  if (staged.temporary.empty()) return;
  ::unlink(staged.temporary.c_str());
  releasePending(staged.slot);
  staged.temporary.clear();
}

void renameStaged(StagedOutputs::Staged& staged) {
  if (std::rename(staged.temporary.c_str(), staged.target.c_str()) != 0) {
    const int err = errno;
    discardStaged(staged);
    failWrite(staged.path, "cannot replace the file", err);
  }
  releasePending(staged.slot);
  staged.temporary.clear();
}

}  // namespace

void checkOutputNameLength(const fs::path& path, const std::string& option) {
  const std::size_t name = path.filename().string().size();
  if (name > kMaxOutputNameBytes)
    throw InputError(path.string(), option,
                     "the file name is " + std::to_string(name) + " bytes long; a file name may have at most " +
                         std::to_string(kMaxOutputNameBytes) + " bytes");
  std::error_code error;
  const std::size_t whole = fs::absolute(path, error).string().size();
  if (whole >= PATH_MAX)
    throw InputError(path.string(), option,
                     "the path is " + std::to_string(whole) + " bytes long; a path must be shorter than " +
                         std::to_string(PATH_MAX) + " bytes");
}

void checkOutputPath(const fs::path& path, const std::string& option, std::initializer_list<fs::path> inputs) {
  const fs::path target = checkedTarget(path, option);
  for (const fs::path& input : inputs) {
    std::error_code error;
    if (!input.empty() && fs::equivalent(target, input, error))
      throw InputError(path.string(), option,
                       "is also an input of this command (" + input.string() + "); write the output to another file");
  }
  refuseReplacingInput(path, target, option);
  if (const auto other = claimOutputFile(target, option))
    throw InputError(path.string(), option, "is also the output of " + *other + "; give each output its own file");
}

void createOutputFolder(const fs::path& directory, const std::string& option) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory))
    throw InputError(directory.string(), option,
                     "cannot create the folder" + (error ? ": " + error.message() : std::string()));
}

void writeFileAtomically(const fs::path& path, std::string_view content) {
  StagedOutputs::Staged staged = stageFile(path, content);
  if (currentStagedOutputs) {
    currentStagedOutputs->add(std::move(staged));
    return;
  }
  renameStaged(staged);
}

/// Gives the new file `fd` the owner, group and mode of the file it replaces, as far as the process
/// may; when the group cannot be kept, the group's permissions are dropped rather than granted to
/// another group.
void keepOwnerAndMode(int fd, const fs::path& target) {
  struct stat old {};
  if (::stat(target.c_str(), &old) != 0) return;  // a new file: 0666 less the umask, from open()
  mode_t mode = old.st_mode & 0777;
  if (old.st_uid != ::geteuid() || old.st_gid != ::getegid()) {
    if (::fchown(fd, old.st_uid, old.st_gid) != 0 && ::fchown(fd, static_cast<uid_t>(-1), old.st_gid) != 0)
      mode &= ~static_cast<mode_t>(S_IRWXG);
  }
  ::fchmod(fd, mode);
}

StagedOutputs::StagedOutputs() : previous_(currentStagedOutputs) { currentStagedOutputs = this; }

StagedOutputs::~StagedOutputs() {
  currentStagedOutputs = previous_;
  for (Staged& staged : staged_) discardStaged(staged);
}

void StagedOutputs::add(Staged staged) { staged_.push_back(std::move(staged)); }

void StagedOutputs::commit() {
  for (Staged& staged : staged_) renameStaged(staged);
  staged_.clear();
}

std::string readTextFile(const fs::path& path) {
  // O_NONBLOCK: opening a named FIFO nobody writes to returns at once instead of waiting.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == EISDIR) throw InputError(path.string(), "", "is a folder; expected a file");
    throw InputError(path.string(), "", std::string("cannot open the file for reading: ") + std::strerror(errno));
  }
  const auto fail = [&](const std::string& message) {
    ::close(fd);
    throw InputError(path.string(), "", message);
  };
  struct stat status {};
  if (::fstat(fd, &status) != 0) fail(std::string("cannot read the file: ") + std::strerror(errno));
  if (S_ISDIR(status.st_mode)) fail("is a folder; expected a file");
  const bool pipe = S_ISFIFO(status.st_mode);
  if (!S_ISREG(status.st_mode) && !pipe)
    fail("is not a regular file (a device or socket); pmdplan reads regular files and pipes");
  if (!pipe) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  recordInputFile(path);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN && pipe) {  // a writer that has not written yet: wait for it
      struct pollfd wait {
        fd, POLLIN, 0
      };
      if (::poll(&wait, 1, -1) < 0 && errno != EINTR) fail(std::string("read failed: ") + std::strerror(errno));
      continue;
    }
    if (n < 0) fail(std::string("read failed: ") + std::strerror(errno));
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > kMaxInputFileBytes)
      fail("longer than " + std::to_string(kMaxInputFileBytes >> 20) + " MiB, the largest input pmdplan reads");
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  if (pipe && text.empty())
    throw InputError(path.string(), "",
                     "is a pipe with nothing in it (a named FIFO nobody writes to?); pmdplan reads regular files and "
                     "pipes with a writer");
  return text;
}

}  // namespace pmdplan
