#pragma once
// One benchmark run: plan with the chosen planner through the one service `plan` uses
// (planning/task_planning.hpp: planTask), validate, measure.
//
// Smoothing: every planner smooths inside solve() (Sect. 5.3); an OMPL planner's path gets the very
// same smoothing (ompl_planner.hpp), OMPL's own simplifier is not used.
// Grasp goals (docs/grasp_goals.md): every planner plans the approach to the pre-grasp as `plan`
// does, the smoothed approach then ends with the closing segment.
// Validation: every returned path, ours too, is checked again by the grasp rule
// (GraspRule::validatePath, its phases honoured) on a separate exact checker at the same
// tolerance; an invalid path is a failure, never a success.
#include <cstdint>
#include <optional>
#include <vector>

#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/bench/run_record.hpp"
#include "pmdplan/bench/task_bench.hpp"
#include "pmdplan/io/files/path_file.hpp"
#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan {

/// Runs planner `planner` once (run number `run`) with the settings `parameters` (those the planner
/// honours: PlannerFamily). An OMPL planner sets OMPL's process-wide seed, so call this in a fresh
/// process per run (forked_run.hpp). A solved run's path is put in `path` when it is not null
/// (untouched otherwise).
RunRecord runPlannerOnce(TaskBench& bench, const PlannerEntry& planner, int run, const PlannerSettings& parameters,
                         PathFile* path = nullptr);

/// Validates the solved run's path and measures it into `record` (the time to certify its approach
/// with the bench's motion checker, path nodes, length, human-likeness, valid); an invalid path sets `failure` to the
/// validation's first problem. A grasp path's closing phase (from point `closingFrom`) is validated with hand-target
/// contact allowed.
void assessPath(TaskBench& bench, const std::vector<Configuration>& path, RunRecord& record,
                std::optional<std::size_t> closingFrom = {});

}  // namespace pmdplan
