#pragma once
// A caller's request that long library work end early (Python's Ctrl-C, python/src/python_interrupt.hpp).
// While a StopRequestScope lives on a thread, stopRequested() on that thread asks its function: the
// planners treat a stop like their time limit (PlannerRun::timeIsUp, the OMPL planners' termination
// condition) and path validation throws StopRequested at its next state. Without a scope nothing
// ever stops early, and the check costs one thread-local read.
#include <exception>
#include <functional>

namespace pmdplan {

class StopRequestScope {
 public:
  /// `requested` is called from the thread that made the scope, as often as the work checks (it
  /// should be cheap, or limit its own rate).
  explicit StopRequestScope(std::function<bool()> requested);
  ~StopRequestScope();
  StopRequestScope(const StopRequestScope&) = delete;
  StopRequestScope& operator=(const StopRequestScope&) = delete;

 private:
  friend bool stopRequested();
  std::function<bool()> requested_;
  const StopRequestScope* outer_;
};

/// True once the innermost StopRequestScope of this thread says so.
bool stopRequested();

/// Thrown by work that has no "not finished" answer (path validation) when a stop was requested.
struct StopRequested : std::exception {
  const char* what() const noexcept override { return "stopped at the caller's request"; }
};

}  // namespace pmdplan
