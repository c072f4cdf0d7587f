#pragma once
// Planning time per planner and task as an SVG box plot on a log scale: one group per task, one
// box per planner (quartiles, median line, whiskers to the smallest and largest time), over all
// runs, failures included at the time they gave up, with the success count under each box and
// the time limit drawn as a dashed line. Plain SVG text, so the same records give the same bytes
// and no plotting library is needed.
#include <string>
#include <vector>

#include "pmdplan/bench/run_record.hpp"

namespace pmdplan {

std::string planningTimeBoxPlotSvg(const std::vector<RunRecord>& records, const std::vector<std::string>& tasks,
                                   const std::vector<std::string>& planners, double timeLimitSeconds);

}  // namespace pmdplan
