#pragma once
// Outputs are written to a temporary file beside the target and renamed over it, so a reader
// never sees half a file and a failed run never corrupts an earlier result.
#include <filesystem>
#include <string_view>

namespace pmdplan {

/// Writes `content` to `path` atomically; throws std::runtime_error naming the path on failure.
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

/// Reads a whole file; throws InputError naming the path if it cannot be read.
std::string readTextFile(const std::filesystem::path& path);

}  // namespace pmdplan
