"""Ctrl-C reaches long library calls: a plan without a time limit and a long validation end with
KeyboardInterrupt within a second of SIGINT (python/src/python_interrupt.hpp). Each runs in a child
Python process that the test interrupts; without the stop request the plan ran forever."""
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import pmdplan

# The child prints "started" just before the call, then "interrupted <seconds>" when the call raised
# KeyboardInterrupt, the seconds counted from its start.
PLAN_FOREVER = """
import sys, time, pmdplan
task = pmdplan.Task.load("can_on_table")
settings = pmdplan.PlannerSettings("pmd")
settings.neighbour_threshold = 1e-3  # no roadmap edge ever connects: the search never ends
settings.max_samples = 2**31 - 1
print("started", flush=True)
began = time.monotonic()
try:
    pmdplan.plan(task, settings=settings, seed=1, time_limit=float("inf"))
except KeyboardInterrupt:
    print("interrupted %.3f" % (time.monotonic() - began), flush=True)
"""

VALIDATE_LONG = """
import sys, time, numpy as np, pmdplan
task = pmdplan.Task.load("can_on_table")
a, b, c = pmdplan.plan(task, seed=1).path
path = np.array([a] + [b, a] * 60 + [c])  # about 3·10^5 states at 1 mm: several seconds
print("started", flush=True)
began = time.monotonic()
try:
    pmdplan.validate(task, path)
except KeyboardInterrupt:
    print("interrupted %.3f" % (time.monotonic() - began), flush=True)
"""


def interrupt_after(script, seconds):
    """Runs `script` in a child Python, sends SIGINT `seconds` after it started its call; returns
    (the child's output, seconds from SIGINT to its end)."""
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=dict(os.environ))
    try:
        assert child.stdout.readline().strip() == "started"
        time.sleep(seconds)
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=10)
        return out, time.monotonic() - sent, err
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()


def test_ctrl_c_ends_a_plan_without_a_time_limit():
    out, after, err = interrupt_after(PLAN_FOREVER, 1.0)
    assert out.startswith("interrupted"), (out, err)
    assert after < 3.0, after


def test_ctrl_c_ends_a_long_validation():
    out, after, err = interrupt_after(VALIDATE_LONG, 1.0)
    assert out.startswith("interrupted"), (out, err)
    assert after < 3.0, after


def test_a_validation_beyond_the_work_bound_is_refused_before_it_starts(can_on_table):
    a, b, c = pmdplan.plan(can_on_table, seed=1).path
    path = np.array([a] + [b, a] * 1000 + [c])  # about 5·10^6 states: used to take minutes
    began = time.monotonic()
    with pytest.raises(pmdplan.InputError, match="more than the 400000"):
        pmdplan.validate(can_on_table, path)
    assert time.monotonic() - began < 1.0
