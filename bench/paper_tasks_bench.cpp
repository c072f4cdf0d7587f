// The paper's five tasks, many seeds each: success, validation by the exact checker, planning
// time and roadmap figures, printed as a Markdown table. With --compare, the full-space baseline
// runs beside the PMD planner on the same tasks and seeds and the median time ratio is printed.
//
//   paper_tasks_bench [--seeds 20] [--time-limit 60] [--full-time-limit 300] [--tasks a,b,...] [--compare]
//                     [--require-all]   (exit 1 unless every run is solved and valid: the CI form)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "pmdplan/collision/path_validation.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/progress_line.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

using namespace pmdplan;

namespace {

struct Run {
  bool solved = false;
  bool valid = false;
  PlanningStatistics statistics;
};

struct Summary {
  std::string task, planner;
  std::vector<Run> runs;
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

template <typename F>
double mean(const std::vector<Run>& runs, F value) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const auto& r : runs)
    if (r.solved) sum += value(r.statistics), ++n;
  return n ? sum / static_cast<double>(n) : 0.0;
}

std::vector<double> solvedTimes(const std::vector<Run>& runs) {
  std::vector<double> times;
  for (const auto& r : runs)
    if (r.solved) times.push_back(r.statistics.planningTime);
  return times;
}

Summary runTask(const std::string& name, HandSamplingMode mode, const SynergyModel& synergies, int seeds, double timeLimit,
                ProgressLine& progress, int& done, int total) {
  Summary summary{name, handSamplingModeName(mode), {}};
  const Task task = loadTaskByName(name);
  CollisionChecking checking(task, CheckerKind::Exact);
  ExactCollisionChecker& checker = checking.exact();
  const SegmentChecker validation(checker, *task.robot, 0.001);
  for (int seed = 1; seed <= seeds; ++seed) {
    progress.update(done++, total, name + " " + summary.planner + " seed " + std::to_string(seed));
    TaskPlanningOptions options;
    options.mode = mode;
    options.parameters = PlannerParameters::defaultsFor(mode);
    options.parameters.seed = static_cast<std::uint64_t>(seed);
    options.parameters.timeLimit = timeLimit;
    options.synergies = &synergies;
    const auto result = planTask(task, checking, options);
    Run run;
    run.solved = result.statistics.solved();
    run.statistics = result.statistics;
    run.valid = run.solved && validatePath(checker, validation, result.path, task.start, task.goal).valid;
    summary.runs.push_back(run);
  }
  return summary;
}

void printTable(const std::vector<Summary>& summaries, double timeLimit) {
  std::printf("\n| task | planner | solved | valid at 1 mm | median time [s] | mean time [s] | max time [s] | samples | roadmap nodes | path nodes | final rho_a |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& s : summaries) {
    const auto times = solvedTimes(s.runs);
    std::size_t valid = 0;
    for (const auto& r : s.runs) valid += r.valid;
    std::printf("| %s | %s | %zu/%zu | %zu/%zu | %.3f | %.3f | %.3f | %.1f | %.1f | %.2f | %.4f |\n", s.task.c_str(), s.planner.c_str(),
                times.size(), s.runs.size(), valid, s.runs.size(), median(times),
                mean(s.runs, [](const PlanningStatistics& p) { return p.planningTime; }),
                times.empty() ? 0.0 : *std::max_element(times.begin(), times.end()),
                mean(s.runs, [](const PlanningStatistics& p) { return static_cast<double>(p.samples); }),
                mean(s.runs, [](const PlanningStatistics& p) { return static_cast<double>(p.roadmapNodes); }),
                mean(s.runs, [](const PlanningStatistics& p) { return static_cast<double>(p.pathNodes); }),
                mean(s.runs, [](const PlanningStatistics& p) { return p.finalArmHalfSize; }));
  }
  std::printf("\nTime limit %.0f s per run; unsolved runs count as failures and are left out of the time columns.\n", timeLimit);
}

}  // namespace

int main(int argc, char** argv) {
  int seeds = 20;
  double timeLimit = 60.0, fullTimeLimit = 300.0;
  bool compare = false, requireAll = false;
  std::vector<std::string> tasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf", "t_in_clutter"};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "paper_tasks_bench: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--seeds") seeds = std::atoi(next().c_str());
    else if (a == "--time-limit") timeLimit = std::atof(next().c_str());
    else if (a == "--full-time-limit") fullTimeLimit = std::atof(next().c_str());
    else if (a == "--compare") compare = true;
    else if (a == "--require-all") requireAll = true;
    else if (a == "--tasks") {
      tasks.clear();
      std::stringstream list(next());
      for (std::string t; std::getline(list, t, ',');) tasks.push_back(t);
    } else {
      std::fprintf(stderr, "usage: paper_tasks_bench [--seeds N] [--time-limit S] [--full-time-limit S] [--tasks a,b] [--compare] [--require-all]\n");
      return 2;
    }
  }
  if (seeds < 1 || !(timeLimit > 0) || !(fullTimeLimit > 0)) {
    std::fprintf(stderr, "paper_tasks_bench: --seeds must be >= 1 and time limits positive\n");
    return 2;
  }
  try {
    const auto synergies = loadSynergyModel(dataDirectory() / "synergies" / "sah_tx90_default.yaml");
    ProgressLine progress("paper tasks");
    const int total = seeds * static_cast<int>(tasks.size()) * (compare ? 2 : 1);
    int done = 0;
    std::vector<Summary> summaries;
    for (const auto& t : tasks) {
      summaries.push_back(runTask(t, HandSamplingMode::Synergy, synergies, seeds, timeLimit, progress, done, total));
      if (compare) summaries.push_back(runTask(t, HandSamplingMode::FullSpace, synergies, seeds, fullTimeLimit, progress, done, total));
    }
    progress.finish();
    printTable(summaries, timeLimit);
    if (compare) {
      std::printf("\n| task | median time pmd [s] | median time full [s] | full / pmd |\n|---|---|---|---|\n");
      for (std::size_t i = 0; i + 1 < summaries.size(); i += 2) {
        const double pmd = median(solvedTimes(summaries[i].runs)), full = median(solvedTimes(summaries[i + 1].runs));
        std::printf("| %s | %.3f | %.3f | %.1f |\n", summaries[i].task.c_str(), pmd, full, pmd > 0 ? full / pmd : 0.0);
      }
      std::printf("\nThe paper reports 88x on can_on_table (10.39 s vs 915.28 s, Table 2). Full-space limit %.0f s.\n", fullTimeLimit);
    }
    if (requireAll)
      for (const auto& s : summaries)
        for (const auto& r : s.runs)
          if (!r.valid) {
            std::printf("\nNOT ALL RUNS SOLVED AND VALID (%s, %s)\n", s.task.c_str(), s.planner.c_str());
            return 1;
          }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "paper_tasks_bench: %s\n", e.what());
    return 2;
  }
  return 0;
}
