#include "pmdplan/core/progress_line.hpp"

#include <unistd.h>

#include <cstdio>

namespace pmdplan {

ProgressLine::ProgressLine(std::string label) : label_(std::move(label)), enabled_(::isatty(2) == 1) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(double done, double total, const std::string& status) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  drawn_ = true;
  if (total > 0)
    std::fprintf(stderr, "\r\033[K%s %3.0f%% %s", label_.c_str(), 100.0 * done / total, status.c_str());
  else
    std::fprintf(stderr, "\r\033[K%s %s", label_.c_str(), status.c_str());
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\r\033[K");
  drawn_ = false;
}

}  // namespace pmdplan
