#include "pmdplan/io/files/live_csv_file.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>

#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

LiveCsvFile::LiveCsvFile(std::filesystem::path target, const std::string& option, const std::vector<std::string>& notes,
                         const std::string& header, std::initializer_list<std::filesystem::path> inputs)
    : target_(std::move(target)) {
  checkOutputPath(target_, option, inputs);
  if (std::filesystem::is_symlink(target_))
    target_ = std::filesystem::canonical(target_);  // the link stays, as for atomic writes
  partial_ = target_;
  partial_ += ".partial";
  file_ = std::fopen(partial_.c_str(), "w");
  if (!file_)
    throw InputError(partial_.string(), option, std::string("cannot write the recording: ") + std::strerror(errno));
  std::string head;
  for (const auto& note : notes) head += "# " + note + "\n";
  head += header + "\n";
  if (std::fputs(head.c_str(), file_) < 0 || std::fflush(file_) != 0)
    throw InputError(partial_.string(), option, std::string("cannot write the recording: ") + std::strerror(errno));
}

LiveCsvFile::~LiveCsvFile() {
  if (!file_) return;
  std::fclose(file_);
  std::error_code ignored;
  if (rows_ == 0) std::filesystem::remove(partial_, ignored);
}

void LiveCsvFile::addRow(const std::string& row) {
  if (std::fputs(row.c_str(), file_) < 0 || std::fputc('\n', file_) == EOF || std::fflush(file_) != 0)
    throw InputError(partial_.string(), "row " + std::to_string(rows_ + 1),
                     std::string("cannot write the recording: ") + std::strerror(errno));
  ++rows_;
}

long long LiveCsvFile::finish() {
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
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
