#include "pmdplan/io/files/live_csv_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/command_files.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {
namespace {

/// The file the recording replaces (a symbolic link is written through, as for atomic writes).
std::filesystem::path liveTarget(const std::filesystem::path& target) {
  std::error_code error;
  if (std::filesystem::is_symlink(target, error)) {
    const auto resolved = std::filesystem::canonical(target, error);
    if (!error) return resolved;
  }
  return target;
}

std::filesystem::path partialOf(const std::filesystem::path& target) {
  std::filesystem::path partial = target;
  partial += ".partial";
  return partial;
}

[[noreturn]] void refuseEarlierPartial(const std::filesystem::path& partial, const std::string& option) {
  throw InputError(partial.string(), option,
                   "holds an earlier recording (or is in the way); move it away, pmdplan does not overwrite it");
}

}  // namespace

void LiveCsvFile::checkTarget(const std::filesystem::path& target, const std::string& option,
                              std::initializer_list<std::filesystem::path> inputs) {
  checkOutputPath(target, option, inputs);
  const std::filesystem::path partial = partialOf(liveTarget(target));
  checkOutputNameLength(partial, option);
  struct stat status {};
  if (::lstat(partial.c_str(), &status) == 0) refuseEarlierPartial(partial, option);
  if (const auto other = claimOutputFile(partial, option + " (its .partial file)"))
    throw InputError(partial.string(), option, "is also the output of " + *other + "; give each output its own file");
}

LiveCsvFile::LiveCsvFile(std::filesystem::path target, const std::string& option, const std::vector<std::string>& notes,
                         const std::string& header, std::initializer_list<std::filesystem::path> inputs)
    : target_(std::move(target)) {
  checkTarget(target_, option, inputs);
  target_ = liveTarget(target_);
  partial_ = partialOf(target_);
  // O_EXCL | O_NOFOLLOW: a new file, never one that is there (a link, a FIFO, an earlier recording).
  fd_ = ::open(partial_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd_ < 0 && errno == EEXIST) refuseEarlierPartial(partial_, option);
  if (fd_ < 0)
    throw InputError(partial_.string(), option, std::string("cannot write the recording: ") + std::strerror(errno));
  keepOwnerAndMode(fd_, target_);
  std::string head;
  for (const auto& note : notes) head += "# " + note + "\n";
  head += header + "\n";
  if (const int error = append(head)) {
    ::close(fd_);
    fd_ = -1;
    ::unlink(partial_.c_str());
    throw InputError(partial_.string(), option, std::string("cannot write the recording: ") + std::strerror(error));
  }
}

LiveCsvFile::~LiveCsvFile() {
  if (fd_ < 0) return;
  ::close(fd_);
  if (rows_ == 0) ::unlink(partial_.c_str());
}

int LiveCsvFile::append(const std::string& text) {
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      // Half a row would make the file unreadable (pmdplan's own readers refuse it): cut it off.
      if (::ftruncate(fd_, static_cast<off_t>(committed_)) == 0) ::lseek(fd_, static_cast<off_t>(committed_), SEEK_SET);
      return error;
    }
    written += static_cast<std::size_t>(n);
  }
  committed_ += static_cast<long long>(text.size());
  return 0;
}

void LiveCsvFile::addRow(const std::string& row) {
  if (const int error = append(row + "\n"))
    throw InputError(partial_.string(), "row " + std::to_string(rows_ + 1),
                     std::string("cannot write the recording: ") + std::strerror(error));
  ++rows_;
}

long long LiveCsvFile::finish() {
  const bool closed = ::close(fd_) == 0;
  fd_ = -1;
  std::error_code error;
  if (rows_ == 0) {
    std::filesystem::remove(partial_, error);
    return 0;
  }
  if (!closed)
    throw InputError(partial_.string(), "",
                     "cannot finish the recording (closing it failed); its rows are in this file");
  std::filesystem::rename(partial_, target_, error);
  if (error)
    throw InputError(
        partial_.string(), "",
        "cannot rename the recording to " + target_.string() + ": " + error.message() + "; its rows are in this file");
  return rows_;
}

}  // namespace pmdplan
