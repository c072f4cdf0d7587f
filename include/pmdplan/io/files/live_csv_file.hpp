#pragma once
// A CSV output written while a live stream runs, where an atomic write at the end would lose
// everything to a crash: rows go, one whole line per write, to NAME.partial beside the target, and
// a clean end (the stream's end, Ctrl-C, an unplugged device) renames it over the target. A run
// that is killed outright leaves NAME.partial with every row written so far; a run with no rows
// removes it and leaves the target as it was.
//
// NAME.partial is the recovery file of an earlier run that was killed: it is never overwritten (an
// existing one is refused before the work), and it is created afresh (O_EXCL | O_NOFOLLOW: never
// through a symbolic link, never into a FIFO), with the mode of the target it will replace (or
// 0666 less the umask). A write that fails (a full disk) is cut back to the last whole row, so the
// file kept always ends in a complete row.
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace pmdplan {

class LiveCsvFile {
 public:
  /// Checks `target` as an output of `option` before the work: the rules of checkOutputPath
  /// (`inputs` may not be it), and no NAME.partial beside it. Throws InputError.
  static void checkTarget(const std::filesystem::path& target, const std::string& option,
                          std::initializer_list<std::filesystem::path> inputs = {});

  /// Checks `target` (checkTarget), creates the partial file and writes the '#' note lines and the
  /// header.
  LiveCsvFile(std::filesystem::path target, const std::string& option, const std::vector<std::string>& notes,
              const std::string& header, std::initializer_list<std::filesystem::path> inputs = {});
  /// Without finish(): closes, and leaves the partial file if it holds rows (removes it if not).
  ~LiveCsvFile();
  LiveCsvFile(const LiveCsvFile&) = delete;
  LiveCsvFile& operator=(const LiveCsvFile&) = delete;

  /// Appends one line (without its newline) in one write. Throws InputError naming the partial
  /// file when the write fails (a full disk), after cutting the file back to its last whole row.
  void addRow(const std::string& row);
  /// Renames the partial file over the target and returns the rows written; with no rows,
  /// removes it and returns 0.
  long long finish();

  long long rows() const { return rows_; }
  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& partial() const { return partial_; }

 private:
  /// Writes `text` whole, or cuts the file back to `committed_` and returns the error (errno).
  int append(const std::string& text);

  std::filesystem::path target_;
  std::filesystem::path partial_;
  int fd_ = -1;
  long long rows_ = 0;
  long long committed_ = 0;  ///< bytes of whole lines in the file
};

}  // namespace pmdplan
