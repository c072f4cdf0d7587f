"""What planning through Python costs over the C++ call, on a built-in task (target: < 5 %).

Both sides plan seeds 1..RUNS with the fast checker and the shipped synergy model, reusing one task,
one checker and one model across the runs. Two figures:
- per call: pmdplan.plan timed around the Python call (argument conversion, GIL release, result
  conversion included) against the library's planTask timed in C++ inside that same call
  (PlanResult.call_seconds): the binding's own cost, free of run-to-run noise;
- against a C++ program: build/python/plan_call_reference plans the same seeds in its own process
  (planTask timed around the call), in wall-clock time and in the process's CPU time (which the
  other load of a shared machine does not inflate; Python's is time.process_time, one thread). Rounds alternate between the two so that a slow phase of the
  machine hits both; the figure compares the summed per-seed fastest runs (the least disturbed by
  other load), and still carries the noise of two processes on a shared machine.
Printed, never asserted.

    PYTHONPATH=build/python python3 python/bench/python_overhead.py [--task can_on_table] [--runs 20] [--rounds 5]
"""
import argparse
import os
import subprocess
import sys
import time

import pmdplan


def cpp_round(binary, task, runs):
    out = subprocess.run([binary, task, str(runs)], check=True, capture_output=True, text=True).stdout
    times = {}
    for line in out.splitlines():
        seed, seconds, cpu, _status = line.split()
        times[int(seed)] = (float(seconds), float(cpu))
    return times


def python_round(task, checker, synergies, runs):
    """{seed: (wall seconds of pmdplan.plan, seconds of the C++ call inside it, CPU seconds)}"""
    times = {}
    for seed in range(1, runs + 1):
        began, cpu_began = time.perf_counter(), time.process_time()
        result = pmdplan.plan(task, checker=checker, synergies=synergies, seed=seed)
        times[seed] = (time.perf_counter() - began, result.call_seconds, time.process_time() - cpu_began)
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--task", default="can_on_table")
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--reference", default=os.path.join(os.path.dirname(pmdplan.__file__), "..", "plan_call_reference"))
    args = parser.parse_args()

    task = pmdplan.Task.load(args.task)
    checker = pmdplan.CollisionChecker(task, "fast")
    synergies = pmdplan.SynergyModel.default_for(task.robot.name)
    seeds = range(1, args.runs + 1)
    cpp, cpp_cpu, py, inner, py_cpu = ({s: [] for s in seeds} for _ in range(5))
    for _ in range(args.rounds):
        for seed, (wall, cpu) in cpp_round(args.reference, args.task, args.runs).items():
            cpp[seed].append(wall)
            cpp_cpu[seed].append(cpu)
        for seed, (wall, call, cpu) in python_round(task, checker, synergies, args.runs).items():
            py[seed].append(wall)
            inner[seed].append(call)
            py_cpu[seed].append(cpu)
    wall_sum = sum(sum(v) for v in py.values())
    call_sum = sum(sum(v) for v in inner.values())
    cpp_total = sum(min(v) for v in cpp.values())
    py_total = sum(min(v) for v in py.values())
    plans = args.runs * args.rounds
    print(f"{args.task}: {args.runs} seeds x {args.rounds} rounds, fast checker")
    print(f"  per call:  pmdplan.plan {1000 * wall_sum / plans:.3f} ms, planTask inside it {1000 * call_sum / plans:.3f} ms,"
          f" binding {1000 * (wall_sum - call_sum) / plans:.3f} ms = {100 * (wall_sum - call_sum) / call_sum:+.2f} %")
    print(f"  vs a C++ program: plan_call_reference {1000 * cpp_total / args.runs:.3f} ms, pmdplan.plan"
          f" {1000 * py_total / args.runs:.3f} ms (fastest run per seed) = {100 * (py_total - cpp_total) / cpp_total:+.2f} %")
    cpp_cpu_total = sum(sum(v) for v in cpp_cpu.values())
    py_cpu_total = sum(sum(v) for v in py_cpu.values())
    print(f"  CPU time vs a C++ program: plan_call_reference {1000 * cpp_cpu_total / plans:.3f} ms, pmdplan.plan"
          f" {1000 * py_cpu_total / plans:.3f} ms (means) = {100 * (py_cpu_total - cpp_cpu_total) / cpp_cpu_total:+.2f} %")
    print(f"  Python overhead (per call): {100 * (wall_sum - call_sum) / call_sum:+.2f} % (target < 5 %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
