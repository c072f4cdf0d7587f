"""The GIL is released while planning: Python code runs in another thread during a plan."""
import threading
import time

import numpy as np

import pmdplan


def test_python_runs_in_another_thread_while_a_plan_runs():
    task = pmdplan.Task.load("can_on_table")
    checker = pmdplan.CollisionChecker(task, "exact")  # the slower checker: a longer plan
    window = {}

    def run():
        window["begin"] = time.perf_counter()
        window["result"] = pmdplan.plan(task, checker=checker, seed=1)
        window["end"] = time.perf_counter()

    thread = threading.Thread(target=run)
    ticks = []
    thread.start()
    while thread.is_alive():
        ticks.append(time.perf_counter())
    thread.join()
    result = window["result"]
    assert result.solved
    # Python ran in this thread inside the library's planning call: ticks strictly inside the window
    # of the call (its own wall time, measured in C++, placed at the window's end).
    inside = [t for t in ticks if window["end"] - result.call_seconds + 0.005 < t < window["end"] - 0.005]
    assert result.call_seconds > 0.05, "the plan is too short to tell"
    assert len(inside) > 100, (len(inside), result.call_seconds)


def test_two_plans_run_at_once_on_their_own_checkers():
    task = pmdplan.Task.load("can_on_table")
    results = [None, None]

    def run(i):
        results[i] = pmdplan.plan(task, seed=i + 1)

    threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(r.solved for r in results)
    for i, r in enumerate(results):
        np.testing.assert_array_equal(r.path, pmdplan.plan(task, seed=i + 1).path)

