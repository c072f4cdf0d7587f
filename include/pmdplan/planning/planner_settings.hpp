#pragma once
// Every setting of the PMD roadmap planner (Algorithm 4) and of its hand samplers, in one place.
// Defaults are the paper's (Table 3, Sect. 5); where the paper is silent or its value is
// unworkable the deviation is stated at the field and in docs/deviations.md. Every front end (the
// command line, Python, OMPL's parameters) reaches every field through planner_setting_table.hpp.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "pmdplan/core/sequences/sample_sequence.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/lazy_pmd_settings.hpp"
#include "pmdplan/planning/pmd_connect_settings.hpp"
#include "pmdplan/planning/synergy_hand_sampler.hpp"

namespace pmdplan {

/// How Algorithm 4's line "rho_a = k·rho_a; k = k + 1" grows the arm boxes from sweep to sweep.
enum class ArmBoxGrowth {
  Factorial,  ///< rho_a(k) = k·rho_a(k-1): 1, 2, 6, 24, 120 × rho_a (the line read literally)
  Linear,     ///< rho_a(k) = k·rho_a(1): 1, 2, 3, 4 × rho_a (the other reading; the authors' Kautham code)
};

/// Named sets of defaults (`--preset`).
enum class PlannerPreset {
  Paper,    ///< "paper": the paper's values (Table 3, Sect. 5.2); the default
  Kautham,  ///< "kautham": the authors' Kautham implementation (radius 4 × d, linear rho_a growth)
  Wide,     ///< "wide": the paper's values with the neighbour radius at 2 × d (pmdplan's earlier default)
};

/// "paper", "kautham", "wide".
std::string plannerPresetName(PlannerPreset preset);
std::optional<PlannerPreset> parsePlannerPreset(const std::string& name);
/// "paper, kautham, wide" for messages.
std::string knownPlannerPresetNames();
/// The longest finite time limit, 10^6 s (11.6 days).
inline constexpr double kMaxFiniteTimeLimitSeconds = 1e6;

struct PlannerSettings {
  /// rho_a: initial half-size of the arm hypercubes, normalised arm-joint units (Table 3: 0.001).
  /// Sweep k uses rho_a(k) = k·rho_a(k-1), as in Algorithm 4, capped at 1 (the whole arm box).
  double rhoA = 0.001;
  ArmBoxGrowth rhoAGrowth = ArmBoxGrowth::Factorial;
  /// K: most neighbours a new sample is connected to (Table 3: 10).
  std::size_t neighbours = 10;
  /// Neighbours lie within neighbourThreshold · d(c_ini, c_goal), normalised full space.
  /// Sect. 5.2 and 7: the radius is d(c_ini, c_goal) itself ("not a user-defined parameter"): 1.
  /// The paper measures d over the arm joints (c^a); we measure it, like every roadmap distance,
  /// over all joints — a stated deviation (docs/deviations.md), since our neighbour search runs
  /// in the full normalised space where the hand joints count too.
  double neighbourThreshold = 1.0;
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
  std::size_t sweepVisits = 10;
  /// N: the run fails once this many samples (hand-arm draws, Table 2's "samples") have been
  /// drawn. Table 3's N = 100 (10,000) cannot bound the same count: Table 2 reports 698.82
  /// samples with no failed run. So N is large here and the time limit is the real bound.
  std::size_t maxSamples = 10'000'000;
  /// The PMD hand box: half-widths kappa·sigma_i and the most PMDs (thumb base + 4 in the paper's
  /// runs). Unused by the full-space baseline.
  SynergySamplingSettings pmdBox;
  /// Wall-clock bound of the roadmap construction, seconds, at most kMaxFiniteTimeLimitSeconds
  /// (std::chrono's clock overflows past that order) or +infinity. The only thing
  /// time is allowed to change: a run it does not stop is the same for the same seed.
  double timeLimit = 60.0;
  /// Seed of the run's std::mt19937_64 (and of the Halton offsets and SDK starts).
  std::uint64_t seed = 1;
  /// Where the hand and arm samplers' numbers come from (`--sequence`): uniform random, Halton or
  /// SDK, the three of the paper's toolkit (Sect. 6). The paper does not say which its runs used;
  /// random is the default (docs/deviations.md). Every sampler maps the same kind of points.
  SampleSequence sequence = SampleSequence::Random;
  /// Apply the smoothing of Sect. 5.3 to the path A* finds.
  bool smooth = true;
  /// The lazy PMD planner's own settings (`--planner pmd-lazy`); the paper's planner ignores them.
  LazyPmdSettings lazy;
  /// The bidirectional PMD planner's own settings (`--planner pmd-connect`); the others ignore them.
  PmdConnectSettings connect;

  /// A preset's values for a mode: Table 3's n_A = n_H = 10 for Synergy, 20 for FullSpace.
  static PlannerSettings preset(PlannerPreset preset, HandSamplingMode mode);
  /// The paper's values for a mode (preset Paper).
  static PlannerSettings defaultsFor(HandSamplingMode mode) { return preset(PlannerPreset::Paper, mode); }

  /// Throws InputError (no file; the field named by the setting's key in planner_setting_table.hpp:
  /// "rho-a", "neighbours", ..., which each front end spells its way) for values out of range.
  void check() const;
};

}  // namespace pmdplan
