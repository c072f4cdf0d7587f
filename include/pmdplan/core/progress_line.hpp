#pragma once
// A one-line progress display on a terminal (stderr), silent when stderr is not a terminal.
#include <chrono>
#include <string>

namespace pmdplan {

class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  ~ProgressLine();
  /// Redraws at most every 100 ms; `done` of `total` (total 0 = unknown) plus a short status.
  void update(double done, double total, const std::string& status = {});
  void finish();
  bool enabled() const { return enabled_; }

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace pmdplan
