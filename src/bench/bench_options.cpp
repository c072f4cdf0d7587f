#include "pmdplan/bench/bench_options.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <utility>

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
  if (o.seed < 1) throw InputError("", "--seed", "expected a seed >= 1 (OMPL cannot take seed 0)");
  if (o.seed > std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(o.runs))
    throw InputError("", "--seed", "too large: the runs' seeds S .. S + runs - 1 must fit in 64 bits");
  if (!(o.timeLimit > 0.0) || !std::isfinite(o.timeLimit))
    throw InputError("", "--time-limit", "expected a positive, finite number of seconds");
  if (!(o.graceSeconds >= 0.0) || !std::isfinite(o.graceSeconds))
    throw InputError("", "--grace", "expected a non-negative, finite number of seconds");
  if (!(o.toleranceMetres > 0.0) || !std::isfinite(o.toleranceMetres))
    throw InputError("", "--tolerance-mm", "expected a positive number of millimetres");
  // An output is written when the campaign ends, hours later perhaps: its folder must exist now.
  const std::pair<const std::filesystem::path*, const char*> outputs[] = {
      {&o.csv, "--csv"}, {&o.markdown, "--markdown"}, {&o.omplLog, "--ompl-log"}, {&o.plot, "--plot"}};
  for (const auto& [path, field] : outputs) {
    if (path->empty()) continue;
    const std::filesystem::path folder = path->has_parent_path() ? path->parent_path() : std::filesystem::path(".");
    if (!std::filesystem::is_directory(folder))
      throw InputError(path->string(), field, "its folder '" + folder.string() + "' does not exist; expected a file in an existing folder");
  }
  if (o.reportOnly && o.journal.empty())
    throw InputError("", "--report", "needs --journal DIR, the folder of the campaign whose finished runs to report");
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
