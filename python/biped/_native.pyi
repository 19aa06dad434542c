"""Type stubs of the native module ``biped._native`` (re-exported by ``biped``).

Every array method of ``Model`` takes one state (1-D arrays, e.g. ``q`` of length ``nq``) or
a batch (2-D arrays, one row per state; all arguments batched alike) and returns the result
for one state or stacked along a leading batch axis. Batches are computed in parallel on
``threads`` threads (default: all cores) with the GIL released.
"""

from os import PathLike
from typing import Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike
Array = npt.NDArray[np.float64]
Point = Tuple[float, float, float]

class BipedError(ValueError):
    """Invalid input (model file, array, name or option); the message names what and where."""

class Model:
    """A multibody model with its dynamics, kinematics and centroidal quantities.

    Velocities and accelerations of a free (root) joint are ``[linear; angular]`` in the body
    frame, its position ``xyz`` plus the quaternion ``x y z w`` (Pinocchio's conventions).
    Spatial rows of Jacobians and momenta are ``[angular; linear]``.
    """

    @staticmethod
    def from_urdf(path: Union[str, PathLike], floating: bool = False, reject_mimic: bool = False) -> Model:
        """Loads a URDF file; ``floating`` adds a free-flyer root joint named "root".

        Raises ``OSError`` if the file cannot be read, ``BipedError`` if it is not valid.
        """
    @staticmethod
    def lola(kind: str) -> Model:
        """The Lola-like biped: ``"type2"`` (rigid drives) or ``"type3"`` (elastic gears)."""
    @staticmethod
    def dill(n: int) -> Model:
        """Featherstone's Dill(n) benchmark tree (2^n revolute bodies, 0 <= n <= 16)."""
    def __reduce__(self) -> tuple:
        """Pickling: the model is rebuilt from its URDF text (not its path), Lola variant or
        Dill level, so it can be sent to another process or machine (a Ray worker)."""
    @property
    def nq(self) -> int:
        """Number of position coordinates."""
    @property
    def nv(self) -> int:
        """Number of velocity coordinates."""
    @property
    def nbodies(self) -> int:
        """Number of bodies."""
    @property
    def joints(self) -> List[Tuple[str, int, int, int, int]]:
        """Joints in coordinate order: ``(name, idx_q, nq, idx_v, nv)``."""
    @property
    def bodies(self) -> List[str]:
        """Body names in body-index order (the frames of ``frame_pose``, ``frame_jacobian``)."""
    @property
    def q_names(self) -> List[str]:
        """Names of the position coordinates, in ``q`` order."""
    @property
    def v_names(self) -> List[str]:
        """Names of the velocity coordinates, in ``v`` order."""
    @property
    def warnings(self) -> List[str]:
        """Import warnings (e.g. ignored URDF ``<mimic>`` joints)."""
    @property
    def mass(self) -> float:
        """Total mass in kg."""
    def neutral(self) -> Array:
        """The neutral configuration (zero joint angles, identity quaternions)."""
    def forward_dynamics(
        self,
        q: ArrayLike,
        v: ArrayLike,
        tau: ArrayLike,
        algorithm: str = "on",
        fext: Optional[ArrayLike] = None,
        threads: Optional[int] = None,
    ) -> Array:
        """Joint accelerations ``qdd`` (nv) for ``(q, v, tau)``.

        ``algorithm``: ``"on"`` (O(n) three-pass), ``"crba"`` (mass matrix + dense Cholesky)
        or ``"sparse"`` (mass matrix + sparse LTL). ``fext``: per-body wrenches (nbodies x 6,
        rows ``[torque; force]`` in the body frame about its origin).
        """
    def inverse_dynamics(
        self,
        q: ArrayLike,
        v: ArrayLike,
        a: ArrayLike,
        fext: Optional[ArrayLike] = None,
        threads: Optional[int] = None,
    ) -> Array:
        """Joint forces ``tau`` (nv) for ``(q, v, a)`` by RNEA, optional body wrenches ``fext``."""
    def mass_matrix(self, q: ArrayLike, threads: Optional[int] = None) -> Array:
        """Joint-space mass matrix ``M(q)`` (nv x nv, CRBA)."""
    def frame_pose(
        self, q: ArrayLike, name: str, point: Optional[Point] = None, threads: Optional[int] = None
    ) -> Array:
        """World pose (4x4 homogeneous) of body ``name``'s frame, origin moved to ``point``
        (body coordinates)."""
    def body_poses(self, q: ArrayLike, threads: Optional[int] = None) -> Array:
        """World poses (nbodies x 4 x 4) of all bodies, in ``bodies`` order."""
    def frame_jacobian(
        self,
        q: ArrayLike,
        name: str,
        reference: str = "local_world_aligned",
        point: Optional[Point] = None,
        threads: Optional[int] = None,
    ) -> Array:
        """Jacobian (6 x nv, rows ``[angular; linear]``) of body ``name``'s frame at ``point``.

        ``reference``: ``"local"`` (body axes), ``"local_world_aligned"`` (world axes, linear
        part the velocity of the point) or ``"world"`` (spatial, about the world origin).
        """
    def com(self, q: ArrayLike, threads: Optional[int] = None) -> Array:
        """Centre of mass (world, 3)."""
    def com_jacobian(self, q: ArrayLike, threads: Optional[int] = None) -> Array:
        """CoM Jacobian ``J_C`` (3 x nv)."""
    def centroidal_momentum(self, q: ArrayLike, v: ArrayLike, threads: Optional[int] = None) -> Array:
        """Centroidal momentum ``h_G = [L_G; p]`` (6, world axes, about the CoM)."""
    def centroidal_matrix(self, q: ArrayLike, threads: Optional[int] = None) -> Array:
        """Centroidal momentum matrix ``A_G`` (6 x nv, ``h_G = A_G v``)."""
    def centroidal_jacobian(self, q: ArrayLike, threads: Optional[int] = None) -> Array:
        """Angular-momentum Jacobian ``J_L`` (3 x nv, ``L_G = J_L v``): the top rows of ``A_G``."""

class Ik:
    """Whole-body differential IK on a URDF (``biped_control::ik::Ik``): hard frame, CoM and
    joint tasks and a soft posture by name; the URDF's joint position (0.01 rad margin) and
    velocity limits are kept by every step. Task methods return a handle for ``set_target``."""

    def __init__(self, path: Union[str, PathLike], floating: bool = True) -> None: ...
    @property
    def nq(self) -> int:
        """Length of ``q``."""
    def frame_pose(self, link: str, pose: ArrayLike) -> int:
        """Link ``link``'s frame to the world pose ``pose`` (4x4)."""
    def frame_position(self, link: str, position: ArrayLike) -> int:
        """Link ``link``'s origin to the world point ``position``."""
    def frame_orientation(self, link: str, rotation: ArrayLike) -> int:
        """Link ``link``'s orientation to the world rotation ``rotation`` (3x3)."""
    def com(self, position: ArrayLike) -> int:
        """The centre of mass to ``position``."""
    def posture(self, q: ArrayLike, weight: float) -> int:
        """Soft task: every limited joint towards ``q``."""
    def joint(self, name: str, target: float) -> int:
        """Joint ``name`` to ``target``."""
    def set_target(self, task: int, target: ArrayLike) -> None:
        """Moves task ``task``'s target (same kind of value as when it was made)."""
    def step(self, q: ArrayLike, dt: float) -> Tuple[Array, Dict[str, float]]:
        """One step: the new ``q`` and ``{error_norm, joints_at_limits, min_limit_margin}``."""

class CollisionModel:
    """A collision model from a TOML file (``crates/ssv`` format), moved to body poses."""

    def __init__(self, path: Union[str, PathLike], within_activation: bool = False) -> None:
        """Loads the file; ``within_activation`` computes only pairs closer than d_a."""
    @property
    def bodies(self) -> List[str]:
        """Body names; ``update`` takes one pose per body in this order."""
    @property
    def segments(self) -> List[str]:
        """Segment names."""
    @property
    def pairs(self) -> List[Tuple[str, str]]:
        """Segment pairs as ``(name_a, name_b)``."""
    @property
    def activation_distance(self) -> float:
        """Activation distance d_a in metres."""
    @property
    def poses(self) -> Dict[str, Array]:
        """The file's named postures: name -> (nbodies, 4, 4) body poses."""
    def update(self, poses: Union[str, ArrayLike]) -> None:
        """Moves the segments to body poses ((nbodies, 4, 4)) or to a named posture."""
    def distances(
        self,
    ) -> List[Tuple[str, str, Optional[float], Optional[Point], Optional[Point]]]:
        """Every pair at the last update: ``(a, b, distance, point_a, point_b)``; ``None``
        entries for pairs beyond d_a that were not computed."""
    def min_distance(self) -> Optional[Tuple[str, str, float, Point, Point]]:
        """The closest computed pair ``(a, b, distance, point_a, point_b)``, or ``None``."""

def ssv_distance_json(a: str, b: str) -> Tuple[float, Point, Point, Point]:
    """Distance between two shapes in JSON text: ``(distance, point_a, point_b, normal)``."""

def ssv_distances(
    kind_a: str, a: ArrayLike, kind_b: str, b: ArrayLike, threads: Optional[int] = None
) -> Array:
    """Row-wise distances: (N, 10) rows ``[distance, point_a, point_b, normal]``."""

def simulate(words: List[str], controller: Optional[object] = None) -> Tuple[dict, Dict[str, Array]]:
    """``biped simulate`` with command-line ``words``: ``(summary, signals)`` (see ``biped.run``)."""

def simulate_batch(
    batch: List[List[str]], threads: Optional[int] = None
) -> List[Union[Tuple[dict, Dict[str, Array]], BipedError]]:
    """Every run of ``batch`` in parallel; results in input order, a failed run's error in its slot."""

def walk(words: List[str]) -> Tuple[dict, Dict[str, Dict[str, Array]]]:
    """``biped walk`` with command-line ``words``: ``(summary, tables by file stem)``."""

def walk_batch(
    batch: List[List[str]], threads: Optional[int] = None
) -> List[Union[Tuple[dict, Dict[str, Dict[str, Array]]], BipedError]]:
    """Every walk of ``batch`` in parallel; results in input order, a failed walk's error in its slot."""

def option_spec(command: str) -> Dict[str, Tuple[bool, bool]]:
    """Options of ``biped <command>``: ``{keyword: (takes_value, repeatable)}``."""
