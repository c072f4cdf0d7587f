"""Type stubs of the pmdplan module (the compiled pmdplan._core, re-exported).

The attributes of Robot, Task, CollisionChecker, SynergyModel and PlanResult are read-only
properties; PlannerSettings' fields are writable."""
import os
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Joints = Union[ArrayLike, Mapping[str, float]]
PathLike = Union[str, os.PathLike]

class InputError(ValueError):
    """Bad input; str(error) is the CLI's exit-2 message."""
    file: str
    field: str
    message: str

class Robot:
    @staticmethod
    def load(urdf: PathLike, srdf: Optional[PathLike] = None) -> Robot: ...
    @staticmethod
    def builtin(name: str) -> Robot: ...
    @staticmethod
    def from_name_or_path(name_or_urdf: str) -> Robot: ...
    name: str
    urdf_path: os.PathLike
    dof: int
    joint_names: list[str]
    lower: np.ndarray
    upper: np.ndarray
    groups: dict[str, list[int]]
    palm_link: str
    def configuration(self, values: Joints) -> np.ndarray: ...
    def joint_dict(self, configuration: Joints) -> dict[str, float]: ...
    def normalise(self, configuration: Joints) -> np.ndarray: ...

class Task:
    def __init__(self, robot: Robot, start: Joints, goal: Joints, obstacles: Sequence[Mapping[str, Any]] = ...,
                 base: Union[None, Mapping[str, Any], ArrayLike] = None, name: str = "python_task",
                 description: str = "", target: Optional[str] = None) -> None: ...
    @staticmethod
    def load(name_or_path: str) -> Task: ...
    def replace(self, start: Optional[Joints] = None, goal: Optional[Joints] = None,
                obstacles: Optional[Sequence[Mapping[str, Any]]] = None, name: Optional[str] = None) -> Task: ...
    name: str
    description: str
    file: os.PathLike
    robot: Robot
    start: np.ndarray
    goal: np.ndarray
    target: Optional[str]
    base: np.ndarray
    obstacles: list[dict[str, Any]]

class CollisionChecker:
    def __init__(self, task: Task, checker: str = "fast", tolerance_mm: float = 1.0) -> None: ...
    task: Task
    checker: str
    tolerance_mm: float
    state_checks: int
    def is_valid(self, configuration: Joints) -> bool: ...
    def colliding_pairs(self, configuration: Joints) -> list[tuple[str, str]]: ...
    def check_batch(self, configurations: ArrayLike) -> np.ndarray: ...
    def is_segment_free(self, from_configuration: Joints, to_configuration: Joints) -> bool: ...
    def is_path_free(self, path: ArrayLike) -> bool: ...

class SynergyModel:
    @staticmethod
    def load(path: PathLike) -> SynergyModel: ...
    @staticmethod
    def default_for(robot_name: str) -> SynergyModel: ...
    def save(self, path: PathLike) -> None: ...
    def to_yaml(self) -> str: ...
    source: str
    joint_names: list[str]
    lower: np.ndarray
    upper: np.ndarray
    own_axis_joints: list[str]
    mean: np.ndarray
    directions: np.ndarray
    sigma: np.ndarray
    variance_fraction: np.ndarray
    cumulative_variance: np.ndarray
    orthonormal: bool
    provenance: str
    direction_count: int
    def coefficients(self, posture: Joints) -> np.ndarray: ...
    def posture(self, coefficients: ArrayLike) -> np.ndarray: ...
    def project(self, posture: Joints, directions: int = 4) -> np.ndarray: ...
    def distance_from_subspace(self, posture: Joints) -> np.ndarray: ...

def fit_synergies(postures: ArrayLike, joints: Union[Robot, Sequence[tuple[str, float, float]]],
                  own_axis_joints: Sequence[str] = ..., constant_tolerance: float = 1e-12,
                  provenance: str = "fitted from a numpy array") -> dict[str, Any]: ...

class PlannerSettings:
    initial_arm_half_size: float
    arm_box_growth: str
    neighbour_count: int
    neighbour_threshold_factor: float
    arm_trials: int
    hand_trials: int
    min_sweep_visits: int
    max_samples: int
    time_limit: float
    seed: int
    kappa: float
    max_pmds: int
    smooth: bool
    lazy_batch: int
    lazy_neighbours: int
    lazy_radius: float
    lazy_probes: int
    lazy_arm_growth: float
    sequence: str
    connect_range: float
    connect_round: int
    connect_arm_growth: float
    connect_probes: int
    def __init__(self, planner: str = "pmd") -> None: ...
    def check(self) -> None: ...

class PlanResult:
    task: str
    planner: str
    seed: int
    joint_names: list[str]
    call_seconds: float
    status: str
    solved: bool
    path: np.ndarray
    statistics: dict[str, Any]
    closing_from: Optional[int]
    def save(self, file: PathLike) -> None: ...

def planners() -> list[str]: ...
def plan(task: Task, planner: str = "pmd", *, settings: Optional[PlannerSettings] = None,
         checker: Union[str, CollisionChecker] = "fast", synergies: Union[None, SynergyModel, PathLike] = None,
         seed: Optional[int] = None, time_limit: Optional[float] = None, tolerance_mm: float = 1.0) -> PlanResult: ...
def validate(task: Task, path: Union[ArrayLike, PathLike], tolerance_mm: float = 1.0, *,
             closing_from: Optional[int] = None) -> dict[str, Any]: ...
def human_likeness(task: Task, path: ArrayLike, synergies: Union[None, SynergyModel, PathLike] = None,
                   step: float = 0.01, subspace_directions: int = 4) -> dict[str, float]: ...
