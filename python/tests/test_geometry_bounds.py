"""Python's Task goes through the checks of task files: shape sizes and positions within the bounds,
mesh files through the mesh reader's limits, and a plain task name."""
import os

import numpy as np
import pytest

import pmdplan

COLLADA_CYCLE = """<?xml version="1.0"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 0.01 0 0 0 0.01 0</float_array>
<technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/>
<param name="Z" type="float"/></accessor></technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/>
</vertices><triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry>
</library_geometries><library_nodes><node id="a"><instance_node url="#b"/><instance_geometry url="#g"/></node>
<node id="b"><instance_node url="#a"/></node></library_nodes><library_visual_scenes><visual_scene id="s"><node id="root">
<instance_node url="#a"/></node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>
"""


@pytest.mark.parametrize("obstacle, field", [
    ({"box": [1e300, 1, 1], "xyz": [0, 0, 0]}, "obstacles[0].box[0]"),
    ({"sphere": 1e300, "xyz": [0, 0, 0]}, "obstacles[0].sphere"),
    ({"sphere": 1e20, "xyz": [1e20, 0, 0]}, "obstacles[0].sphere"),
    ({"cylinder": {"radius": 0.1, "length": 1e10}, "xyz": [0, 0, 0]}, "obstacles[0].cylinder.length"),
    ({"sphere": 0.1, "xyz": [0, 1e300, 0]}, "obstacles[0].xyz[1]"),
])
def test_obstacles_beyond_the_bounds_are_input_errors(tiny_robot_files, obstacle, field):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), obstacles=[{"name": "o", **obstacle}])
    assert raised.value.field == field


def test_the_largest_allowed_obstacle_is_taken(tiny_robot_files):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    task = pmdplan.Task(robot, np.zeros(3), np.zeros(3),
                        obstacles=[{"name": "o", "box": [100, 100, 100], "xyz": [0, 0, -1000]}])
    assert task.obstacles[0]["box"] == [100, 100, 100]


def test_a_base_beyond_the_bound_is_an_input_error(tiny_robot_files):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), base={"xyz": [1e6, 0, 0]})
    assert raised.value.field == "base.xyz[0]"
    matrix = np.eye(4)
    matrix[2, 3] = -1e300
    with pytest.raises(pmdplan.InputError):
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), base=matrix)


def test_mesh_obstacles_go_through_the_mesh_reader(tiny_robot_files, tmp_path):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    cycle = tmp_path / "cycle.dae"
    cycle.write_text(COLLADA_CYCLE)
    with pytest.raises(pmdplan.InputError, match="cycle"):  # it crashed assimp (SIGSEGV)
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), obstacles=[{"name": "m", "mesh": {"file": cycle}, "xyz": [1, 1, 1]}])
    fifo = tmp_path / "pipe.stl"
    os.mkfifo(fifo)
    with pytest.raises(pmdplan.InputError, match="not a regular file"):
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), obstacles=[{"name": "m", "mesh": {"file": fifo}, "xyz": [1, 1, 1]}])
    tri = tmp_path / "tri.obj"
    tri.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task(robot, np.zeros(3), np.zeros(3),
                     obstacles=[{"name": "m", "mesh": {"file": tri, "scale": [1, -1, 1]}, "xyz": [1, 1, 1]}])
    assert raised.value.field == "obstacles[0].mesh.scale"
    task = pmdplan.Task(robot, np.zeros(3), np.zeros(3),
                        obstacles=[{"name": "m", "mesh": {"file": tri, "scale": [0.01, 0.01, 0.01]}, "xyz": [1, 1, 1]}])
    assert task.obstacles[0]["mesh"]["scale"] == [0.01, 0.01, 0.01]


@pytest.mark.parametrize("name", ["../../x", "/tmp/abs", "\x1b[2Jred", ".hidden", "a" * 101, ""])
def test_a_task_name_that_is_not_plain_is_an_input_error(tiny_robot_files, name):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), name=name)
    assert raised.value.field == "name"
    assert "\x1b" not in str(raised.value)
    task = pmdplan.Task(robot, np.zeros(3), np.zeros(3), name="fine-name_1.0")
    with pytest.raises(pmdplan.InputError):
        task.replace(name=name)
