#pragma once
// A CSV output written while a live stream runs, where an atomic write at the end would lose
// everything to a crash: rows go, one flushed line each, to NAME.partial beside the target, and a
// clean end (the stream's end, Ctrl-C, an unplugged device) renames it over the target. A run that
// is killed outright leaves NAME.partial with every row written so far; a run with no rows
// removes it and leaves the target as it was.
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace pmdplan {

class LiveCsvFile {
 public:
  /// Checks `target` like any output (checkOutputPath, field `option`; `inputs` may not be it),
  /// opens the partial file and writes the '#' note lines and the header.
  LiveCsvFile(std::filesystem::path target, const std::string& option, const std::vector<std::string>& notes,
              const std::string& header, std::initializer_list<std::filesystem::path> inputs = {});
  /// Without finish(): closes, and leaves the partial file if it holds rows (removes it if not).
  ~LiveCsvFile();
  LiveCsvFile(const LiveCsvFile&) = delete;
  LiveCsvFile& operator=(const LiveCsvFile&) = delete;

  /// Appends one line (without its newline) and flushes it. Throws InputError naming the
  /// partial file when the write fails (a full disk).
  void addRow(const std::string& row);
  /// Renames the partial file over the target and returns the rows written; with no rows,
  /// removes it and returns 0.
  long long finish();

  long long rows() const { return rows_; }
  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& partial() const { return partial_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path partial_;
  std::FILE* file_ = nullptr;
  long long rows_ = 0;
};

}  // namespace pmdplan
