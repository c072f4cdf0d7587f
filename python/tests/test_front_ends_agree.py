"""The CLI and the Python module are two front ends of the same library services: `pmdplan check
--json` and pmdplan.check (io/files/task_check_json.hpp), `pmdplan validate --json` and
pmdplan.validate (io/files/path_file_validation.hpp) give the same documents for the same input,
verdict, segment and pair included; the synergy model resolution (synergy/synergy_model_resolution.hpp)
gives Python the CLI's explanation for a robot without a shipped model."""
import json

import numpy as np
import pytest

import pmdplan
from test_grasp import grasp, grasp_task_text  # noqa: F401  (the grasp task and path fixture)


def test_check_is_the_clis(cli, can_on_table):
    code, out, _ = cli("check", "can_on_table", "--json", "--tolerance-mm", "2")
    by_python = pmdplan.check(can_on_table, tolerance_mm=2)
    assert by_python == json.loads(out)
    assert code == (0 if by_python["plan"]["accepts"] else 1)
    assert by_python["straight_line"]["tolerance_mm"] == 2


def test_check_of_a_grasp_goal_is_the_clis(cli, grasp):  # noqa: F811
    _, task_file, _, _ = grasp
    code, out, _ = cli("check", task_file, "--json")
    assert code == 0
    by_python = pmdplan.check(pmdplan.Task.load(str(task_file)))
    assert by_python == json.loads(out)
    assert by_python["goal"]["grasp"] == "goal_can" and "pregrasp" in by_python["goal"]


def straight_path_file(grasp_path_file, folder):
    """The grasp path cut to its ends (start, goal) without phases: one straight segment."""
    document = json.loads(grasp_path_file.read_text())
    document["points"] = [document["points"][0], document["points"][-1]]
    document.pop("phases", None)
    document["statistics"]["path_nodes"] = 2
    path = folder / "straight.path.json"
    path.write_text(json.dumps(document))
    return path


def test_a_colliding_path_is_judged_alike_segment_and_pair(cli, grasp):  # noqa: F811
    folder, task_file, _, path_file = grasp
    straight = straight_path_file(path_file, folder)
    code, out, stderr = cli("validate", task_file, straight, "--json")
    assert code == 1, out + stderr
    by_cli = json.loads(out)
    by_python = pmdplan.validate(pmdplan.Task.load(str(task_file)), straight)
    assert by_python == by_cli
    assert not by_python["valid"] and by_python["closing_from"] is None
    assert by_python["problems"][0].startswith("segment 0 (0 -> 1): ")
    assert by_python["collisions"], by_python
    pairs = [tuple(pair) for pair in by_python["collisions"]]
    assert all(f"{a} - {b}" in " ".join(by_python["problems"]) for a, b in pairs[:1])


def test_a_grasp_path_is_judged_alike_with_its_text(cli, grasp):  # noqa: F811
    _, task_file, _, path_file = grasp
    code, out, _ = cli("validate", task_file, path_file)
    by_python = pmdplan.validate(pmdplan.Task.load(str(task_file)), path_file)
    assert code == 0 and by_python["valid"]
    points = len(json.loads(path_file.read_text())["points"])
    assert out.startswith(f"{path_file}: valid ({points} points, {by_python['states_checked']} states checked at 1 mm; "
                          f"approach to point {by_python['closing_from']}, then closing on the target)")


def test_a_path_too_long_to_check_names_the_file_in_both(cli, can_on_table, grasp, tmp_path):  # noqa: F811
    _, _, _, path_file = grasp
    document = json.loads(path_file.read_text())
    start, goal = can_on_table.start.tolist(), can_on_table.goal.tolist()
    document["points"] = [{"positions": start if i % 2 == 0 else goal} for i in range(4000)]
    document.pop("phases", None)
    document["statistics"]["path_nodes"] = 4000
    long_file = tmp_path / "long.path.json"
    long_file.write_text(json.dumps(document))
    code, _, stderr = cli("validate", "can_on_table", long_file, "--tolerance-mm", "0.01")
    assert code == 2
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.validate(can_on_table, long_file, tolerance_mm=0.01)
    assert str(raised.value) in stderr
    assert str(long_file) in str(raised.value)


def test_a_robot_without_a_shipped_model_is_explained_as_the_cli_does(tiny_robot_files):
    robot = pmdplan.Robot.load(*tiny_robot_files)
    task = pmdplan.Task(robot, np.zeros(3), np.zeros(3))
    with pytest.raises(pmdplan.InputError, match="robot 'tiny' has no shipped synergy model") as raised:
        pmdplan.human_likeness(task, np.zeros((2, 3)))
    assert raised.value.field == "synergies"
    with pytest.raises(pmdplan.InputError, match="robot 'tiny' has no shipped synergy model"):
        pmdplan.plan(task, "pmd", seed=1)
