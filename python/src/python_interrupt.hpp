#pragma once
// Ctrl-C during a long library call (pmdplan.plan, pmdplan.validate): the call runs with the GIL
// released, so Python's SIGINT handler cannot run until it returns — with time_limit=inf, never.
// A PythonInterrupt, made on the calling thread before the GIL is released, opens the library's
// stop request (pmdplan/core/stop_request.hpp): whenever the work checks it, at most every 50 ms,
// it takes the GIL and runs Python's signal handlers (PyErr_CheckSignals); once a handler raises
// (KeyboardInterrupt), the work stops, and raiseIfInterrupted() raises that exception in Python.
#include <chrono>

#include "bindings.hpp"
#include "pmdplan/core/stop_request.hpp"

namespace pmdplan::python {

class PythonInterrupt {
 public:
  /// How often the signal handlers run while the library works.
  static constexpr std::chrono::milliseconds kPollInterval{50};

  /// With the GIL held, on the thread that will do the work. Off Python's main thread (which alone
  /// runs signal handlers) the work is never stopped.
  PythonInterrupt();

  /// With the GIL held, after the work returned or threw StopRequested: raises the handler's
  /// exception (py::error_already_set) if one ran; otherwise nothing.
  void raiseIfInterrupted();

 private:
  bool poll();

  bool mainThread_;
  bool interrupted_ = false;
  std::chrono::steady_clock::time_point lastPoll_;
  StopRequestScope scope_;
};

}  // namespace pmdplan::python
