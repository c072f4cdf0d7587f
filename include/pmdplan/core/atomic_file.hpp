#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so a reader
// never sees half a file and a failed run never corrupts an earlier result.
//
// The rules for an output path (docs/robustness.md, "Outputs"): its folder must exist; its file
// name is at most kMaxOutputNameBytes bytes and the whole path shorter than PATH_MAX; a symbolic
// link is followed and the file it points to is replaced (the link stays); anything that exists
// and is not a regular file (a device such as /dev/null, a folder, a pipe) is refused; an output
// may not be an input of the command nor another of its outputs (command_files.hpp). A new output
// gets the mode 0666 less the umask; a replaced file keeps its mode (and, where the process may,
// its owner and group). The temporary file is `.NAME.pmdplan-PID-XXXXXX` (NAME cut to
// kTemporaryNameBytes bytes): it is removed when the write fails, when the process ends on SIGINT,
// SIGTERM or SIGHUP, and, if the process was killed outright, by the next write of the same output
// once that process is gone.
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace pmdplan {

/// The largest file pmdplan reads (128 MiB); a longer input (or an endless one such as
/// /dev/zero) is an InputError, so memory never grows past what a real input needs.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{128} << 20;

/// The longest output file name (255 bytes, Linux's NAME_MAX), checked before the work.
inline constexpr std::size_t kMaxOutputNameBytes = 255;

/// How much of an output's name its temporary file's name keeps (64 bytes), so that the temporary
/// name fits in kMaxOutputNameBytes whatever the output's name.
inline constexpr std::size_t kTemporaryNameBytes = 64;

/// Checks that `path` can be written under the rules above, before any work is done: against
/// `inputs`, the inputs the command has read so far and the outputs it checked before (under
/// another option). Throws InputError naming the path (field `option`).
void checkOutputPath(const std::filesystem::path& path, const std::string& option,
                     std::initializer_list<std::filesystem::path> inputs = {});

/// Checks the length of `path`'s file name and of the whole path (the rule above); throws
/// InputError naming it (field `option`).
void checkOutputNameLength(const std::filesystem::path& path, const std::string& option);

/// Creates the folder `directory` (and its parents) for outputs; throws InputError naming it
/// (field `option`) when it cannot be made, say because a file is in the way.
void createOutputFolder(const std::filesystem::path& directory, const std::string& option);

/// Writes `content` to `path` atomically; throws InputError naming the path when the path breaks
/// the rules above or the write fails (full disk, no permission). While a StagedOutputs is alive
/// in this thread, the file is written and flushed but only renamed by its commit().
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

/// Gives the new file `fd`, created with mode 0666 (the kernel takes the umask off), the owner,
/// group and permission bits of `target` if it exists, as far as the process may (a group that
/// cannot be kept loses its permissions rather than passing them to another group). For writers
/// that create their own file.
void keepOwnerAndMode(int fd, const std::filesystem::path& target);

/// A command's outputs written together: while one is alive, writeFileAtomically (in this thread)
/// writes and flushes each output to its temporary file and commit() renames them all, so no
/// output is renamed unless every one was written. Without commit() (a failed write, any
/// exception) the temporary files are removed and every target stays as it was.
class StagedOutputs {
 public:
  StagedOutputs();
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs&) = delete;
  StagedOutputs& operator=(const StagedOutputs&) = delete;

  /// Renames every staged file over its target, in the order they were written.
  void commit();

  struct Staged {
    std::filesystem::path path;    ///< as the command named it
    std::filesystem::path target;  ///< the file replaced (symbolic links followed)
    std::string temporary;
    int slot = -1;  ///< its place in the signal handler's list
  };
  void add(Staged staged);

 private:
  std::vector<Staged> staged_;
  StagedOutputs* previous_;
};

/// Reads a whole file; throws InputError naming the path if it cannot be read, is longer than
/// kMaxInputFileBytes, or is neither a regular file nor a pipe with a writer (a named FIFO nobody
/// writes to is refused at once rather than waited on; a device is refused). Records the file as an
/// input of the command (command_files.hpp).
std::string readTextFile(const std::filesystem::path& path);

}  // namespace pmdplan
