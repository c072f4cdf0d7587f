#include "pmdplan/bench/bench_options.hpp"

#include <cmath>
#include <set>

#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/core/input_error.hpp"

namespace pmdplan {

void checkBenchOptions(const BenchOptions& o) {
  if (o.tasks.empty()) throw InputError("", "TASK", "no task given; expected built-in task names or task files");
  std::set<std::string> seen;
  for (const auto& task : o.tasks)
    if (!seen.insert(task).second) throw InputError("", "TASK", "task '" + task + "' is given twice");
  if (o.planners.empty()) throw InputError("", "--planners", "no planner given; expected a comma-separated list of " + knownPlannerNames());
  seen.clear();
  for (const auto& planner : o.planners) {
    if (!findPlanner(planner))
      throw InputError("", "--planners", "'" + planner + "' is not a planner; known planners: " + knownPlannerNames());
    if (!seen.insert(planner).second) throw InputError("", "--planners", "planner '" + planner + "' is given twice");
  }
  if (o.runs < 1) throw InputError("", "--runs", "expected a whole number of runs >= 1, got " + std::to_string(o.runs));
  if (!(o.timeLimit > 0.0) || !std::isfinite(o.timeLimit))
    throw InputError("", "--time-limit", "expected a positive, finite number of seconds");
  if (!(o.graceSeconds >= 0.0) || !std::isfinite(o.graceSeconds))
    throw InputError("", "--grace", "expected a non-negative, finite number of seconds");
  if (!(o.toleranceMetres > 0.0) || !std::isfinite(o.toleranceMetres))
    throw InputError("", "--tolerance-mm", "expected a positive number of millimetres");
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items(1);
  for (const char c : text) {
    if (c == ',') items.emplace_back();
    else items.back() += c;
  }
  return items;
}

}  // namespace pmdplan
