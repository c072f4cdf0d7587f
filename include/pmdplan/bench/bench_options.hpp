#pragma once
// What a benchmark campaign runs: tasks x planners x runs, seeds, limits, checker and outputs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pmdplan/collision/checker_kind.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan {

struct BenchSettings {
  /// Built-in task names or task files (default: the paper's five tasks).
  std::vector<std::string> tasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf", "t_in_clutter"};
  /// Names from plannerRoster().
  std::vector<std::string> planners = {"pmd"};
  /// Runs per task and planner; run i uses seed + i.
  int runs = 10;
  std::uint64_t seed = 1;
  /// Wall-clock limit of each run's planning, seconds.
  double timeLimit = 60.0;
  /// A run's child process is killed once it has gone this long past the time limit without a
  /// result (smoothing and validation come after planning), and the run recorded as a failure.
  double graceSeconds = 60.0;
  /// Our planners' settings (planner_setting_table.hpp) for each hand sampling mode; every run
  /// takes its seed and the time limit above instead of theirs.
  PlannerSettings pmdParameters = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  PlannerSettings fullParameters = PlannerSettings::defaultsFor(HandSamplingMode::FullSpace);
  CheckerKind checker = CheckerKind::Fast;
  /// Motion-check resolution of every planner and of the validation, metres.
  double toleranceMetres = SegmentChecker::kDefaultTolerance;
  /// Synergy model for the PMD planner and the human-likeness metrics (empty: the robot's default).
  std::filesystem::path synergies;
  /// Outputs (empty: not written).
  std::filesystem::path csv, markdown, omplLog, plot;
  /// A folder (created if missing) where every solved run's smoothed path is written as it
  /// finishes, as a path file named TASK.PLANNER.seedN.path.json (path_set.hpp), for
  /// `pmdplan view FOLDER --seed N`. Empty: no paths written.
  std::filesystem::path paths;
  /// A folder where finished runs are kept as they finish (campaign_journal.hpp); a campaign
  /// started again with the same folder skips them. Empty: no journal.
  std::filesystem::path journal;
  /// Run nothing: write the outputs from the journal's finished runs only (a report of a campaign
  /// part way). Needs a journal.
  bool reportOnly = false;

  const PlannerSettings& roadmapParameters(HandSamplingMode mode) const {
    return mode == HandSamplingMode::Synergy ? pmdParameters : fullParameters;
  }
};

/// Throws InputError (no file; field named like the command-line option, e.g. "--runs",
/// "--planners", "--time-limit", "--tolerance-mm", "TASK") for an empty or unknown planner list,
/// a repeated planner or task, runs < 1, a seed < 1 (OMPL cannot take seed 0) or one whose runs
/// would pass the largest seed, a time limit that is not a positive finite number, a
/// tolerance that is not positive, no task, an output (file named, field "--csv", "--markdown",
/// "--ompl-log", "--plot") whose folder does not exist, or a report ("--report") without a journal. Tasks themselves
/// are checked when loaded.
void checkBenchOptions(const BenchSettings& options);

/// Splits "a,b,c" at commas (empty items kept, so checkBenchOptions can name them).
std::vector<std::string> splitList(const std::string& text);

}  // namespace pmdplan
