"""What planning through Python costs over the C++ call, on a built-in task (target: < 5 %).

Both sides plan seeds 1..RUNS with the fast checker and the shipped synergy model, reusing one task,
one checker and one model across the runs: the C++ side is build/python/plan_call_reference (the
library's planTask, timed around the call), the Python side pmdplan.plan timed around the Python
call (argument conversion, GIL release, result conversion included). Rounds alternate between the
two so that a slow phase of the machine hits both; the figure is the overhead of the summed
per-seed medians. Printed, never asserted.

    PYTHONPATH=build/python python3 python/bench/python_overhead.py [--task can_on_table] [--runs 20] [--rounds 5]
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

import pmdplan


def cpp_round(binary, task, runs):
    out = subprocess.run([binary, task, str(runs)], check=True, capture_output=True, text=True).stdout
    times = {}
    for line in out.splitlines():
        seed, seconds, _status = line.split()
        times[int(seed)] = float(seconds)
    return times


def python_round(task, checker, synergies, runs):
    times = {}
    for seed in range(1, runs + 1):
        began = time.perf_counter()
        pmdplan.plan(task, checker=checker, synergies=synergies, seed=seed)
        times[seed] = time.perf_counter() - began
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
    cpp, py = {s: [] for s in range(1, args.runs + 1)}, {s: [] for s in range(1, args.runs + 1)}
    for _ in range(args.rounds):
        for seed, t in cpp_round(args.reference, args.task, args.runs).items():
            cpp[seed].append(t)
        for seed, t in python_round(task, checker, synergies, args.runs).items():
            py[seed].append(t)
    cpp_total = sum(statistics.median(v) for v in cpp.values())
    py_total = sum(statistics.median(v) for v in py.values())
    overhead = 100.0 * (py_total - cpp_total) / cpp_total
    print(f"{args.task}: {args.runs} seeds x {args.rounds} rounds, fast checker")
    print(f"  C++ planTask:    {1000 * cpp_total / args.runs:8.3f} ms per plan (median per seed, mean over seeds)")
    print(f"  pmdplan.plan:    {1000 * py_total / args.runs:8.3f} ms per plan")
    print(f"  Python overhead: {overhead:+.2f} % (target < 5 %)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
