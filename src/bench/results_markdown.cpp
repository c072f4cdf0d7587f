#include "pmdplan/bench/results_markdown.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

#include "pmdplan/bench/run_summary.hpp"

namespace pmdplan {
namespace {

/// About four significant digits without exponents for the sizes these metrics have.
std::string shortNumber(double value) {
  char text[64];
  const double magnitude = std::fabs(value);
  if (magnitude >= 1000.0)
    std::snprintf(text, sizeof text, "%.0f", value);
  else if (magnitude >= 100.0)
    std::snprintf(text, sizeof text, "%.1f", value);
  else if (magnitude >= 1.0)
    std::snprintf(text, sizeof text, "%.2f", value);
  else if (magnitude >= 0.001 || magnitude == 0.0)
    std::snprintf(text, sizeof text, "%.4f", value);
  else
    std::snprintf(text, sizeof text, "%.2e", value);
  return text;
}

std::string cell(const MetricSummary& m) {
  if (m.count == 0) return "–";
  return shortNumber(m.mean) + " (" + shortNumber(m.median) + ")";
}

std::string successCell(const RunSummary& s) {
  if (s.runs == 0) return "no runs";
  char text[64];
  std::snprintf(text, sizeof text, "%zu/%zu (%.0f %%)", s.succeeded, s.runs, 100.0 * s.successRate());
  return text;
}

/// Appends " text |" (in pieces: GCC 12 warns falsely about `" " + text + " |"` here, bug 105329).
void addCell(std::string& md, const std::string& text) {
  md += ' ';
  md += text;
  md += " |";
}

struct MetricRow {
  const char* label;
  std::function<const MetricSummary&(const RunSummary&)> metric;
};

/// A median planning time in milliseconds, three significant digits, with the successes.
std::string timeCell(const RunSummary& s) {
  if (s.planningTime.count == 0) return "– (" + std::to_string(s.succeeded) + "/" + std::to_string(s.runs) + ")";
  const double ms = 1e3 * s.planningTime.median;
  char text[64];
  std::snprintf(text, sizeof text,
                ms >= 100.0  ? "%.0f ms (%zu/%zu)"
                : ms >= 10.0 ? "%.1f ms (%zu/%zu)"
                             : "%.2f ms (%zu/%zu)",
                ms, s.succeeded, s.runs);
  return text;
}

std::string ratioCell(const RunSummary& other, const RunSummary& pmd) {
  if (other.planningTime.count == 0 || pmd.planningTime.count == 0) return "–";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", other.planningTime.median / pmd.planningTime.median);
  return text;
}

/// OMPL's own planners: "ompl:<Planner>" without our PMD sampling ("@pmd").
bool isOmplsOwn(const std::string& planner) {
  return planner.rfind("ompl:", 0) == 0 && planner.find("@pmd") == std::string::npos;
}

/// The OMPL planner a user would pick for the task instead of ours: OMPL's own (not our PMD
/// sampling in OMPL, `@pmd`), the most successes, then the lowest median.
const RunSummary* bestOmpl(const std::vector<RunSummary>& summaries) {
  const RunSummary* best = nullptr;
  for (const RunSummary& s : summaries) {
    if (!isOmplsOwn(s.planner) || s.succeeded == 0) continue;
    if (!best || s.succeeded > best->succeeded ||
        (s.succeeded == best->succeeded && s.planningTime.median < best->planningTime.median))
      best = &s;
  }
  return best;
}

/// Median planning time of every planner on every task, and how pmd compares (a ratio above 1:
/// pmd is faster). Only with pmd among the planners.
std::string summaryMarkdown(const std::vector<std::vector<RunSummary>>& byTask,
                            const std::vector<std::string>& planners) {
  const auto at = [&](const std::string& name) {
    return std::find(planners.begin(), planners.end(), name) - planners.begin();
  };
  const auto pmd = static_cast<std::size_t>(at("pmd")), full = static_cast<std::size_t>(at("full"));
  if (pmd == planners.size()) return "";
  const bool withOmpl = std::any_of(planners.begin(), planners.end(), isOmplsOwn);
  std::string md = "### Summary: median planning time of the successful runs (successes/runs)\n\n| task |";
  for (const std::string& planner : planners) addCell(md, planner);
  if (full < planners.size()) md += " full / pmd |";
  if (withOmpl) md += " best OMPL planner | best OMPL / pmd |";
  md += "\n|---|";
  for (std::size_t i = 0; i < planners.size() + (full < planners.size()) + 2 * withOmpl; ++i) md += "---|";
  md += "\n";
  for (const auto& summaries : byTask) {
    md += "| " + summaries.front().task + " |";
    for (const RunSummary& s : summaries) addCell(md, timeCell(s));
    if (full < planners.size()) addCell(md, ratioCell(summaries[full], summaries[pmd]));
    if (withOmpl) {
      const bool ran = std::any_of(summaries.begin(), summaries.end(),
                                   [](const RunSummary& s) { return isOmplsOwn(s.planner) && s.runs > 0; });
      if (const RunSummary* best = bestOmpl(summaries)) {
        addCell(md, best->planner.substr(5));
        addCell(md, ratioCell(*best, summaries[pmd]));
      } else {
        md += ran ? " none solved | – |" : " no runs | – |";
      }
    }
    md += "\n";
  }
  md += "\nRatios: the other planner's median over pmd's (above 1: pmd is faster).";
  if (withOmpl)
    md +=
        " Best OMPL planner: of OMPL's own (not the `@pmd` ones, which sample with ours), the one with the most "
        "successes on the task, then the lowest median.";
  md += "\n\n";
  return md;
}

std::string meanRatio(const MetricSummary& full, const MetricSummary& pmd) {
  if (full.count == 0 || pmd.count == 0 || pmd.mean == 0.0) return "–";
  return shortNumber(full.mean / pmd.mean) + "×";
}

std::string medianRatio(const MetricSummary& full, const MetricSummary& pmd) {
  if (full.count == 0 || pmd.count == 0 || pmd.median == 0.0) return "–";
  return shortNumber(full.median / pmd.median) + "×";
}

/// The paper's central claim (Table 2): how many times more samples, nodes and time the
/// full-space baseline needs than pmd. Only with both among the planners.
std::string claimMarkdown(const std::vector<std::vector<RunSummary>>& byTask,
                          const std::vector<std::string>& planners) {
  const auto pmd = static_cast<std::size_t>(std::find(planners.begin(), planners.end(), "pmd") - planners.begin());
  const auto full = static_cast<std::size_t>(std::find(planners.begin(), planners.end(), "full") - planners.begin());
  if (pmd == planners.size() || full == planners.size()) return "";
  std::string md =
      "### full / pmd: the paper's Table 2 claim\n\n"
      "| task | samples, means | samples, medians | roadmap nodes, means | roadmap nodes, medians | planning time, "
      "means | "
      "planning time, medians |\n|---|---|---|---|---|---|---|\n";
  for (const auto& summaries : byTask) {
    const RunSummary& f = summaries[full];
    const RunSummary& p = summaries[pmd];
    md += "| " + f.task + " |";
    addCell(md, meanRatio(f.samples, p.samples));
    addCell(md, medianRatio(f.samples, p.samples));
    addCell(md, meanRatio(f.roadmapNodes, p.roadmapNodes));
    addCell(md, medianRatio(f.roadmapNodes, p.roadmapNodes));
    addCell(md, meanRatio(f.planningTime, p.planningTime));
    addCell(md, medianRatio(f.planningTime, p.planningTime));
    md += "\n";
  }
  md +=
      "| paper, task 0 (Table 2, means of 100 runs) | 10.4× | – | 19.4× | – | 88.1× | – |\n\n"
      "Over the successful runs of each planner. Samples: hand-arm draws, as the paper counts them.\n\n";
  return md;
}

/// A ratio of two positive numbers to two places, or "–".
std::string quotient(double numerator, double denominator) {
  if (!(numerator > 0.0) || !(denominator > 0.0)) return "–";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", numerator / denominator);
  return text;
}

bool isOurs(const std::string& planner) {
  return planner == "pmd" || planner == "pmd-lazy" || planner == "pmd-connect";
}

/// Each of our PMD planners (pmd, pmd-lazy, pmd-connect) on each task against the best OMPL
/// planner: median planning times and their ratio, the time to certify the returned path and
/// planning over it, and the synergy-subspace distance against pmd's and RRTConnect's. Only with
/// one of ours and an OMPL planner among the planners.
std::string targetsMarkdown(const std::vector<std::vector<RunSummary>>& byTask,
                            const std::vector<std::string>& planners) {
  const bool ours = std::any_of(planners.begin(), planners.end(), isOurs);
  const bool ompl = std::any_of(planners.begin(), planners.end(), isOmplsOwn);
  if (!ours || !ompl) return "";
  const auto find = [&](const std::vector<RunSummary>& summaries, const std::string& name) -> const RunSummary* {
    for (const RunSummary& s : summaries)
      if (s.planner == name && s.succeeded > 0) return &s;
    return nullptr;
  };
  std::string md =
      "### Our planners against the best OMPL planner\n\n"
      "| task | planner | success | median planning | best OMPL planner (median) | best OMPL / planner | "
      "median certification | planning / certification | synergy-subspace distance, mean | planner / pmd | "
      "RRTConnect / planner |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& summaries : byTask) {
    const RunSummary* best = bestOmpl(summaries);
    const RunSummary* pmd = find(summaries, "pmd");
    const RunSummary* rrtConnect = find(summaries, "ompl:RRTConnect");
    for (const RunSummary& s : summaries) {
      if (!isOurs(s.planner)) continue;
      const bool any = s.succeeded > 0;
      md +=
          "| " + s.task + " | " + s.planner + " | " + std::to_string(s.succeeded) + "/" + std::to_string(s.runs) + " |";
      addCell(md, any ? shortNumber(1e3 * s.planningTime.median) + " ms" : "–");
      addCell(md, best ? best->planner.substr(5) + " (" + shortNumber(1e3 * best->planningTime.median) + " ms)"
                       : "none solved");
      addCell(md, best && any ? quotient(best->planningTime.median, s.planningTime.median) : "–");
      addCell(md, any ? shortNumber(1e3 * s.certificationTime.median) + " ms" : "–");
      addCell(md, any ? quotient(s.planningTime.median, s.certificationTime.median) : "–");
      addCell(md, any ? shortNumber(s.subspaceDistanceMean.mean) : "–");
      addCell(md, pmd && any ? quotient(s.subspaceDistanceMean.mean, pmd->subspaceDistanceMean.mean) : "–");
      addCell(md,
              rrtConnect && any ? quotient(rrtConnect->subspaceDistanceMean.mean, s.subspaceDistanceMean.mean) : "–");
      md += "\n";
    }
  }
  md +=
      "\nMedians over the successful runs; best OMPL / planner above 1: the planner is faster. Certification: one "
      "motion check of each segment of the returned path (up to the pre-grasp) with the same checker, after the run. "
      "Synergy-subspace distances: means over the successful runs.\n\n";
  return md;
}

}  // namespace

std::string benchMarkdown(const std::vector<RunRecord>& records, const std::vector<std::string>& tasks,
                          const std::vector<std::string>& planners) {
  const std::vector<MetricRow> rows = {
      {"planning time [s]", [](const RunSummary& s) -> const MetricSummary& { return s.planningTime; }},
      {"smoothing time [s]", [](const RunSummary& s) -> const MetricSummary& { return s.smoothingTime; }},
      {"certification time [s]", [](const RunSummary& s) -> const MetricSummary& { return s.certificationTime; }},
      {"samples (hand-arm draws; OMPL: states checked)",
       [](const RunSummary& s) -> const MetricSummary& { return s.samples; }},
      {"arm trials", [](const RunSummary& s) -> const MetricSummary& { return s.armTrials; }},
      {"max trials (j × h loops)", [](const RunSummary& s) -> const MetricSummary& { return s.maxTrials; }},
      {"final rho_a", [](const RunSummary& s) -> const MetricSummary& { return s.finalArmHalfSize; }},
      {"roadmap nodes / graph states", [](const RunSummary& s) -> const MetricSummary& { return s.roadmapNodes; }},
      {"path nodes", [](const RunSummary& s) -> const MetricSummary& { return s.pathNodes; }},
      {"path length (normalised)", [](const RunSummary& s) -> const MetricSummary& { return s.pathLength; }},
      {"collision checks", [](const RunSummary& s) -> const MetricSummary& { return s.collisionChecks; }},
      {"synergy-subspace distance, mean",
       [](const RunSummary& s) -> const MetricSummary& { return s.subspaceDistanceMean; }},
      {"synergy-subspace distance, max",
       [](const RunSummary& s) -> const MetricSummary& { return s.subspaceDistanceMax; }},
      {"Mahalanobis distance, mean", [](const RunSummary& s) -> const MetricSummary& { return s.mahalanobisMean; }},
      {"authors' PMD-subspace distance, mean",
       [](const RunSummary& s) -> const MetricSummary& { return s.authorsSubspaceDistanceMean; }},
      {"authors' PMD-subspace distance, max",
       [](const RunSummary& s) -> const MetricSummary& { return s.authorsSubspaceDistanceMax; }},
      {"Fig. 7 joint coupling", [](const RunSummary& s) -> const MetricSummary& { return s.jointCoupling; }},
  };
  std::vector<std::vector<RunSummary>> byTask;
  for (const std::string& task : tasks) {
    byTask.emplace_back();
    for (const std::string& planner : planners) byTask.back().push_back(summariseRuns(records, task, planner));
  }
  std::string md =
      summaryMarkdown(byTask, planners) + targetsMarkdown(byTask, planners) + claimMarkdown(byTask, planners);
  for (std::size_t t = 0; t < tasks.size(); ++t) {
    const std::string& task = tasks[t];
    const std::vector<RunSummary>& summaries = byTask[t];
    md += "### " + task + "\n\n| metric |";
    for (const std::string& planner : planners) addCell(md, planner);
    md += "\n|---|";
    for (std::size_t i = 0; i < planners.size(); ++i) md += "---|";
    md += "\n| success (solved and valid) |";
    for (const RunSummary& s : summaries) addCell(md, successCell(s));
    md += "\n";
    for (const MetricRow& row : rows) {
      md += std::string("| ") + row.label + " |";
      for (const RunSummary& s : summaries) addCell(md, cell(row.metric(s)));
      md += "\n";
    }
    std::set<int> dimensions;
    for (const RunSummary& s : summaries)
      for (const auto& entry : s.nodeShareByHandDimension) dimensions.insert(entry.first);
    for (const int dimension : dimensions) {
      md += "| % of sampled nodes from hand dimension " + std::to_string(dimension) + " |";
      for (const RunSummary& s : summaries) {
        const auto at = s.nodeShareByHandDimension.find(dimension);
        addCell(md, at == s.nodeShareByHandDimension.end() ? "–" : cell(at->second));
      }
      md += "\n";
    }
    md += "\n";
  }
  md +=
      "Cells: mean (median) over the successful runs; success over all runs. Human-likeness along the path "
      "(normalised joint units; Mahalanobis under the synergy model; the authors' PMD subspace and the Fig. 7 "
      "joint coupling, in [-1, 1], do not use the planner's model: docs/human_likeness.md).\n";
  return md;
}

}  // namespace pmdplan
