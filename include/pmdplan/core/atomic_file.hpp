#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so a reader
// never sees half a file and a failed run never corrupts an earlier result.
//
// The rules for an output path (docs/robustness.md): its folder must exist; a symbolic link is
// followed and the file it points to is replaced (the link stays); anything that exists and is
// not a regular file (a device such as /dev/null, a folder, a pipe) is refused; an output may not
// be one of the command's inputs. The temporary file is `.NAME.pmdplan-PID-XXXXXX`: it is removed
// when the write fails, when the process ends on SIGINT, SIGTERM or SIGHUP, and, if the process
// was killed outright, by the next write of the same output once that process is gone.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace pmdplan {

/// The largest file pmdplan reads (128 MiB); a longer input (or an endless one such as
/// /dev/zero) is an InputError, so memory never grows past what a real input needs.
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{128} << 20;

/// Checks that `path` can be written under the rules above, before any work is done; `inputs`
/// are the files the command reads. Throws InputError naming the path (field `option`).
void checkOutputPath(const std::filesystem::path& path, const std::string& option,
                     std::initializer_list<std::filesystem::path> inputs = {});

/// Creates the folder `directory` (and its parents) for outputs; throws InputError naming it
/// (field `option`) when it cannot be made, say because a file is in the way.
void createOutputFolder(const std::filesystem::path& directory, const std::string& option);

/// Writes `content` to `path` atomically; throws InputError naming the path when the path breaks
/// the rules above or the write fails (full disk, no permission).
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

/// Reads a whole file; throws InputError naming the path if it cannot be read or is longer than
/// kMaxInputFileBytes.
std::string readTextFile(const std::filesystem::path& path);

}  // namespace pmdplan
