// The PMD planner on the five paper tasks, planning only (no validation, no process per run):
// every iteration is one seeded run (seed 1, 2, ...), on the fast or the exact checker; our lazy
// and bidirectional PMD planners (`plan-lazy/...`, `plan-connect/...`, fast checker); all three
// again on the fast checker with the Halton and the SDK sequence (`.../fast/halton`,
// `.../fast/sdk`; `--sequence`). Prints the time per run and, after the table,
// each task's median and 90th percentile over the runs made, with the median time to certify the
// returned path (a motion check of each of its approach edges, same checker) and the median of
// planning time / certification time; the thing to profile (`perf record build/benchmarks/planning_bench
// --benchmark_filter=...`).
//
//   planning_bench [--benchmark_min_time=2] [--benchmark_filter=can_in_box]
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <utility>
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

std::map<std::string, std::vector<double>>& certificationTimes() {
  static std::map<std::string, std::vector<double>> times;
  return times;
}

/// Seconds to motion-check the path's approach edges (up to the pre-grasp of a grasp path).
double certificationSeconds(const TaskPlanningResult& result, MotionValidator& motions) {
  const std::size_t last = result.closingFrom.value_or(result.path.size() - 1);
  const auto began = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < last; ++i) benchmark::DoNotOptimize(motions.isValid(result.path[i], result.path[i + 1]));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
}

/// The benchmark name's first part for each of our planners.
const std::vector<std::pair<std::string, std::string>> kPlanners = {
    {"plan", "pmd"}, {"plan-lazy", "pmd-lazy"}, {"plan-connect", "pmd-connect"}};

std::string prefixOf(const std::string& algorithm) {
  for (const auto& [prefix, known] : kPlanners)
    if (known == algorithm) return prefix;
  return "?";
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

void planRuns(benchmark::State& state, const std::string& name, CheckerKind kind, const std::string& algorithm,
              SampleSequence sequence) {
  TaskRuns d;
  d.task = loadTaskByName(name);
  d.synergies = loadSynergyModel(dataDirectory() / "synergies" / (d.task.robot->name() + "_default.yaml"));
  d.checking = std::make_unique<CollisionChecking>(d.task, kind);
  TaskPlanningSettings options;
  options.planner = &ourPlanners().at(algorithm);
  options.synergies = &d.synergies;
  options.parameters.sequence = sequence;
  std::uint64_t seed = 1;
  std::size_t solved = 0, samples = 0, nodes = 0, motionStates = 0;
  const std::string label = prefixOf(algorithm) + "/" + name + "/" + checkerKindName(kind) +
                            (sequence == SampleSequence::Random ? "" : "/" + sampleSequenceName(sequence));
  auto& times = planningTimes()[label];
  auto& certifications = certificationTimes()[label];
  times.clear();  // the framework calls again with more iterations: keep the last call's runs
  certifications.clear();
  for (auto _ : state) {
    options.parameters.seed = seed++;
    const TaskPlanningResult result = planTask(d.task, *d.checking, options);
    solved += result.status == PlannerStatus::Solved;
    samples += result.statistics.samples;
    nodes += result.statistics.roadmapNodes;
    motionStates += result.statistics.motionChecks;
    times.push_back(result.statistics.planningTime);
    if (result.status == PlannerStatus::Solved) {
      state.PauseTiming();
      certifications.push_back(certificationSeconds(result, d.checking->motions()));
      state.ResumeTiming();
    }
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
        planRuns(s, name, kind, "pmd", SampleSequence::Random);
      })->Unit(benchmark::kMillisecond);
  for (const auto& [prefix, algorithm] : kPlanners)
    for (const SampleSequence sequence : {SampleSequence::Random, SampleSequence::Halton, SampleSequence::Sdk})
      for (const auto& name : kTasks) {
        if (algorithm == "pmd" && sequence == SampleSequence::Random) continue;  // above
        const std::string suffix = sequence == SampleSequence::Random ? "" : "/" + sampleSequenceName(sequence);
        benchmark::RegisterBenchmark((prefix + "/" + name + "/fast" + suffix).c_str(), [=, algorithm = algorithm](
                                                                                           benchmark::State& s) {
          planRuns(s, name, CheckerKind::Fast, algorithm, sequence);
        })->Unit(benchmark::kMillisecond);
      }
  benchmark::RunSpecifiedBenchmarks();
  std::printf("\nplanning time over the runs made (seeds 1..n)\n");
  for (auto& [label, times] : planningTimes()) {
    if (times.empty()) continue;
    std::sort(times.begin(), times.end());
    std::printf("  %-36s runs %5zu  median %9.3f ms  p90 %9.3f ms", label.c_str(), times.size(),
                1e3 * times[times.size() / 2], 1e3 * times[times.size() * 9 / 10]);
    const std::vector<double>& certifications = certificationTimes()[label];
    if (!certifications.empty())
      std::printf("  certify median %7.3f ms  planning / certify %6.1f", 1e3 * median(certifications),
                  median(times) / median(certifications));
    std::printf("\n");
  }
  benchmark::Shutdown();
  return 0;
}
