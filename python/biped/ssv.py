"""Swept-sphere volumes (SSVs): exact distances between spheres, capsules and rounded
triangles, and collision models of whole robots.

A shape is a dict as in ``biped ssv query``: ``{"point": [x, y, z], "radius": r}``,
``{"line": [p, q], "radius": r}`` or ``{"triangle": [p, q, s], "radius": r}`` (metres).
"""

import json
from typing import Any, Mapping, NamedTuple, Optional

import numpy as np

from ._native import CollisionModel, ssv_distance_json, ssv_distances

__all__ = ["CollisionModel", "Distance", "Distances", "distance", "distances"]


class Distance(NamedTuple):
    """Signed distance between two volumes (negative on overlap), the closest surface
    points and the unit normal from ``a`` towards ``b``."""

    distance: float
    point_a: np.ndarray
    point_b: np.ndarray
    normal: np.ndarray


class Distances(NamedTuple):
    """Row-wise results of :func:`distances`: shapes (N,), (N, 3), (N, 3), (N, 3)."""

    distance: np.ndarray
    point_a: np.ndarray
    point_b: np.ndarray
    normal: np.ndarray


def _plain(value: Any) -> Any:
    """JSON form of numpy values inside a shape dict."""
    if hasattr(value, "tolist"):
        return value.tolist()
    raise TypeError(f"not a number or array: {value!r}")


def distance(a: Mapping[str, Any], b: Mapping[str, Any]) -> Distance:
    """Signed distance between two shapes given as dicts (see the module docstring)."""
    d, pa, pb, n = ssv_distance_json(json.dumps(a, default=_plain), json.dumps(b, default=_plain))
    return Distance(d, np.array(pa), np.array(pb), np.array(n))


def distances(kind_a: str, a: Any, kind_b: str, b: Any, threads: Optional[int] = None) -> Distances:
    """Distances between row i of ``a`` and row i of ``b``.

    ``kind_*`` is ``"point"``, ``"line"`` or ``"triangle"``; each row holds the corner
    coordinates and then the radius (4, 7 or 10 numbers). A single row (1-D) is paired with
    every row of the other array. Batches run in parallel on ``threads`` threads (default:
    all cores).
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.ndim == 1 and b.ndim == 2:
        a = np.broadcast_to(a, (b.shape[0],) + a.shape)
    elif b.ndim == 1 and a.ndim == 2:
        b = np.broadcast_to(b, (a.shape[0],) + b.shape)
    out = np.asarray(ssv_distances(kind_a, a, kind_b, b, threads))
    return Distances(out[..., 0], out[..., 1:4], out[..., 4:7], out[..., 7:10])
