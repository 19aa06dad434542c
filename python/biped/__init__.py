"""Multibody dynamics, centroidal quantities and swept-sphere distances for biped robots.

``Ik`` is the whole-body IK on a URDF (frame, CoM, posture and joint tasks, the URDF's joint
limits kept). ``Model`` loads a robot (URDF, the Lola-like biped, Dill(n)) and computes forward and inverse
dynamics, mass matrices, frame poses and Jacobians, the centre of mass and centroidal
momentum, for one state (1-D arrays) or a batch (2-D arrays, one row per state, computed in
parallel). ``biped.ssv`` holds the swept-sphere distances. ``simulate``, ``simulate_batch``
and ``walk`` run ``biped simulate`` / ``biped walk`` with their options as keywords and return
the summary and the recorded signals as numpy arrays; ``biped.distributed.sweep`` runs many
simulations as Ray tasks; ``read_recording`` reads the recordings for replay they write
(every body's pose at 100 frames per second). Invalid input raises
``BipedError`` (a ``ValueError``); unreadable files raise ``OSError``.
"""

from ._native import BipedError, Ik, Model
from . import ssv
from .recording import Recording, read_recording
from .run import simulate, simulate_batch, walk, walk_batch

__all__ = [
    "BipedError",
    "Ik",
    "Model",
    "Recording",
    "read_recording",
    "simulate",
    "simulate_batch",
    "ssv",
    "walk",
    "walk_batch",
]
