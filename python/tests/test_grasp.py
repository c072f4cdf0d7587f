"""One grasp rule everywhere (docs/grasp_goals.md): a grasp path file (an approach, then a closing
with hand-target contact allowed) is judged alike by `pmdplan validate`, pmdplan.validate and the
viewer data `pmdplan view` writes; a closing that touches an obstacle that is not the target is
invalid for all three, for the same reason; OMPL's planners plan a grasp goal through Python as
`pmdplan bench` does, to the pre-grasp, then the closing."""
import json
import re

import numpy as np
import pytest

import pmdplan
from conftest import cli_error

DEPTH = 0.0015  # how far the goal hand sinks into the widened can (m)


def grasp_task_text(cli, sleeve=False):
    """can_on_table with its goal can widened until the goal hand sinks DEPTH into it; with `sleeve`,
    an obstacle that is not the target 0.5 mm inside the can's surface, which the closing hand touches."""
    code, out, _ = cli("check", "can_on_table", "--json")
    assert code == 0
    goal = json.loads(out)["goal"]
    assert goal["nearest"][1] == "goal_can"
    radius = 0.0317 + goal["clearance_mm"] / 1000 + DEPTH
    text = open(pmdplan.Task.load("can_on_table").file).read()
    text, widened = re.subn(r"(name: goal_can, cylinder: \{radius: )0\.0317", rf"\g<1>{radius:.9f}", text)
    assert widened == 1
    if sleeve:
        text = text.replace("obstacles:", "obstacles:\n  - {name: sleeve, cylinder: "
                            f"{{radius: {radius - 0.0005:.9f}, length: 0.1}}, xyz: [-0.47, 1.10, 0.56]}}", 1)
    return text


def viewer_path(cli, path_file, task_file, folder):
    code, _, stderr = cli("view", path_file, "--task", task_file, "--out", folder)
    assert code == 0, stderr
    text = (folder / "viewer-data.js").read_text()
    return json.loads(text[text.index("{"):text.rindex(";")])["path"]


@pytest.fixture(scope="module")
def grasp(cli, tmp_path_factory):
    """The grasp task file, its sleeved twin and a grasp path planned by the CLI."""
    folder = tmp_path_factory.mktemp("grasp")
    task_file, sleeved_file = folder / "grasp.yaml", folder / "sleeved.yaml"
    task_file.write_text(grasp_task_text(cli))
    sleeved_file.write_text(grasp_task_text(cli, sleeve=True))
    path_file = folder / "grasp.path.json"
    code, out, stderr = cli("plan", task_file, "--seed", "1", "-o", path_file)
    assert code == 0, out + stderr
    return folder, task_file, sleeved_file, path_file


@pytest.mark.parametrize("sleeved", [False, True], ids=["grasp", "closing_touches_sleeve"])
def test_cli_python_and_viewer_data_judge_a_grasp_path_alike(cli, grasp, sleeved):
    folder, task_file, sleeved_file, path_file = grasp
    task_file = sleeved_file if sleeved else task_file
    code, out, _ = cli("validate", task_file, path_file, "--json")
    assert code == (1 if sleeved else 0), out
    by_cli = json.loads(out)
    by_python = pmdplan.validate(pmdplan.Task.load(str(task_file)), str(path_file))
    by_viewer = viewer_path(cli, path_file, task_file, folder / f"viewer-{task_file.stem}")["validation"]
    assert by_python == by_cli
    assert by_viewer == by_cli
    assert by_cli["closing_from"] == len(json.loads(path_file.read_text())["points"]) - 2
    if sleeved:
        assert not by_cli["valid"]
        assert [pair[1] for pair in by_cli["collisions"]] == ["sleeve"] * len(by_cli["collisions"])
        assert "closing" in by_cli["problems"][0] and "goal_can" not in by_cli["problems"][0]
    else:
        assert by_cli["valid"] and by_cli["problems"] == [] and by_cli["collisions"] == []


def test_an_array_is_judged_with_the_phases_it_is_given(cli, grasp):
    _, task_file, _, path_file = grasp
    task = pmdplan.Task.load(str(task_file))
    document = json.loads(path_file.read_text())
    points = np.array([point["positions"] for point in document["points"]])
    closing_from = document["phases"]["closing"][0]
    assert pmdplan.validate(task, points, closing_from=closing_from) == pmdplan.validate(task, str(path_file))
    # Without its phases the closing touches the target, which then counts as a collision.
    unmarked = pmdplan.validate(task, points)
    assert not unmarked["valid"] and unmarked["closing_from"] is None
    assert all(pair[1] == "goal_can" for pair in unmarked["collisions"])
    with pytest.raises(pmdplan.InputError, match="closing_from"):
        pmdplan.validate(task, str(path_file), closing_from=closing_from)


def test_ompl_plans_a_grasp_goal_to_the_pregrasp_then_closes(grasp):
    _, task_file, _, _ = grasp
    task = pmdplan.Task.load(str(task_file))
    result = pmdplan.plan(task, "ompl:RRTConnect", seed=1, time_limit=20)
    assert result.solved
    path = result.path
    assert result.closing_from == path.shape[0] - 2
    np.testing.assert_array_equal(path[-1], task.goal)
    assert result.statistics["path_nodes"] == path.shape[0]
    assert pmdplan.validate(task, path, closing_from=result.closing_from)["valid"]
    ours = pmdplan.plan(task, "pmd-connect", seed=1)
    assert ours.solved and ours.closing_from == ours.path.shape[0] - 2


def test_a_goal_touching_another_obstacle_is_refused_with_the_clis_message(cli, grasp, tmp_path):
    _, task_file, _, _ = grasp
    other = tmp_path / "other.yaml"
    other.write_text(task_file.read_text().replace("target: goal_can", "target: obstacle_can"))
    task = pmdplan.Task.load(str(other))
    for planner in ("pmd", "ompl:RRTConnect"):
        with pytest.raises(pmdplan.InputError) as raised:
            pmdplan.plan(task, planner, seed=1, time_limit=5)
        code, _, stderr = cli("plan", other, "-o", tmp_path / "p.json")
        assert code == 2
        assert str(raised.value) == cli_error(stderr), planner
        assert "goal_can" in str(raised.value) and "obstacle_can" in str(raised.value)
