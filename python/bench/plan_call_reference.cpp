// The C++ side of python/bench/python_overhead.py: plans a task for seeds 1..N with the same
// objects the Python side reuses (task, fast checker, shipped synergy model) and prints one line
// per run: "seed wall_seconds cpu_seconds status" (cpu: the process's CPU time, which the other
// load of a shared machine does not inflate).
//   plan_call_reference TASK RUNS
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

#include "pmdplan/collision/collision_checking.hpp"
#include "pmdplan/planning/task_planning.hpp"
#include "pmdplan/synergy/synergy_model_file.hpp"
#include "pmdplan/world/task.hpp"

namespace {
double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}
}  // namespace

int main(int argc, char** argv) {
  using namespace pmdplan;
  if (argc != 3) {
    std::fprintf(stderr, "usage: plan_call_reference TASK RUNS\n");
    return 2;
  }
  const Task task = loadTaskByName(argv[1]);
  const int runs = std::atoi(argv[2]);
  const SynergyModel synergies = loadSynergyModel(defaultSynergyModelPath(task.robot->name()));
  CollisionChecking checking(task, CheckerKind::Fast);
  TaskPlanningSettings options;
  options.synergies = &synergies;
  for (int seed = 1; seed <= runs; ++seed) {
    options.parameters.seed = static_cast<std::uint64_t>(seed);
    const auto began = std::chrono::steady_clock::now();
    const double cpuBegan = cpuSeconds();
    const TaskPlanningResult result = planTask(task, checking, options);
    const double cpu = cpuSeconds() - cpuBegan;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    std::printf("%d %.9f %.9f %s\n", seed, seconds, cpu, plannerStatusName(result.status).c_str());
  }
  return 0;
}
