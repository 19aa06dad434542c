"""Multibody dynamics, centroidal quantities and swept-sphere distances for biped robots.

``Model`` loads a robot (URDF, the Lola-like biped, Dill(n)) and computes forward and inverse
dynamics, mass matrices, frame poses and Jacobians, the centre of mass and centroidal
momentum, for one state (1-D arrays) or a batch (2-D arrays, one row per state, computed in
parallel). ``biped.ssv`` holds the swept-sphere distances. Invalid input raises
``BipedError`` (a ``ValueError``); unreadable files raise ``OSError``.
"""

from ._native import BipedError, Model
from . import ssv

__all__ = ["BipedError", "Model", "ssv"]
