#include "pmdplan/core/stop_request.hpp"

#include <utility>

namespace pmdplan {
namespace {
thread_local const StopRequestScope* innermost = nullptr;
}  // namespace

StopRequestScope::StopRequestScope(std::function<bool()> requested)
    : requested_(std::move(requested)), outer_(innermost) {
  innermost = this;
}

StopRequestScope::~StopRequestScope() { innermost = outer_; }

bool stopRequested() { return innermost && innermost->requested_ && innermost->requested_(); }

}  // namespace pmdplan
