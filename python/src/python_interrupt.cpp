#include "python_interrupt.hpp"

namespace pmdplan::python {

namespace {

/// Python runs signal handlers in its main thread only: elsewhere there is nothing to poll.
bool onPythonsMainThread() {
  const auto main = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  return main == PyThread_get_thread_ident();
}

}  // namespace

PythonInterrupt::PythonInterrupt()
    : mainThread_(onPythonsMainThread()),
      lastPoll_(std::chrono::steady_clock::now()),
      scope_([this] { return poll(); }) {}

bool PythonInterrupt::poll() {
  if (interrupted_) return true;
  if (!mainThread_) return false;
  const auto now = std::chrono::steady_clock::now();
  if (now - lastPoll_ < kPollInterval) return false;
  lastPoll_ = now;
  py::gil_scoped_acquire acquire;
  // A handler's exception stays set on this thread until raiseIfInterrupted() raises it.
  if (PyErr_CheckSignals() != 0) interrupted_ = true;
  return interrupted_;
}

void PythonInterrupt::raiseIfInterrupted() {
  if (!interrupted_) return;
  if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
  throw py::error_already_set();
}

}  // namespace pmdplan::python
