// The PMD planner on the five paper tasks, planning only (no validation, no process per run):
// every iteration is one seeded run (seed 1, 2, ...), on the fast or the exact checker. Prints
// the time per run and, after the table, each task's median and 90th percentile over the runs
// made; the thing to profile (`perf record build/benchmarks/planning_bench --benchmark_filter=...`).
//
//   planning_bench [--benchmark_min_time=2] [--benchmark_filter=can_in_box]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

using namespace pmdplan;

namespace {

const std::vector<std::string> kTasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf", "t_in_clutter"};

struct TaskRuns {
  Task task;
  SynergyModel synergies;
  std::unique_ptr<CollisionChecking> checking;
};

std::map<std::string, std::vector<double>>& planningTimes() {
  static std::map<std::string, std::vector<double>> times;
  return times;
}

void planRuns(benchmark::State& state, const std::string& name, CheckerKind kind) {
  TaskRuns d;
  d.task = loadTaskByName(name);
  d.synergies = loadSynergyModel(dataDirectory() / "synergies" / (d.task.robot->name() + "_default.yaml"));
  d.checking = std::make_unique<CollisionChecking>(d.task, kind);
  TaskPlanningOptions options;
  options.synergies = &d.synergies;
  std::uint64_t seed = 1;
  std::size_t solved = 0, samples = 0, nodes = 0, motionStates = 0;
  auto& times = planningTimes()[name + "/" + checkerKindName(kind)];
  times.clear();  // the framework calls again with more iterations: keep the last call's runs
  for (auto _ : state) {
    options.parameters.seed = seed++;
    const TaskPlanningResult result = planTask(d.task, *d.checking, options);
    solved += result.status == PlannerStatus::Solved;
    samples += result.statistics.samples;
    nodes += result.statistics.roadmapNodes;
    motionStates += result.statistics.motionChecks;
    times.push_back(result.statistics.planningTime);
  }
  const auto runs = static_cast<double>(state.iterations());
  state.counters["solved_share"] = static_cast<double>(solved) / runs;
  state.counters["samples"] = static_cast<double>(samples) / runs;
  state.counters["nodes"] = static_cast<double>(nodes) / runs;
  state.counters["posed_states"] = static_cast<double>(motionStates) / runs;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (const auto& name : kTasks)
    for (const CheckerKind kind : {CheckerKind::Fast, CheckerKind::Exact})
      benchmark::RegisterBenchmark(("plan/" + name + "/" + checkerKindName(kind)).c_str(), [=](benchmark::State& s) {
        planRuns(s, name, kind);
      })->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  std::printf("\nplanning time over the runs made (seeds 1..n)\n");
  for (auto& [label, times] : planningTimes()) {
    if (times.empty()) continue;
    std::sort(times.begin(), times.end());
    std::printf("  %-28s runs %5zu  median %9.3f ms  p90 %9.3f ms\n", label.c_str(), times.size(),
                1e3 * times[times.size() / 2], 1e3 * times[times.size() * 9 / 10]);
  }
  benchmark::Shutdown();
  return 0;
}
