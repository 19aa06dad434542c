"""Recordings for replay that ``biped walk`` and ``biped simulate`` write (docs/recording.md).

``read_recording(path)`` reads one (``recording.csv.gz``, ``METHOD_recording.csv.gz``,
``dynamic_recording.csv.gz``, or the plain CSV of such a table) into a :class:`Recording`:
the frame times, every column by name and the body poses as one array.
"""

from __future__ import annotations

import csv
import gzip
import io
import os
from dataclasses import dataclass, field

import numpy as np

from ._native import BipedError

POSE_FIELDS = ("x", "y", "z", "qx", "qy", "qz", "qw")


@dataclass
class Recording:
    """One recording: ``time`` (frames,), ``columns`` by name (frames,) each (the body poses
    too, as ``body[NAME].x`` ...), ``bodies`` in model order and ``poses`` (frames, bodies, 7):
    ``x, y, z`` in m and the unit quaternion ``qx, qy, qz, qw`` of each body in the world."""

    time: np.ndarray
    columns: dict[str, np.ndarray]
    bodies: list[str] = field(default_factory=list)
    poses: np.ndarray = field(default_factory=lambda: np.zeros((0, 0, 7)))

    def pose(self, body: str) -> np.ndarray:
        """The poses of ``body`` over the frames, (frames, 7); ``KeyError`` naming the bodies
        for an unknown one."""
        try:
            return self.poses[:, self.bodies.index(body), :]
        except ValueError:
            raise KeyError(f"no body {body!r} in the recording (bodies: {', '.join(self.bodies[:5])}, ...)") from None


def _open_text(path: str):
    if path.endswith(".gz"):
        return io.TextIOWrapper(gzip.open(path, "rb"), newline="")
    return open(path, newline="")


def _body_names(header: list[str]) -> list[str]:
    names = []
    for c in header:
        if c.startswith("body[") and c.endswith("].x"):
            names.append(c[len("body[") : -len("].x")])
    return names


def read_recording(path: str | os.PathLike) -> Recording:
    """Reads a recording; a file that is not one raises ``BipedError`` naming the file and
    line, an unreadable one ``OSError``."""
    path = os.fspath(path)
    with _open_text(path) as f:
        try:
            reader = csv.reader(f)
            header = next(reader, None)
            if not header or header[0] != "time":
                raise BipedError(f"{path}:1: the first column must be `time`")
            rows = []
            for line, row in enumerate(reader, start=2):
                if len(row) != len(header):
                    raise BipedError(f"{path}:{line}: {len(row)} fields, the header has {len(header)}")
                try:
                    rows.append([float(v) for v in row])
                except ValueError as e:
                    raise BipedError(f"{path}:{line}: {e}") from None
        except (EOFError, gzip.BadGzipFile) as e:
            raise BipedError(f"{path}: not a gzip-compressed recording: {e}") from None
    data = np.array(rows, dtype=float).reshape(len(rows), len(header))
    columns = {name: data[:, k] for k, name in enumerate(header)}
    bodies = [b for b in _body_names(header) if all(f"body[{b}].{f}" in columns for f in POSE_FIELDS)]
    poses = np.stack([np.stack([columns[f"body[{b}].{f}"] for f in POSE_FIELDS], axis=-1) for b in bodies], axis=1) if bodies else np.zeros((len(rows), 0, 7))
    return Recording(time=columns["time"], columns=columns, bodies=bodies, poses=poses)
