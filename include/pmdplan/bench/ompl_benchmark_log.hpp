#pragma once
// The campaign in OMPL's benchmark log format, the text ompl_benchmark_statistics (Debian
// package ompl-demos) turns into the database Planner Arena shows. One experiment per task: the
// format holds one experiment per file. Run properties: time, solved, correct solution (the
// exact re-validation), status, simplification time (our smoothing), graph states, solution
// length and segments, samples, collision checks, the three human-likeness numbers of the
// planner's model, the three that do not use it (docs/human_likeness.md) and the seed.
#include <filesystem>
#include <string>
#include <vector>

#include "pmdplan/bench/run_record.hpp"

namespace pmdplan {

struct OmplLogContext {
  std::string hostname;   ///< "Running on ..."
  std::string startTime;  ///< "Starting at ..." (any text)
  std::string setup;      ///< free text describing the experiment
  std::uint64_t seed = 1;
  double timeLimitSeconds = 60.0;
  int runsPerPlanner = 0;
  double totalSeconds = 0.0;  ///< wall-clock time of the campaign
};

/// The log of `task` with its runs of `planners` (in that order) from `records`. Planner names
/// are OMPL-style identifiers: "geometric_RRTConnect" for ompl:RRTConnect, "pmdplan_pmd" for pmd.
std::string omplBenchmarkLog(const std::vector<RunRecord>& records, const std::string& task,
                             const std::vector<std::string>& planners, const OmplLogContext& context);

/// Where a task's log goes: `path` itself for a single task, else "<stem>.<task><extension>".
std::filesystem::path omplLogPathForTask(const std::filesystem::path& path, const std::string& task,
                                         std::size_t taskCount);

/// The OMPL-style identifier of a planner name.
std::string omplLogPlannerName(const std::string& planner);

}  // namespace pmdplan
