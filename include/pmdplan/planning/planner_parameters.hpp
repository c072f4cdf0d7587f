#pragma once
// Parameters of the PMD roadmap planner (Algorithm 4), defaults from the paper's Table 3.
#include <cstddef>
#include <cstdint>

#include "pmdplan/planning/hand_sampling_mode.hpp"

namespace pmdplan {

/// How Algorithm 4's line "rho_a = k·rho_a; k = k + 1" grows the arm boxes from sweep to sweep.
enum class ArmBoxGrowth {
  Factorial,  ///< rho_a(k) = k·rho_a(k-1): 1, 2, 6, 24, 120 × rho_a (the line read literally; DESIGN.md)
  Linear,     ///< rho_a(k) = k·rho_a(1): 1, 2, 3, 4 × rho_a (the other reading; the authors' Kautham code)
};

/// The longest finite time limit, 10^6 s (11.6 days).
inline constexpr double kMaxFiniteTimeLimitSeconds = 1e6;

struct PlannerParameters {
  /// rho_a: initial half-size of the arm hypercubes, normalised arm-joint units (Table 3: 0.001).
  /// Sweep k uses rho_a(k) = k·rho_a(k-1), as in Algorithm 4, capped at 1 (the whole arm box).
  double initialArmHalfSize = 0.001;
  ArmBoxGrowth armBoxGrowth = ArmBoxGrowth::Factorial;
  /// K: most neighbours a new sample is connected to (Table 3: 10).
  std::size_t neighbourCount = 10;
  /// Neighbours lie within neighbourThresholdFactor · d(c_ini, c_goal), normalised full space.
  /// Sect. 5.2 sets the radius to d(c_ini, c_goal) itself, but two PMD hand samples lie about
  /// 0.9-1.0 apart in the normalised space while d(c_ini, c_goal) is 0.83 on can_on_table, so at
  /// factor 1 most samples have no neighbour candidates and some runs stall; factor 2 connects them
  /// (the authors' Kautham code uses 4).
  double neighbourThresholdFactor = 2.0;
  /// n_A: arm configurations tried per hypercube (Table 3: 10; full-space baseline 20).
  int armTrials = 10;
  /// n_H: hand configurations tried per arm configuration (Table 3: 10; full-space baseline 20).
  int handTrials = 10;
  /// Hypercube visits a sweep makes before rho_a grows, at least. A sweep visits every hypercube
  /// of the search range once (Algorithm 4); once the range has narrowed to a few hypercubes (the
  /// start's component reaches the goal's hypercube but the goal is not joined yet), one pass is
  /// a visit or two, and rho_a would blow up to the whole arm box in seven failed tries. So a
  /// narrow range is passed over again, while its passes still add nodes, until this many visits.
  /// Not in the paper (it reports no such runs); 1 restores the literal reading. Default 10.
  std::size_t minSweepVisits = 10;
  /// N: the run fails once this many arm trials (numSamples) have been made. Table 3 gives 100
  /// (10,000 full) for the authors' counting; here it is large, so the time limit is the real bound.
  std::size_t maxSamples = 10'000'000;
  /// Wall-clock bound of the roadmap construction, seconds, at most kMaxFiniteTimeLimitSeconds
  /// (std::chrono's clock overflows past that order) or +infinity. The only thing
  /// time is allowed to change: a run it does not stop is the same for the same seed.
  double timeLimit = 60.0;
  /// Seed of the run's std::mt19937_64.
  std::uint64_t seed = 1;
  /// Apply the smoothing of Sect. 5.3 to the path A* finds.
  bool smooth = true;

  /// Table 3's values for a mode: n_A = n_H = 10 for Synergy, 20 for FullSpace.
  static PlannerParameters defaultsFor(HandSamplingMode mode);

  /// Throws InputError (no file; the field named as on the command line: "rho-a", "neighbours",
  /// "neighbour-threshold", "arm-trials", "hand-trials", "sweep-visits", "max-samples", "time-limit") for values out of
  /// range.
  void check() const;
};

}  // namespace pmdplan
