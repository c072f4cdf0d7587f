#pragma once
// The files one command reads and writes, so that no output replaces an input or another output
// (docs/robustness.md, "Outputs"). The CLI's main opens a CommandFileScope around the command, and
// Python calls that write files open one around the call. While a scope is open, readTextFile and
// the mesh reader record every file they read, checkOutputPath records every output it checks,
// and writeFileAtomically refuses to replace a recorded input or to write one file twice.
//
// Two names are the same file when they reach one file (device and inode: hard links and
// symbolic links count) or, for a file not there yet, when their normalised absolute paths
// (symbolic links resolved) are equal. Outside a scope nothing is recorded (library use, tests).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace pmdplan {

/// Opens the record of one command's files; scopes nest (the outermost one holds the record) and
/// may be opened by several threads at once (they then share one record).
class CommandFileScope {
 public:
  CommandFileScope();
  ~CommandFileScope();
  CommandFileScope(const CommandFileScope&) = delete;
  CommandFileScope& operator=(const CommandFileScope&) = delete;
};

/// Records `path` as read by the command; nothing outside a scope or when it cannot be found.
void recordInputFile(const std::filesystem::path& path);

/// The recorded input (as the command named it) that `target` is; none if it is no input or the
/// command may replace it (permitReplacingInput).
std::optional<std::filesystem::path> recordedInputAt(const std::filesystem::path& target);

/// Lets the command replace the input `path` on purpose (`collision-pairs` regenerates the SRDF it
/// reads).
void permitReplacingInput(const std::filesystem::path& path);

/// Records `target` as the output of `option`; returns the option of an earlier output of another
/// option that is the same file (the same option may check its file twice).
std::optional<std::string> claimOutputFile(const std::filesystem::path& target, const std::string& option);

/// Records `target` as written with content of hash `contentHash`; false if the command already
/// wrote other content to that file (writing the same bytes twice, as one mesh for two links, is
/// no loss).
bool recordWrittenFile(const std::filesystem::path& target, std::size_t contentHash);

}  // namespace pmdplan
