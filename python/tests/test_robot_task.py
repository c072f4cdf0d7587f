"""Robots and tasks: loading, building from Python values, and the CLI's messages for bad input."""
import numpy as np
import pytest

import pmdplan
from conftest import cli_error


def test_builtin_robot_has_the_papers_joints():
    robot = pmdplan.Robot.builtin("sah_tx90")
    assert robot.dof == 19
    assert robot.joint_names[0] == "tx90_joint_1" and "thumb_base" in robot.joint_names
    assert len(robot.groups["arm"]) == 6 and len(robot.groups["hand"]) == 13
    assert np.all(robot.lower < robot.upper)
    assert robot.palm_link


def test_generated_urdf_loads_with_its_srdf(tiny_robot_files):
    urdf, srdf = tiny_robot_files
    robot = pmdplan.Robot.load(urdf, srdf)
    assert robot.name == "tiny"
    assert robot.joint_names == ["shoulder", "elbow", "finger_joint"]
    assert robot.groups == {"arm": [0, 1], "hand": [2]}
    q = robot.configuration({"shoulder": 0.5, "elbow": -1.0, "finger_joint": 0.2})
    np.testing.assert_array_equal(q, [0.5, -1.0, 0.2])
    assert robot.joint_dict(q) == {"shoulder": 0.5, "elbow": -1.0, "finger_joint": 0.2}
    np.testing.assert_allclose(robot.normalise(q), [3.5 / 6, 1.0 / 4, 0.2 / 1.5])
    assert pmdplan.Robot.from_name_or_path(str(urdf)).dof == 3


def test_broken_urdf_is_an_input_error_with_the_clis_message(tmp_path, cli):
    urdf = tmp_path / "broken.urdf"
    urdf.write_text("<robot name='x'><link name='a'/><joint name='j' type='revolute'><parent link='a'/>"
                    "<child link='b'/></joint></robot>")
    (tmp_path / "broken.srdf").write_text("<robot name='x'><group name='arm'><joint name='j'/></group></robot>")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Robot.load(urdf)
    assert isinstance(raised.value, ValueError)
    code, _, stderr = cli("collision-pairs", urdf)
    assert code == 2
    assert str(raised.value) == cli_error(stderr)
    assert raised.value.file == str(urdf)


def test_builtin_task_loads(can_on_table):
    assert can_on_table.name == "can_on_table"
    assert can_on_table.robot.dof == 19
    assert can_on_table.start.shape == (19,)
    assert can_on_table.target == "goal_can"
    names = [o["name"] for o in can_on_table.obstacles]
    assert "table" in names and "goal_can" in names
    assert can_on_table.base.shape == (4, 4)


def test_bad_task_file_is_an_input_error_with_the_clis_message(tmp_path, cli):
    task = tmp_path / "bad.yaml"
    task.write_text("name: bad\nrobot: sah_tx90\nbase: {xyz: [0, 0, 0]}\nobstacles: [{name: a, box: [1, -1, 1], xyz: [0, 0, 5]}]\n"
                    "start: {joints: {}}\ngoal: {joints: {}}\n")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task.load(str(task))
    code, _, stderr = cli("check", task)
    assert code == 2
    assert str(raised.value) == cli_error(stderr)
    assert raised.value.file == str(task)
    assert "obstacles[0].box" in raised.value.field


def test_unknown_task_name_has_the_clis_message(cli):
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task.load("no_such_task")
    _, _, stderr = cli("check", "no_such_task")
    assert str(raised.value) == cli_error(stderr)


def test_task_built_from_python_values(tiny_robot_files):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    obstacles = [
        {"name": "wall", "box": [0.1, 1.0, 1.0], "xyz": [0.6, 0.0, 0.5]},
        {"name": "post", "cylinder": {"radius": 0.05, "length": 0.4}, "xyz": [-0.6, 0, 0.2], "rpy_deg": [0, 0, 45]},
        {"name": "ball", "sphere": 0.1, "xyz": [0, 0.7, 1.0]},
    ]
    task = pmdplan.Task(robot, start=np.zeros(3), goal={"shoulder": 1.0, "elbow": 0.5, "finger_joint": 1.0},
                        obstacles=obstacles, base={"xyz": [0, 0, 0]}, name="tiny_task", target="ball")
    assert task.name == "tiny_task" and task.target == "ball"
    np.testing.assert_array_equal(task.goal, [1.0, 0.5, 1.0])
    back = task.obstacles
    assert [o["name"] for o in back] == ["wall", "post", "ball"]
    np.testing.assert_allclose(back[1]["rpy_deg"], [0, 0, 45], atol=1e-9)
    assert back[1]["cylinder"] == {"radius": 0.05, "length": 0.4}
    moved = task.replace(goal=np.array([0.0, 0.0, 0.5]), name="other")
    np.testing.assert_array_equal(moved.goal, [0, 0, 0.5])
    np.testing.assert_array_equal(task.goal, [1.0, 0.5, 1.0])  # the original is unchanged
    assert moved.name == "other"


def test_task_from_a_4x4_base_matrix(tiny_robot_files):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    base = np.eye(4)
    base[:3, 3] = [1, 2, 3]
    task = pmdplan.Task(robot, np.zeros(3), np.zeros(3), base=base)
    np.testing.assert_array_equal(task.base, base)
    base[0, 0] = 2.0
    with pytest.raises(pmdplan.InputError, match="base"):
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), base=base)


@pytest.mark.parametrize("start, goal, obstacles, field", [
    (np.zeros(2), np.zeros(3), [], "start"),
    (np.zeros(3), {"shoulder": 0.0, "elbow": 0.0}, [], "goal"),
    (np.zeros(3), {"shoulder": 0.0, "elbow": 0.0, "finger_joint": 0.0, "wrist": 1.0}, [], "goal"),
    (np.array([0.0, 9.0, 0.0]), np.zeros(3), [], "start"),
    (np.array([0.0, np.nan, 0.0]), np.zeros(3), [], "start"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "box": [1, 1], "xyz": [0, 0, 0]}], "obstacles[0].box"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "sphere": 1, "box": [1, 1, 1], "xyz": [0, 0, 0]}], "obstacles[0].sphere"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "cone": 1, "xyz": [0, 0, 0]}], "obstacles[0].cone"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "sphere": 1}], "obstacles[0].xyz"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "cylinder": {"radius": -1, "length": 1}, "xyz": [0, 0, 0]}],
     "obstacles[0].cylinder.radius"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "mesh": {"file": "/nonexistent.stl"}, "xyz": [0, 0, 0]}],
     "obstacles[0].mesh.file"),
    (np.zeros(3), np.zeros(3), [{"name": "a", "sphere": 1, "xyz": [0, 0, 0]}, {"name": "a", "sphere": 1, "xyz": [0, 0, 0]}],
     "obstacles[1].name"),
])
def test_bad_python_task_values_name_the_field(tiny_robot_files, start, goal, obstacles, field):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.Task(robot, start, goal, obstacles=obstacles)
    assert raised.value.field == field
    assert str(raised.value).startswith(field) or field in str(raised.value)


def test_unknown_target_is_an_input_error(tiny_robot_files):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    with pytest.raises(pmdplan.InputError, match="target"):
        pmdplan.Task(robot, np.zeros(3), np.zeros(3), target="missing")
