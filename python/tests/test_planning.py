"""Planning through Python: the same path as the CLI for the same seed, every planner, settings,
validation, human-likeness, and the CLI's messages for bad input."""
import json

import numpy as np
import pytest

import pmdplan
from conftest import cli_error


def test_pmd_plan_gives_the_clis_path_for_the_same_seed(can_on_table, tmp_path, cli):
    result = pmdplan.plan(can_on_table, "pmd", seed=2)
    assert result.solved and result.status == "solved"
    path = result.path
    assert path.dtype == np.float64 and path.shape[1] == 19 and path.shape[0] >= 2
    np.testing.assert_array_equal(path[0], can_on_table.start)
    np.testing.assert_array_equal(path[-1], can_on_table.goal)
    stats = result.statistics
    assert stats["status"] == "solved" and stats["path_nodes"] == path.shape[0]
    assert stats["samples"] > 0 and stats["roadmap_nodes"] >= 2
    code, _, _ = cli("plan", "can_on_table", "--seed", "2", "-o", tmp_path / "cli.path.json")
    assert code == 0
    points = [p["positions"] for p in json.loads((tmp_path / "cli.path.json").read_text())["points"]]
    np.testing.assert_array_equal(path, np.array(points))
    result.save(tmp_path / "py.path.json")
    assert pmdplan.validate(can_on_table, str(tmp_path / "py.path.json"))["valid"]


def test_every_planner_kind_solves_can_on_table(can_on_table):
    assert set(["pmd", "full", "pmd-lazy", "pmd-connect", "ompl:RRTConnect"]) <= set(pmdplan.planners())
    for planner in ("full", "pmd-lazy", "pmd-connect", "ompl:RRTConnect"):
        result = pmdplan.plan(can_on_table, planner, seed=1, time_limit=30)
        assert result.solved, planner
        assert result.planner == planner
        assert pmdplan.validate(can_on_table, result.path)["valid"], planner


def test_settings_reach_the_planner(can_on_table, synergies):
    settings = pmdplan.PlannerSettings("pmd")
    assert settings.arm_trials == 10 and pmdplan.PlannerSettings("full").arm_trials == 20
    settings.seed = 5
    settings.smooth = False
    settings.rho_a_growth = "linear"
    assert "rho_a_growth='linear'" in repr(settings)
    checker = pmdplan.CollisionChecker(can_on_table, "fast")
    result = pmdplan.plan(can_on_table, settings=settings, checker=checker, synergies=synergies)
    assert result.solved and result.seed == 5
    stats = result.statistics
    assert stats["path_nodes"] == stats["path_nodes_before_smoothing"]  # not smoothed
    again = pmdplan.plan(can_on_table, settings=settings, checker=checker, synergies=synergies)
    np.testing.assert_array_equal(result.path, again.path)  # same seed, same path
    other = pmdplan.plan(can_on_table, settings=settings, checker=checker, synergies=synergies, seed=6)
    assert other.seed == 6 and settings.seed == 5


def test_lazy_settings_reach_the_lazy_planner(can_on_table):
    settings = pmdplan.PlannerSettings("pmd-lazy")
    assert settings.lazy_batch == 2 and settings.lazy_probes == 10
    first = pmdplan.plan(can_on_table, "pmd-lazy", settings=settings, seed=3)
    again = pmdplan.plan(can_on_table, "pmd-lazy", settings=settings, seed=3)
    np.testing.assert_array_equal(first.path, again.path)
    settings.lazy_radius = 0.0
    with pytest.raises(pmdplan.InputError, match="^lazy_radius: "):
        pmdplan.plan(can_on_table, "pmd-lazy", settings=settings)


def test_connect_and_sequence_settings_reach_the_bidirectional_planner(can_on_table):
    settings = pmdplan.PlannerSettings("pmd-connect")
    assert settings.connect_round == 2 and settings.connect_probes == 4 and settings.sequence == "random"
    settings.sequence = "halton"
    first = pmdplan.plan(can_on_table, "pmd-connect", settings=settings, seed=3)
    again = pmdplan.plan(can_on_table, "pmd-connect", settings=settings, seed=3)
    assert first.solved
    np.testing.assert_array_equal(first.path, again.path)
    settings.sequence = "random"
    other = pmdplan.plan(can_on_table, "pmd-connect", settings=settings, seed=3)
    assert other.solved and not np.array_equal(first.path, other.path)
    with pytest.raises(pmdplan.InputError, match="^sequence: "):
        settings.sequence = "sobol"
    settings.connect_arm_growth = 0.5
    with pytest.raises(pmdplan.InputError, match="^connect_arm_growth: "):
        pmdplan.plan(can_on_table, "pmd-connect", settings=settings)


def test_sample_limit_is_a_status_not_an_error(can_on_table):
    settings = pmdplan.PlannerSettings()
    settings.max_samples = 1
    result = pmdplan.plan(can_on_table, settings=settings)
    assert not result.solved and result.status == "sample_limit"
    assert result.path.shape == (0, 19)
    with pytest.raises(pmdplan.InputError, match="no path"):
        result.save("unused.json")


def test_bad_plan_inputs_have_the_clis_messages(can_on_table, tmp_path, cli):
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.plan(can_on_table, time_limit=-1)
    _, _, stderr = cli("plan", "can_on_table", "--time-limit", "-1")
    assert str(raised.value) == cli_error(stderr).replace("--time-limit", "time_limit", 1)  # Python's name
    settings = pmdplan.PlannerSettings()
    settings.neighbour_threshold = 0
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.plan(can_on_table, settings=settings)
    _, _, stderr = cli("plan", "can_on_table", "--neighbour-threshold", "0")
    assert str(raised.value) == cli_error(stderr).replace("--neighbour-threshold", "neighbour_threshold", 1)
    with pytest.raises(pmdplan.InputError) as raised:
        settings.check()
    assert raised.value.field == "neighbour_threshold"

    model = tmp_path / "bad_model.yaml"
    model.write_text("joints: []\n")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.plan(can_on_table, synergies=str(model))
    _, _, stderr = cli("plan", "can_on_table", "--synergies", model)
    assert str(raised.value) == cli_error(stderr)

    with pytest.raises(pmdplan.InputError, match="known planners"):
        pmdplan.plan(can_on_table, "astar")


def test_colliding_start_has_the_clis_message(can_on_table, tmp_path, cli):
    # A box around the whole robot: start and goal collide with it.
    blocked = can_on_table.replace(obstacles=can_on_table.obstacles + [
        {"name": "block", "box": [4, 4, 4], "xyz": [0, 0, 0]}])
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.plan(blocked)
    assert raised.value.field == "start" and "is in collision" in str(raised.value)
    task_file = tmp_path / "blocked.yaml"
    text = open(can_on_table.file).read()
    task_file.write_text(text.replace("obstacles:", "obstacles:\n  - {name: block, box: [4, 4, 4], xyz: [0, 0, 0]}", 1))
    file_task = pmdplan.Task.load(str(task_file))
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.plan(file_task)
    _, _, stderr = cli("plan", task_file)
    assert str(raised.value) == cli_error(stderr)


def test_validate_reports_a_path_through_the_can(can_on_table):
    report = pmdplan.validate(can_on_table, np.stack([can_on_table.start, can_on_table.goal]))
    assert not report["valid"]
    assert report["problems"] and report["collisions"]
    assert report["states_checked"] > 0
    with pytest.raises(pmdplan.InputError, match="path"):
        pmdplan.validate(can_on_table, np.zeros((2, 3)))
    with pytest.raises(pmdplan.InputError):
        pmdplan.validate(can_on_table, "/nonexistent/path.json")


def test_validate_a_path_file_of_another_robot_has_the_clis_message(can_on_table, tmp_path, cli):
    result = pmdplan.plan(can_on_table, seed=1)
    result.save(tmp_path / "p.json")
    document = json.loads((tmp_path / "p.json").read_text())
    document["joint_names"][0] = "other_joint"
    (tmp_path / "p.json").write_text(json.dumps(document))
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.validate(can_on_table, str(tmp_path / "p.json"))
    code, _, stderr = cli("validate", "can_on_table", tmp_path / "p.json")
    assert code == 2
    assert str(raised.value) == cli_error(stderr)


def test_human_likeness_is_zero_in_the_subspace_and_positive_off_it(can_on_table, synergies):
    hand = can_on_table.robot.groups["hand"]
    on = np.stack([can_on_table.start, can_on_table.start])
    for row in on:
        row[hand] = synergies.project(row[hand], directions=4)
    measured = pmdplan.human_likeness(can_on_table, on, synergies)
    assert set(measured) == {"subspace_distance_mean", "subspace_distance_max", "mahalanobis_mean"}
    assert measured["subspace_distance_max"] < 1e-9
    off = on.copy()
    off[1, hand] = can_on_table.robot.lower[hand]
    assert pmdplan.human_likeness(can_on_table, off)["subspace_distance_max"] > 0.1
    with pytest.raises(pmdplan.InputError, match="step"):
        pmdplan.human_likeness(can_on_table, on, step=0)
