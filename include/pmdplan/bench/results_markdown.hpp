#pragma once
// The campaign as Markdown, laid out like the paper's Tables 2 and 4: rows are the metrics,
// columns the planners, one table per task. Each cell is "mean (median)" over the successful
// runs (solved and valid), the first row the success rate over all runs. With pmd among the
// planners, a summary comes first: every planner's median planning time per task, full / pmd and
// the best OMPL planner over pmd; with OMPL's planners, each of our PMD planners against the best
// of them (time, certification time, synergy-subspace distance).
#include <string>
#include <vector>

#include "pmdplan/bench/run_record.hpp"

namespace pmdplan {

/// Tables for `tasks` x `planners` (in that order) from `records`.
std::string benchMarkdown(const std::vector<RunRecord>& records, const std::vector<std::string>& tasks,
                          const std::vector<std::string>& planners);

}  // namespace pmdplan
