"""Shared fixtures: the built-in tasks, a tiny generated robot, and the CLI binary to compare with."""
import os
import subprocess

import pytest

import pmdplan


@pytest.fixture(scope="session")
def can_on_table():
    return pmdplan.Task.load("can_on_table")


@pytest.fixture(scope="session")
def synergies(can_on_table):
    return pmdplan.SynergyModel.default_for(can_on_table.robot.name)


@pytest.fixture(scope="session")
def cli():
    """Runs the pmdplan binary (PMDPLAN_CLI, set by the ctest test) and returns (exit code, stdout, stderr)."""
    binary = os.environ.get("PMDPLAN_CLI")
    if not binary:
        pytest.skip("PMDPLAN_CLI is not set (run through ctest)")

    def run(*args):
        done = subprocess.run([binary, *map(str, args)], capture_output=True, text=True)
        return done.returncode, done.stdout, done.stderr

    return run


def cli_error(stderr):
    """The message of the CLI's exit-2 line."""
    prefix = "pmdplan: error: "
    line = stderr.strip().splitlines()[-1]
    assert line.startswith(prefix), stderr
    return line[len(prefix):]


TINY_URDF = """<?xml version="1.0"?>
<robot name="tiny">
  <link name="base"><collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.25"/><geometry><box size="0.05 0.05 0.5"/></geometry></collision></link>
  <link name="palm"><collision><origin xyz="0 0 0.05"/><geometry><box size="0.08 0.02 0.1"/></geometry></collision></link>
  <link name="finger"><collision><origin xyz="0 0 0.04"/><geometry><box size="0.02 0.02 0.08"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/><origin xyz="0 0 0.05"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="palm"/><origin xyz="0 0 0.5"/>
    <axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <joint name="finger_joint" type="revolute"><parent link="palm"/><child link="finger"/><origin xyz="0 0 0.1"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="1.5" effort="1" velocity="1"/></joint>
</robot>
"""

TINY_SRDF = """<?xml version="1.0"?>
<robot name="tiny">
  <group name="arm"><joint name="shoulder"/><joint name="elbow"/></group>
  <group name="hand"><joint name="finger_joint"/></group>
  <end_effector name="hand" parent_link="palm" group="hand"/>
  <disable_collisions link1="base" link2="upper" reason="Adjacent"/>
  <disable_collisions link1="upper" link2="palm" reason="Adjacent"/>
  <disable_collisions link1="palm" link2="finger" reason="Adjacent"/>
</robot>
"""


@pytest.fixture
def tiny_robot_files(tmp_path):
    urdf = tmp_path / "tiny.urdf"
    srdf = tmp_path / "tiny.srdf"
    urdf.write_text(TINY_URDF)
    srdf.write_text(TINY_SRDF)
    return urdf, srdf
