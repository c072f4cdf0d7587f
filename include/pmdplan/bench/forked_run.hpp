#pragma once
// Runs a piece of work in a forked child process and brings its text result back over a pipe.
// Why: OMPL's seed can be set only once per process, so every benchmark run gets a fresh process
// that starts from the parent's state (task loaded, OMPL untouched); and a run that crashes or
// hangs takes down only its child, which is recorded as a failure with the reason, never lost.
#include <functional>
#include <string>

namespace pmdplan {

struct ChildOutcome {
  enum class Kind {
    Finished,  ///< the work returned; `output` is its text
    Failed,    ///< the work threw; `problem` holds the message
    Crashed,   ///< the child died of a signal; `problem` names it
    TimedOut,  ///< no result before the deadline: the child was killed
  };
  Kind kind = Kind::Failed;
  std::string output;
  std::string problem;

  bool finished() const { return kind == Kind::Finished; }
};

/// `work` runs in the child, which ends with _exit (no atexit handlers, no flushing of the parent's
/// buffers, no MPI calls). The child is killed (SIGKILL) once `deadlineSeconds` have passed.
ChildOutcome runInChildProcess(const std::function<std::string()>& work, double deadlineSeconds);

}  // namespace pmdplan
