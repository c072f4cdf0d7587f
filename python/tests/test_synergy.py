"""Synergy models: fit from numpy postures, save/load, coefficients <-> postures, projection."""
import numpy as np
import pytest

import pmdplan
from conftest import cli_error


def synthetic_postures(robot, frames, seed):
    """Hand postures (radians) moving mostly along two known directions of the normalised box."""
    rng = np.random.default_rng(seed)
    hand = robot.groups["hand"]
    lower, upper = robot.lower[hand], robot.upper[hand]
    n = len(hand)
    first = np.linspace(1.0, 2.0, n)
    first /= np.linalg.norm(first)
    second = np.cos(np.arange(n))
    second -= second.dot(first) * first
    second /= np.linalg.norm(second)
    unit = (0.5 + 0.15 * rng.standard_normal((frames, 1)) * first + 0.05 * rng.standard_normal((frames, 1)) * second
            + 0.002 * rng.standard_normal((frames, n)))
    return lower + np.clip(unit, 0.0, 1.0) * (upper - lower), first


def test_fit_recovers_the_main_direction_and_round_trips_through_a_file(tmp_path):
    robot = pmdplan.Robot.builtin("sah_tx90")
    postures, first = synthetic_postures(robot, 2000, seed=1)
    fit = pmdplan.fit_synergies(postures, robot)
    model = fit["model"]
    assert fit["frames"] == 2000
    assert model.joint_names == [robot.joint_names[i] for i in robot.groups["hand"]]
    assert abs(abs(model.directions[:, 0].dot(first)) - 1.0) < 1e-3
    assert fit["cumulative_variance"][1] > 0.95
    np.testing.assert_allclose(model.cumulative_variance, np.cumsum(model.variance_fraction))
    path = tmp_path / "model.yaml"
    model.save(path)
    loaded = pmdplan.SynergyModel.load(path)
    np.testing.assert_array_equal(loaded.directions, model.directions)
    np.testing.assert_array_equal(loaded.mean, model.mean)
    assert loaded.source == str(path)
    assert loaded.to_yaml() == path.read_text()


def test_own_axis_joints_and_joint_tuples():
    joints = [("a", 0.0, 1.0), ("b", -1.0, 1.0), ("c", 0.0, 2.0)]
    rng = np.random.default_rng(2)
    t = rng.random(500)
    postures = np.column_stack([rng.random(500), -0.5 + t, 2.0 * t * 0.9 + 0.01 * rng.random(500)])
    fit = pmdplan.fit_synergies(postures, joints, own_axis_joints=["a"])
    model = fit["model"]
    assert model.own_axis_joints == ["a"]
    assert fit["pca_joints"] == ["b", "c"]
    assert model.directions[0, 0] == 0.0


def test_coefficients_and_postures_are_inverse(synergies):
    rng = np.random.default_rng(3)
    s = rng.standard_normal(synergies.direction_count) * synergies.sigma
    posture = synergies.posture(s)
    assert posture.shape == (len(synergies.joint_names),)
    np.testing.assert_allclose(synergies.coefficients(posture), s, atol=1e-12)
    np.testing.assert_allclose(synergies.posture([]), synergies.lower + synergies.mean * (synergies.upper - synergies.lower))


def test_projection_lands_in_the_subspace(synergies):
    rng = np.random.default_rng(5)
    posture = synergies.lower + rng.random(len(synergies.joint_names)) * (synergies.upper - synergies.lower)
    distances = synergies.distance_from_subspace(posture)
    assert distances.shape == (synergies.direction_count + 1,)
    assert np.all(np.diff(distances) <= 1e-12)
    projected = synergies.project(posture, directions=4)
    assert synergies.distance_from_subspace(projected)[4] < 1e-12
    thumb = synergies.joint_names.index("thumb_base")
    assert projected[thumb] == pytest.approx(posture[thumb])  # own axis kept
    named = dict(zip(synergies.joint_names, posture))
    np.testing.assert_allclose(synergies.coefficients(named), synergies.coefficients(posture))


def test_bad_synergy_inputs(tmp_path, synergies, cli):
    robot = pmdplan.Robot.builtin("sah_tx90")
    with pytest.raises(pmdplan.InputError, match="postures"):
        pmdplan.fit_synergies(np.zeros((10, 4)), robot)
    with pytest.raises(pmdplan.InputError):
        pmdplan.fit_synergies(np.zeros((3, 13)), robot)  # too few frames
    with pytest.raises(pmdplan.InputError, match="joints"):
        pmdplan.fit_synergies(np.zeros((3, 2)), "hand")
    with pytest.raises(pmdplan.InputError, match="coefficients"):
        synergies.posture(np.zeros(synergies.direction_count + 1))
    with pytest.raises(pmdplan.InputError, match="directions"):
        synergies.project(synergies.posture([]), directions=99)
    bad = tmp_path / "bad.yaml"
    bad.write_text(synergies.to_yaml().replace("orthonormal: true", "orthonormal: maybe"))
    with pytest.raises(pmdplan.InputError) as raised:
        pmdplan.SynergyModel.load(bad)
    code, _, stderr = cli("synergies", "--show", bad)
    assert code == 2
    assert str(raised.value) == cli_error(stderr)
