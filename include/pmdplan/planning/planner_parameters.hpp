#pragma once
// Parameters of the PMD roadmap planner (Algorithm 4), defaults from the paper's Table 3.
#include <cstddef>
#include <cstdint>

#include "pmdplan/planning/hand_sampling_mode.hpp"

namespace pmdplan {

struct PlannerParameters {
  /// rho_a: initial half-size of the arm hypercubes, normalised arm-joint units (Table 3: 0.001).
  /// Sweep k uses rho_a(k) = k·rho_a(k-1), as in Algorithm 4.
  double initialArmHalfSize = 0.001;
  /// K: most neighbours a new sample is connected to (Table 3: 10).
  std::size_t neighbourCount = 10;
  /// n_A: arm configurations tried per hypercube (Table 3: 10; full-space baseline 20).
  int armTrials = 10;
  /// n_H: hand configurations tried per arm configuration (Table 3: 10; full-space baseline 20).
  int handTrials = 10;
  /// N: the run fails once this many arm trials (numSamples) have been made. Table 3 gives 100
  /// (10,000 full) for the authors' counting; here it is large, so the time limit is the real bound.
  std::size_t maxSamples = 10'000'000;
  /// Wall-clock bound of the roadmap construction, seconds (may be +infinity). The only thing
  /// time is allowed to change: a run it does not stop is the same for the same seed.
  double timeLimit = 60.0;
  /// Seed of the run's std::mt19937_64.
  std::uint64_t seed = 1;
  /// Apply the smoothing of Sect. 5.3 to the path A* finds.
  bool smooth = true;

  /// Table 3's values for a mode: n_A = n_H = 10 for Synergy, 20 for FullSpace.
  static PlannerParameters defaultsFor(HandSamplingMode mode);

  /// Throws InputError (no file; the field named as on the command line: "rho-a", "neighbours",
  /// "arm-trials", "hand-trials", "max-samples", "time-limit") for values out of range.
  void check() const;
};

}  // namespace pmdplan
