"""pmdplan: human-like motion planning for robot hand-arm systems.

The paper's planner (Rosell et al., Autonomous Robots 31, 2011): a probabilistic roadmap that samples
the hand from the thumb base plus the first principal motion directions (PMDs) of human glove
postures and the arm near the straight start-goal path. Load a robot and a task (or build one from
numpy arrays), fit or load synergy models, check collisions, plan, validate and measure paths.

    import pmdplan
    task = pmdplan.Task.load("can_on_table")
    result = pmdplan.plan(task, "pmd", seed=1)
    result.path          # (points, dof) numpy array, radians
    pmdplan.validate(task, result.path, closing_from=result.closing_from)["valid"]  # a grasp's phases

Bad input raises pmdplan.InputError (a ValueError) with the command line's message.
"""
import os as _os

# A pip-installed package carries the built-in robots and tasks beside the module.
_data = _os.path.join(_os.path.dirname(__file__), "data")
if _os.path.isdir(_data):
    _os.environ.setdefault("PMDPLAN_DATA_DIR", _data)

from ._core import (  # noqa: E402
    CollisionChecker,
    InputError,
    PlannerSettings,
    PlanResult,
    Robot,
    SynergyModel,
    Task,
    check,
    fit_synergies,
    human_likeness,
    plan,
    planners,
    validate,
)

__all__ = [
    "CollisionChecker",
    "InputError",
    "PlannerSettings",
    "PlanResult",
    "Robot",
    "SynergyModel",
    "Task",
    "check",
    "fit_synergies",
    "human_likeness",
    "plan",
    "planners",
    "validate",
]
