#include "pmdplan/core/command_files.hpp"

#include <sys/stat.h>

#include <mutex>
#include <vector>

namespace pmdplan {
namespace {

namespace fs = std::filesystem;

/// What makes two names the same file: the file itself if it exists, else its normalised path.
struct CommandFileKey {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string normal;
};

CommandFileKey commandFileKey(const fs::path& path) {
  CommandFileKey key;
  struct stat status {};
  if (::stat(path.c_str(), &status) == 0) {
    key.exists = true;
    key.device = status.st_dev;
    key.inode = status.st_ino;
  }
  std::error_code error;
  fs::path absolute = fs::absolute(path, error);
  if (error) absolute = path;
  const fs::path normal = fs::weakly_canonical(absolute, error);
  key.normal = (error ? absolute.lexically_normal() : normal).string();
  return key;
}

bool sameCommandFile(const CommandFileKey& a, const CommandFileKey& b) {
  return (a.exists && b.exists && a.device == b.device && a.inode == b.inode) || a.normal == b.normal;
}

struct NamedFile {
  CommandFileKey key;
  std::string name;  // the input's path as given, the output's option, or a written content's hash
};

struct CommandFileRecord {
  int depth = 0;
  std::vector<NamedFile> inputs, permitted, claims, written;
};

std::mutex commandRecordMutex;
CommandFileRecord commandRecord;

const NamedFile* findCommandFile(const std::vector<NamedFile>& list, const CommandFileKey& key) {
  for (const NamedFile& entry : list)
    if (sameCommandFile(entry.key, key)) return &entry;
  return nullptr;
}

}  // namespace

CommandFileScope::CommandFileScope() {
  const std::lock_guard lock(commandRecordMutex);
  ++commandRecord.depth;
}

CommandFileScope::~CommandFileScope() {
  const std::lock_guard lock(commandRecordMutex);
  if (--commandRecord.depth == 0) commandRecord = CommandFileRecord{};
}

void recordInputFile(const fs::path& path) {
  {
    const std::lock_guard lock(commandRecordMutex);
    if (commandRecord.depth == 0) return;
  }
  CommandFileKey key = commandFileKey(path);  // outside the lock: stat may be slow
  if (!key.exists) return;
  const std::lock_guard lock(commandRecordMutex);
  if (commandRecord.depth > 0 && !findCommandFile(commandRecord.inputs, key))
    commandRecord.inputs.push_back({std::move(key), path.string()});
}

std::optional<fs::path> recordedInputAt(const fs::path& target) {
  const CommandFileKey key = commandFileKey(target);
  const std::lock_guard lock(commandRecordMutex);
  if (findCommandFile(commandRecord.permitted, key)) return std::nullopt;
  for (const NamedFile& input : commandRecord.inputs) {
    if (!sameCommandFile(input.key, key)) continue;
    // An input removed since (a scratch file) frees its inode for a new file: it counts only while
    // its own name still reaches that file.
    const CommandFileKey now = commandFileKey(input.name);
    if (input.key.normal == key.normal || (now.exists && now.device == key.device && now.inode == key.inode))
      return fs::path(input.name);
  }
  return std::nullopt;
}

void permitReplacingInput(const fs::path& path) {
  CommandFileKey key = commandFileKey(path);
  const std::lock_guard lock(commandRecordMutex);
  if (commandRecord.depth > 0) commandRecord.permitted.push_back({std::move(key), path.string()});
}

std::optional<std::string> claimOutputFile(const fs::path& target, const std::string& option) {
  CommandFileKey key = commandFileKey(target);
  const std::lock_guard lock(commandRecordMutex);
  if (commandRecord.depth == 0) return std::nullopt;
  for (const NamedFile& claim : commandRecord.claims)
    if (sameCommandFile(claim.key, key) && claim.name != option) return claim.name;
  commandRecord.claims.push_back({std::move(key), option});
  return std::nullopt;
}

bool recordWrittenFile(const fs::path& target, std::size_t contentHash) {
  CommandFileKey key = commandFileKey(target);
  const std::string hash = std::to_string(contentHash);
  const std::lock_guard lock(commandRecordMutex);
  if (commandRecord.depth == 0) return true;
  // By path only: a file written and renamed frees the inode of the one it replaced for a new file.
  for (const NamedFile& earlier : commandRecord.written)
    if (earlier.key.normal == key.normal) return earlier.name == hash;
  commandRecord.written.push_back({std::move(key), hash});
  return true;
}

}  // namespace pmdplan
