#include "pmdplan/bench/ompl_benchmark_log.hpp"

#include <ompl/config.h>

#include <charconv>
#include <functional>

namespace pmdplan {
namespace {

// OMPL 1.5's ompl::base::PlannerStatus::StatusType, in order: the log's "status" enum.
const char* const kStatusEnum =
    "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|Approximate solution|Exact "
    "solution|Crash|Abort";
enum class OmplStatus {
  Unknown,
  InvalidStart,
  InvalidGoal,
  UnrecognizedGoal,
  Timeout,
  Approximate,
  Exact,
  Crash,
  Abort
};

bool startsWith(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

OmplStatus statusOf(const RunRecord& r) {
  if (r.solved) return OmplStatus::Exact;  // an invalid path shows as "correct solution" 0, as in OMPL
  const std::string& f = r.failure;
  if (startsWith(f, "crashed")) return OmplStatus::Crash;
  if (startsWith(f, "killed")) return OmplStatus::Timeout;
  if (f == "not solved: time_limit" || f == "not solved: Timeout") return OmplStatus::Timeout;
  if (f == "not solved: invalid_start" || f == "not solved: Invalid start") return OmplStatus::InvalidStart;
  if (f == "not solved: invalid_goal" || f == "not solved: Invalid goal") return OmplStatus::InvalidGoal;
  if (f == "not solved: Approximate solution") return OmplStatus::Approximate;
  return OmplStatus::Abort;
}

std::string number(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

struct Property {
  const char* nameAndType;  ///< "time REAL": OMPL joins the words before the type with '_'
  std::function<std::string(const RunRecord&)> value;
};

/// A measure that does not use the planner's model, or empty (read as NULL) when not measured.
std::string independentValue(const RunRecord& r, double IndependentHumanLikeness::*field) {
  return r.humanLikeness && r.humanLikeness->independent ? number(*r.humanLikeness->independent.*field) : std::string();
}

const std::vector<Property>& properties() {
  static const std::vector<Property> list = {
      {"time REAL", [](const RunRecord& r) { return number(r.planningTimeSeconds); }},
      {"solved BOOLEAN", [](const RunRecord& r) { return std::string(r.solved ? "1" : "0"); }},
      {"correct solution BOOLEAN", [](const RunRecord& r) { return std::string(r.valid ? "1" : "0"); }},
      {"status ENUM", [](const RunRecord& r) { return std::to_string(static_cast<int>(statusOf(r))); }},
      {"simplification time REAL", [](const RunRecord& r) { return number(r.smoothingTimeSeconds); }},
      {"graph states INTEGER", [](const RunRecord& r) { return std::to_string(r.roadmapNodes); }},
      {"solution length REAL", [](const RunRecord& r) { return r.solved ? number(r.pathLength) : std::string(); }},
      {"solution segments INTEGER",
       [](const RunRecord& r) {
         return r.solved && r.pathNodes > 0 ? std::to_string(r.pathNodes - 1) : std::string();
       }},
      {"samples INTEGER", [](const RunRecord& r) { return std::to_string(r.samples); }},
      {"collision checks INTEGER", [](const RunRecord& r) { return std::to_string(r.collisionChecks); }},
      {"synergy subspace distance mean REAL",
       [](const RunRecord& r) {
         return r.humanLikeness ? number(r.humanLikeness->subspaceDistanceMean) : std::string();
       }},
      {"synergy subspace distance max REAL",
       [](const RunRecord& r) {
         return r.humanLikeness ? number(r.humanLikeness->subspaceDistanceMax) : std::string();
       }},
      {"mahalanobis distance mean REAL",
       [](const RunRecord& r) { return r.humanLikeness ? number(r.humanLikeness->mahalanobisMean) : std::string(); }},
      {"authors pmd distance mean REAL",
       [](const RunRecord& r) { return independentValue(r, &IndependentHumanLikeness::authorsSubspaceDistanceMean); }},
      {"authors pmd distance max REAL",
       [](const RunRecord& r) { return independentValue(r, &IndependentHumanLikeness::authorsSubspaceDistanceMax); }},
      {"joint coupling REAL",
       [](const RunRecord& r) { return independentValue(r, &IndependentHumanLikeness::jointCoupling); }},
      {"seed INTEGER", [](const RunRecord& r) { return std::to_string(r.seed); }},
  };
  return list;
}

/// Log values are single tokens on one line: no spaces or newlines.
std::string token(std::string text) {
  for (char& c : text)
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
  return text.empty() ? "-" : text;
}

}  // namespace

std::string omplLogPlannerName(const std::string& planner) {
  const std::string prefix = "ompl:";
  if (startsWith(planner, prefix)) return "geometric_" + token(planner.substr(prefix.size()));
  return "pmdplan_" + token(planner);
}

std::filesystem::path omplLogPathForTask(const std::filesystem::path& path, const std::string& task,
                                         std::size_t taskCount) {
  if (taskCount <= 1) return path;
  std::filesystem::path result = path;
  result.replace_filename(path.stem().string() + "." + task + path.extension().string());
  return result;
}

std::string omplBenchmarkLog(const std::vector<RunRecord>& records, const std::string& task,
                             const std::vector<std::string>& planners, const OmplLogContext& context) {
  std::string log = "OMPL version " + std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) +
                    "." + std::to_string(OMPL_PATCH_VERSION) + "\n";
  log += "Experiment " + token(task) + "\n";
  log += "Running on " + token(context.hostname) + "\n";
  log += "Starting at " + context.startTime + "\n";
  log += "<<<|\n" + context.setup + (context.setup.empty() || context.setup.back() == '\n' ? "" : "\n") + "|>>>\n";
  log += std::to_string(context.seed) + " is the random seed\n";
  log += number(context.timeLimitSeconds) + " seconds per run\n";
  log += "0 MB per run\n";
  log += std::to_string(context.runsPerPlanner) + " runs per planner\n";
  log += number(context.totalSeconds) + " seconds spent to collect the data\n";
  log += "1 enum type\n";
  log += std::string(kStatusEnum) + "\n";
  log += std::to_string(planners.size()) + " planners\n";
  for (const std::string& planner : planners) {
    log += omplLogPlannerName(planner) + "\n";
    log += "0 common properties\n";
    log += std::to_string(properties().size()) + " properties for each run\n";
    for (const Property& p : properties()) log += std::string(p.nameAndType) + "\n";
    std::vector<const RunRecord*> runs;
    for (const RunRecord& r : records)
      if (r.task == task && r.planner == planner) runs.push_back(&r);
    log += std::to_string(runs.size()) + " runs\n";
    for (const RunRecord* r : runs) {
      for (const Property& p : properties()) log += p.value(*r) + "; ";
      log += "\n";
    }
    log += ".\n";
  }
  return log;
}

}  // namespace pmdplan
