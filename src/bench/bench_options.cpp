#include "pmdplan/bench/bench_options.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <utility>

#include "pmdplan/bench/planner_roster.hpp"
#include "pmdplan/collision/swept_distance_bound.hpp"
#include "pmdplan/core/atomic_file.hpp"
#include "pmdplan/core/input_error.hpp"
#include "pmdplan/planning/planner_settings.hpp"

namespace pmdplan {

void checkBenchOptions(const BenchSettings& o) {
  if (o.tasks.empty()) throw InputError("", "TASK", "no task given; expected built-in task names or task files");
  std::set<std::string> seen;
  for (const auto& task : o.tasks)
    if (!seen.insert(task).second) throw InputError("", "TASK", "task '" + task + "' is given twice");
  if (o.planners.empty())
    throw InputError("", "--planners", "no planner given; expected a comma-separated list of " + knownPlannerNames());
  seen.clear();
  for (const auto& planner : o.planners) {
    plannerNamed(planner, "--planners");
    if (!seen.insert(planner).second) throw InputError("", "--planners", "planner '" + planner + "' is given twice");
  }
  if (o.runs < 1) throw InputError("", "--runs", "expected a whole number of runs >= 1, got " + std::to_string(o.runs));
  if (o.seed < 1) throw InputError("", "--seed", "expected a seed >= 1 (OMPL cannot take seed 0)");
  if (o.seed > std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(o.runs))
    throw InputError("", "--seed", "too large: the runs' seeds S .. S + runs - 1 must fit in 64 bits");
  if (!(o.timeLimit > 0.0) || !(o.timeLimit <= kMaxFiniteTimeLimitSeconds))
    throw InputError("", "--time-limit", "expected a positive number of seconds up to 1e6");
  if (!(o.graceSeconds >= 0.0) || !(o.graceSeconds <= kMaxFiniteTimeLimitSeconds))
    throw InputError("", "--grace", "expected a non-negative number of seconds up to 1e6");
  checkMotionToleranceMm(o.toleranceMetres * 1000.0);
  // An output is written when the campaign ends, hours later perhaps: its folder must exist now.
  const std::pair<const std::filesystem::path*, const char*> outputs[] = {
      {&o.csv, "--csv"}, {&o.markdown, "--markdown"}, {&o.omplLog, "--ompl-log"}, {&o.plot, "--plot"}};
  for (const auto& [path, field] : outputs) {
    if (path->empty()) continue;
    checkOutputPath(*path, field, {o.synergies});
  }
  if (o.reportOnly && o.journal.empty())
    throw InputError("", "--report", "needs --journal DIR, the folder of the campaign whose finished runs to report");
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items(1);
  for (const char c : text) {
    if (c == ',')
      items.emplace_back();
    else
      items.back() += c;
  }
  return items;
}

}  // namespace pmdplan
