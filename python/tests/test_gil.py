"""The GIL is released while planning: Python code runs in another thread during a plan."""
import bisect
import threading
import time

import numpy as np

import pmdplan


def test_python_runs_in_another_thread_while_a_plan_runs():
    task = pmdplan.Task.load("can_on_table")
    checker = pmdplan.CollisionChecker(task, "fast")
    windows = []  # (begin, end) of each library planning call, on time.perf_counter's clock

    def run():
        planned, seed = 0.0, 1
        while planned < 0.5 and seed <= 500:  # plans until half a second was spent inside the library
            # A limit far beyond any plan's time: a slow build (sanitizers) must not end a plan early.
            result = pmdplan.plan(task, checker=checker, seed=seed, time_limit=3600)
            end = time.perf_counter()
            assert result.solved
            # The call's own wall time (measured in C++) ends a little before the Python call returns.
            windows.append((end - result.call_seconds, end))
            planned += result.call_seconds
            seed += 1

    thread = threading.Thread(target=run)
    ticks = []
    thread.start()
    while thread.is_alive():
        sum(range(100))  # some Python work between the ticks
        ticks.append(time.perf_counter())
    thread.join()
    # Python ran in this thread while the library planned: ticks inside the calls' windows (1 ms
    # margins for the argument and result conversions, which hold the GIL).
    margin = 0.001
    inside = sum(bisect.bisect_left(ticks, end - margin) - bisect.bisect_right(ticks, begin + margin)
                 for begin, end in windows if end - begin > 2 * margin)
    assert inside > 100, (inside, len(windows))


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

