#pragma once
// Shared by the libFuzzer harnesses: each feeds one parser arbitrary bytes. The parser may accept
// them or throw InputError (bad input: exit 2); anything else — another exception, a crash, a
// sanitizer report, a hang — is a bug the fuzzer reports.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "pmdplan/core/input_error.hpp"

namespace pmdplan::fuzz {

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// A per-process scratch folder for parsers that read files (task, URDF + SRDF).
inline const std::filesystem::path& scratchDirectory() {
  static const std::filesystem::path dir = [] {
    auto path = std::filesystem::temp_directory_path() / ("pmdplan-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return dir;
}

inline std::filesystem::path writeScratch(const std::string& name, std::string_view text) {
  const auto path = scratchDirectory() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
  return path;
}

/// Runs `parse`; InputError is the expected way to refuse an input.
template <typename Parse>
int expectAcceptedOrInputError(Parse&& parse) {
  try {
    parse();
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace pmdplan::fuzz
