#include "pmdplan/bench/results_markdown.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include "pmdplan/bench/run_summary.hpp"

namespace pmdplan {
namespace {

/// About four significant digits without exponents for the sizes these metrics have.
std::string shortNumber(double value) {
  char text[64];
  const double magnitude = std::fabs(value);
  if (magnitude >= 1000.0) std::snprintf(text, sizeof text, "%.0f", value);
  else if (magnitude >= 100.0) std::snprintf(text, sizeof text, "%.1f", value);
  else if (magnitude >= 1.0) std::snprintf(text, sizeof text, "%.2f", value);
  else if (magnitude >= 0.001 || magnitude == 0.0) std::snprintf(text, sizeof text, "%.4f", value);
  else std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

std::string cell(const MetricSummary& m) {
  if (m.count == 0) return "–";
  return shortNumber(m.mean) + " (" + shortNumber(m.median) + ")";
}

std::string successCell(const RunSummary& s) {
  char text[64];
  std::snprintf(text, sizeof text, "%zu/%zu (%.0f %%)", s.succeeded, s.runs, 100.0 * s.successRate());
  return text;
}

struct MetricRow {
  const char* label;
  std::function<const MetricSummary&(const RunSummary&)> metric;
};

}  // namespace

std::string benchMarkdown(const std::vector<RunRecord>& records, const std::vector<std::string>& tasks,
                          const std::vector<std::string>& planners) {
  const std::vector<MetricRow> rows = {
      {"planning time [s]", [](const RunSummary& s) -> const MetricSummary& { return s.planningTime; }},
      {"smoothing time [s]", [](const RunSummary& s) -> const MetricSummary& { return s.smoothingTime; }},
      {"samples", [](const RunSummary& s) -> const MetricSummary& { return s.samples; }},
      {"roadmap nodes / graph states", [](const RunSummary& s) -> const MetricSummary& { return s.roadmapNodes; }},
      {"path nodes", [](const RunSummary& s) -> const MetricSummary& { return s.pathNodes; }},
      {"path length (normalised)", [](const RunSummary& s) -> const MetricSummary& { return s.pathLength; }},
      {"collision checks", [](const RunSummary& s) -> const MetricSummary& { return s.collisionChecks; }},
      {"synergy-subspace distance, mean", [](const RunSummary& s) -> const MetricSummary& { return s.subspaceDistanceMean; }},
      {"synergy-subspace distance, max", [](const RunSummary& s) -> const MetricSummary& { return s.subspaceDistanceMax; }},
      {"Mahalanobis distance, mean", [](const RunSummary& s) -> const MetricSummary& { return s.mahalanobisMean; }},
  };
  std::string md;
  for (const std::string& task : tasks) {
    std::vector<RunSummary> summaries;
    for (const std::string& planner : planners) summaries.push_back(summariseRuns(records, task, planner));
    md += "### " + task + "\n\n| metric |";
    for (const std::string& planner : planners) md += " " + planner + " |";
    md += "\n|---|";
    for (std::size_t i = 0; i < planners.size(); ++i) md += "---|";
    md += "\n| success (solved and valid) |";
    for (const RunSummary& s : summaries) md += " " + successCell(s) + " |";
    md += "\n";
    for (const MetricRow& row : rows) {
      md += std::string("| ") + row.label + " |";
      for (const RunSummary& s : summaries) md += " " + cell(row.metric(s)) + " |";
      md += "\n";
    }
    md += "\n";
  }
  md += "Cells: mean (median) over the successful runs; success over all runs. Human-likeness along the path "
        "(normalised joint units; Mahalanobis under the synergy model).\n";
  return md;
}

}  // namespace pmdplan
