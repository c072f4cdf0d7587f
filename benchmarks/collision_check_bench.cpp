// Exact (FCL) against fast (convex parts, FCL only within the band of touching) collision checks,
// side by side in one run, on two mixes of configurations per task (the fast checker takes them a
// batch of eight at a time, the exact one by one; times per configuration):
//   plan   - the states a real PMD plan of the task checks (samples and every state of its
//            motion checks, recorded from one seeded run);
//   random - the equivalence test's mix: uniform in the limits, near start/goal, near the straight
//            start-goal segment (about half of them collide).
// Then motion checks: SegmentChecker on the exact checker against FastSegmentChecker, on the
// segments that plan checked ("plan") and on short random ones ("short", 2 to 60 states). After
// the Google Benchmark table, a summary prints the exact/fast ratio of every pair of benchmarks.
// Tasks named "mesh:TASK" run the same on the mesh robot: the SAH + TX90 with every collision
// primitive a triangulated STL (circumscribed; tests/collision/primitive_meshes.hpp), written to a
// temporary folder at start.
//
// `fast-single` is the fast checker one configuration at a time (isValid), as a planner checks its
// samples; `fast` and `fast-N` take eight at a time.
//
//   collision_check_bench [--benchmark_min_time=0.2] [--benchmark_filter=...]
//       [--benchmark_repetitions=5 --benchmark_enable_random_interleaving=true]  (on a shared machine)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "collision/primitive_meshes.hpp"
#include "pmdplan/collision/fast/fast_collision_checker.hpp"
#include "pmdplan/collision/fast_segment_checker.hpp"
#include "pmdplan/collision/segment_checker.hpp"
#include "pmdplan/core/data_directory.hpp"
#include "pmdplan/core/random_source.hpp"
#include "pmdplan/planning/hand_sampling_mode.hpp"
#include "pmdplan/planning/pmd_roadmap_planner.hpp"
#include "pmdplan/planning/robot_planning_space.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"

using namespace pmdplan;

namespace {

const std::vector<std::string> kTasks = {"can_on_table", "cans_on_desk", "can_in_box", "cans_in_shelf", "t_in_clutter"};
constexpr std::size_t kMaxRecorded = 20000;

/// Passes every check on to the fast checker and keeps the configurations (up to a limit).
class RecordingValidator : public StateValidator {
 public:
  explicit RecordingValidator(StateValidator& inner) : inner_(inner) {}
  bool isValid(const Configuration& q) override {
    if (recorded.size() < kMaxRecorded) recorded.push_back(q);
    return inner_.isValid(q);
  }
  bool isArmValid(const Configuration& q) override { return inner_.isArmValid(q); }
  std::size_t checkCount() const override { return inner_.checkCount(); }
  std::vector<Configuration> recorded;

 private:
  StateValidator& inner_;
};

double normal(RandomSource& random) {
  const double u1 = 1.0 - random.uniform01(), u2 = random.uniform01();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

Configuration randomMixConfiguration(const Task& task, RandomSource& random, int kind) {
  const auto& joints = task.robot->activeJoints();
  Configuration q(task.robot->dof());
  const double t = random.uniform01();
  const bool nearGoal = random.uniform01() < 0.5;
  for (int i = 0; i < q.size(); ++i) {
    const auto& j = joints[static_cast<std::size_t>(i)];
    const double spread = 0.05 * (j.upper - j.lower) * normal(random);
    const double value = kind == 0   ? random.uniform(j.lower, j.upper)
                         : kind == 1 ? (nearGoal ? task.goal[i] : task.start[i]) + spread
                                     : task.start[i] + t * (task.goal[i] - task.start[i]) + spread;
    q[i] = std::clamp(value, j.lower, j.upper);
  }
  return q;
}

struct Segment {
  Configuration from, to;
};

/// Passes every motion check on and keeps its ends (up to a limit): the planner's own segments.
class RecordingMotions : public MotionValidator {
 public:
  explicit RecordingMotions(MotionValidator& inner) : inner_(inner) {}
  bool isValid(const Configuration& from, const Configuration& to) override {
    if (recorded.size() < 400) recorded.push_back({from, to});
    return inner_.isValid(from, to);
  }
  std::size_t statesChecked() const override { return inner_.statesChecked(); }
  std::vector<Segment> recorded;

 private:
  MotionValidator& inner_;
};

struct TaskData {
  Task task;
  std::unique_ptr<ExactCollisionChecker> exact;    ///< benchmarked alone
  std::unique_ptr<ExactCollisionChecker> confirm;  ///< the fast checker's FCL
  std::unique_ptr<FastCollisionChecker> fast;
  std::vector<Configuration> planStates, randomStates;
  std::vector<Segment> shortSegments, planSegments;
};

TaskData& taskData(const std::string& name) {
  static std::map<std::string, std::unique_ptr<TaskData>> cache;
  auto& slot = cache[name];
  if (slot) return *slot;
  slot = std::make_unique<TaskData>();
  auto& d = *slot;
  const std::string meshPrefix = "mesh:";
  if (name.rfind(meshPrefix, 0) == 0) {
    static const test::TempDir folder;
    static const auto robots = dataDirectory() / "robots" / "sah_tx90";
    static const auto urdf = testing::writeMeshRobot(folder, robots / "sah_tx90.urdf", robots / "sah_tx90.srdf",
                                                     "mesh_robot", testing::Tessellation::Circumscribed);
    const std::string task = name.substr(meshPrefix.size());
    d.task = loadTask(folder.write(task + ".yaml", testing::builtInTaskText(task, urdf.string())));
  } else {
    d.task = loadTaskByName(name);
  }
  d.exact = std::make_unique<ExactCollisionChecker>(d.task);
  d.confirm = std::make_unique<ExactCollisionChecker>(d.task);
  d.fast = std::make_unique<FastCollisionChecker>(d.task, *d.confirm);

  // One seeded plan, every state it checks recorded (motion states through SegmentChecker).
  const auto synergies = loadSynergyModel(dataDirectory() / "synergies" / (d.task.robot->name() + "_default.yaml"));
  const PlanningSpace space = planningSpaceFromRobot(*d.task.robot);
  RecordingValidator recorder(*d.fast);
  SegmentChecker segmentChecker(recorder, *d.task.robot);
  RecordingMotions motions(segmentChecker);
  PlannerSettings parameters = PlannerSettings::defaultsFor(HandSamplingMode::Synergy);
  parameters.seed = 1;
  parameters.timeLimit = 60.0;
  PmdRoadmapPlanner planner(space, recorder, motions, makeHandSampler(HandSamplingMode::Synergy, space, &synergies),
                            parameters);
  planner.setStartAndGoal(d.task.start, d.task.goal);
  planner.solve();
  d.planStates = std::move(recorder.recorded);
  d.planSegments = std::move(motions.recorded);

  RandomSource random(2026);
  for (int i = 0; i < 3000; ++i) d.randomStates.push_back(randomMixConfiguration(d.task, random, i % 3));
  SweptDistanceBound bound(*d.task.robot);
  while (d.shortSegments.size() < 300) {
    const Configuration from = randomMixConfiguration(d.task, random, 1 + static_cast<int>(d.shortSegments.size() % 2));
    Configuration direction(from.size());
    for (int i = 0; i < from.size(); ++i) direction[i] = normal(random);
    const double length = random.uniform(0.002, 0.06);
    const Configuration to = from + direction * (length / bound.bound(from, from + direction));
    if (!d.task.robot->withinLimits(to, 0.0) || !d.exact->isValid(from) || !d.exact->isValid(to)) continue;
    d.shortSegments.push_back({from, to});
  }
  return d;
}

const std::vector<Configuration>& mix(TaskData& d, int which) { return which == 0 ? d.planStates : d.randomStates; }

/// How checkStates asks: the exact checker one by one, the fast one in batches or one by one.
enum class Asking { Exact, FastBatch, FastSingle };

// One iteration checks kLanes configurations: the exact checker one by one, the fast checker in one
// batch (its forward kinematics and geometric stages run over all of them at once, in lane vectors
// `laneWidth` wide) or, as the planners check their samples, one by one (isValid: the scalar
// screen); times are per configuration.
void checkStates(benchmark::State& state, const std::string& name, Asking asking, int which, SimdLevel level) {
  auto& d = taskData(name);
  d.fast->setSimdLevel(level);
  constexpr int kLanes = FastCollisionChecker::kLanes;
  const auto& states = mix(d, which);
  std::size_t i = 0, valid = 0;
  for (auto _ : state) {
    const Configuration* batch[kLanes];
    for (int k = 0; k < kLanes; ++k) batch[k] = &states[(i + static_cast<std::size_t>(k)) % states.size()];
    i = (i + kLanes) % states.size();
    if (asking == Asking::FastBatch) {
      bool ok[kLanes];
      double safe[kLanes];
      d.fast->checkBatch(batch, kLanes, ok, safe);
      for (const bool v : ok) valid += v;
    } else {
      StateValidator& one = asking == Asking::Exact ? static_cast<StateValidator&>(*d.exact) : *d.fast;
      for (const Configuration* q : batch) valid += one.isValid(*q);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * kLanes);
  state.counters["states"] = static_cast<double>(states.size());
  state.counters["valid_share"] = static_cast<double>(valid) / static_cast<double>(state.iterations() * kLanes);
  state.counters["us_per_state"] = benchmark::Counter(static_cast<double>(state.iterations() * kLanes),
                                                      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void checkSegments(benchmark::State& state, const std::string& name, bool fast, bool planned) {
  auto& d = taskData(name);
  d.fast->setSimdLevel(widestSimdLevel());
  const auto& segments = planned ? d.planSegments : d.shortSegments;
  SegmentChecker slow(*d.exact, *d.task.robot);
  FastSegmentChecker sweeping(*d.fast, *d.task.robot, SegmentChecker::kDefaultTolerance);
  MotionValidator& motions = fast ? static_cast<MotionValidator&>(sweeping) : slow;
  std::size_t i = 0, free = 0;
  for (auto _ : state) {
    free += motions.isValid(segments[i].from, segments[i].to);
    if (++i == segments.size()) i = 0;
  }
  state.counters["states_per_segment"] =
      static_cast<double>(motions.statesChecked()) / static_cast<double>(state.iterations());
  state.counters["free_share"] = static_cast<double>(free) / static_cast<double>(state.iterations());
}

/// Keeps every run's time per iteration for the ratio summary: with --benchmark_repetitions, the
/// fastest repetition of each benchmark (on a shared machine, other load only ever adds time).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& run : runs) {
      if (run.run_type != Run::RT_Iteration) continue;
      const auto [at, added] = times.try_emplace(run.benchmark_name(), run.GetAdjustedRealTime());
      if (!added) at->second = std::min(at->second, run.GetAdjustedRealTime());
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> times;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::vector<std::string> names = kTasks;
  for (const auto& task : kTasks) names.push_back("mesh:" + task);
  for (const auto& name : names) {
    // "fast" at the CPU's widest lane vectors, "fast-N" at the narrower widths N it runs too
    // (not for the mesh robot).
    const SimdLevel widest = widestSimdLevel();
    const SimdLevel narrowest = name.rfind("mesh:", 0) == 0 ? widest : SimdLevel::sse2;
    for (const auto& [which, label] : {std::pair{0, "plan"}, std::pair{1, "random"}}) {
      benchmark::RegisterBenchmark(("check/" + name + "/" + label + "/exact").c_str(), [=](benchmark::State& s) {
        checkStates(s, name, Asking::Exact, which, widest);
      })->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("check/" + name + "/" + label + "/fast-single").c_str(), [=](benchmark::State& s) {
        checkStates(s, name, Asking::FastSingle, which, widest);
      })->Unit(benchmark::kMicrosecond);
      for (const SimdLevel level : {SimdLevel::avx512, SimdLevel::avx2, SimdLevel::sse2}) {
        if (laneWidth(level) > laneWidth(widest) || laneWidth(level) < laneWidth(narrowest)) continue;
        const std::string suffix = level == widest ? "" : "-" + std::to_string(laneWidth(level));
        benchmark::RegisterBenchmark(
            ("check/" + name + "/" + label + "/fast" + suffix).c_str(),
            [=](benchmark::State& s) { checkStates(s, name, Asking::FastBatch, which, level); })
            ->Unit(benchmark::kMicrosecond);
      }
    }
    for (const auto& [planned, label] : {std::pair{true, "plan"}, std::pair{false, "short"}})
      for (const bool fast : {false, true})
        benchmark::RegisterBenchmark(("segment/" + name + "/" + label + "/" + (fast ? "fast" : "exact")).c_str(),
                                     [=](benchmark::State& s) { checkSegments(s, name, fast, planned); })
            ->Unit(benchmark::kMicrosecond);
  }
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf("\nexact / fast time ratio (%s kernels; the fastest repetition of each)\n",
              simdLevelName(widestSimdLevel()));
  for (const auto& [benchmarkName, exactTime] : reporter.times) {
    const auto at = benchmarkName.rfind("/exact");
    if (at == std::string::npos || at + 6 != benchmarkName.size()) continue;
    const std::string stem = benchmarkName.substr(0, at);
    for (const auto& [fastName, fastTime] : reporter.times) {
      if (fastName.rfind(stem + "/fast", 0) != 0) continue;
      std::printf("  %-34s %-7s exact %9.2f us  fast %8.2f us  ratio %6.1f\n", stem.c_str(),
                  fastName.substr(stem.size() + 1).c_str(), exactTime, fastTime, exactTime / fastTime);
    }
  }
  benchmark::Shutdown();
  return 0;
}
