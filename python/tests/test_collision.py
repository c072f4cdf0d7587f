"""Collision checks: one configuration, numpy batches, segments, paths; both checkers agree."""
import numpy as np
import pytest

import pmdplan


def random_configurations(robot, count, seed):
    rng = np.random.default_rng(seed)
    return robot.lower + rng.random((count, robot.dof)) * (robot.upper - robot.lower)


@pytest.fixture(scope="module")
def checkers():
    task = pmdplan.Task.load("can_on_table")
    return task, pmdplan.CollisionChecker(task, "fast"), pmdplan.CollisionChecker(task, "exact")


def test_start_and_goal_are_free(checkers):
    task, fast, exact = checkers
    for checker in (fast, exact):
        assert checker.is_valid(task.start)
        assert checker.is_valid(task.robot.joint_dict(task.goal))
        assert checker.colliding_pairs(task.start) == []
    assert fast.checker == "fast" and exact.checker == "exact" and fast.tolerance_mm == 1.0


def test_batch_answers_equal_single_answers_and_the_exact_checker(checkers):
    task, fast, exact = checkers
    configurations = random_configurations(task.robot, 200, seed=4)
    batch = fast.check_batch(configurations)
    assert batch.dtype == np.bool_ and batch.shape == (200,)
    np.testing.assert_array_equal(batch, [fast.is_valid(q) for q in configurations])
    np.testing.assert_array_equal(batch, exact.check_batch(configurations))
    assert 0 < batch.sum() < 200  # random configurations: some free, some not
    colliding = configurations[np.argmin(batch)]
    pairs = fast.colliding_pairs(colliding)
    assert pairs and all(len(p) == 2 for p in pairs)


def test_segments_and_paths(checkers):
    task, fast, exact = checkers
    for checker in (fast, exact):
        # The straight start-goal segment runs the fingers through the can.
        assert not checker.is_segment_free(task.start, task.goal)
        assert checker.is_segment_free(task.start, task.start)
        assert not checker.is_path_free(np.stack([task.start, task.goal]))
        assert checker.is_path_free(np.stack([task.start, task.start]))
    before = fast.state_checks
    fast.is_valid(task.start)
    assert fast.state_checks == before + 1


def test_bad_checker_inputs_have_the_clis_messages(checkers, cli):
    task, fast, _ = checkers
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.CollisionChecker(task, "sloppy")
    _, _, stderr = cli("plan", "can_on_table", "--checker", "sloppy")
    assert raised.value.field == "checker"  # the argument's Python name; the CLI's message
    assert str(raised.value) == stderr.strip().splitlines()[-1].removeprefix("pmdplan: error: --")
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.CollisionChecker(task, "fast", tolerance_mm=0)
    _, _, stderr = cli("check", "can_on_table", "--tolerance-mm", "0")
    assert raised.value.field == "tolerance_mm"
    cli_message = stderr.strip().splitlines()[-1].removeprefix("pmdplan: error: ")
    assert str(raised.value) == cli_message.replace("--tolerance-mm", "tolerance_mm", 1)
    with pytest.raises(pmdplan.InputError, match="configurations"):
        fast.check_batch(np.zeros((3, 5)))
    with pytest.raises(pmdplan.InputError, match="configuration"):
        fast.is_valid([0.0] * 3)
    with pytest.raises(pmdplan.InputError, match="outside its limits"):
        fast.is_valid(task.robot.upper + 1.0)
