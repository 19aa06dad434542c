"""Simulations and walks with the options of ``biped simulate`` and ``biped walk``.

``simulate(**options)`` runs one scenario and returns ``(summary, signals)``: ``summary`` is the
dict of ``summary.json`` (``steps``, ``realtime_factor``, ``checks``, ``passed``, the ``final``
state ``t``/``q``/``v``, ...), ``signals`` a dict of 1-D numpy arrays, the time ``"t"`` and every
column of ``signals.csv``. With ``out=DIR`` it also writes the files ``biped simulate`` writes.
A ``controller(t, sensors)`` callable runs once per control cycle after the scenario's joint
PD: ``sensors`` is a dict of arrays (``joint_positions``, ``joint_velocities``,
``motor_positions``, ``motor_velocities``, ``motor_currents``, ``foot_wrenches`` (k x 6:
force, then moment about the foot body origin, in the foot frame), ``imu_orientation``
(w, x, y, z), ``imu_angular_velocity``, ``imu_linear_acceleration``, the PD's ``commands`` and
the ``actuators`` names); it returns one command per actuator (torques, N m) or ``None`` to
keep the PD's.

``simulate_batch(list_of_option_dicts, threads=None)`` runs many in parallel in Rust; its
results are in input order, each what ``simulate`` returns, or the ``BipedError`` of a run
that failed (the others complete).

``walk(**options)`` runs ``biped walk`` and returns ``(summary, tables)``: the dict of its
``summary.json`` and its CSV tables by file stem (``"none"``, ``"none_trajectory"``,
``"none_recording"``, ..., ``"dynamic"``, ``"dynamic_recording"``), each a dict of arrays. A fall or a violated verdict raises ``BipedError`` with
the line the command line exits with; ``allow_violations=True`` accepts violations.
``walk_batch(list_of_option_dicts, threads=None)`` runs walks in parallel like
``simulate_batch``, a fall's or violation's ``BipedError`` in its slot.
"""

from __future__ import annotations

from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _native
from ._native import BipedError
from ._options import words

Signals = Dict[str, np.ndarray]
Result = Tuple[Dict[str, Any], Signals]


def simulate(controller: Optional[Callable[[float, dict], Any]] = None, **options: Any) -> Result:
    """Runs ``biped simulate`` with ``options`` as keywords; returns ``(summary, signals)``."""
    return _native.simulate(words("simulate", options), controller)


def simulate_batch(
    runs: Sequence[Mapping[str, Any]], threads: Optional[int] = None
) -> List[Union[Result, BipedError]]:
    """Runs every option dict of ``runs`` in parallel (``threads``, default: all cores)."""
    return _native.simulate_batch(_batch("simulate", runs), threads)


def walk(**options: Any) -> Tuple[Dict[str, Any], Dict[str, Signals]]:
    """Runs ``biped walk`` with ``options`` as keywords; returns ``(summary, tables)``."""
    return _native.walk(words("walk", options))


def walk_batch(
    runs: Sequence[Mapping[str, Any]], threads: Optional[int] = None
) -> List[Union[Tuple[Dict[str, Any], Dict[str, Signals]], BipedError]]:
    """Runs every option dict of ``runs`` as ``walk`` in parallel; a failed walk's error in its slot."""
    return _native.walk_batch(_batch("walk", runs), threads)


def _batch(command: str, runs: Sequence[Mapping[str, Any]]) -> List[List[str]]:
    """The command-line words of every option dict of ``runs``."""
    batch = []
    for k, options in enumerate(runs):
        if not isinstance(options, Mapping):
            raise BipedError(f"{command}: run {k} is a {type(options).__name__}, not a dict")
        batch.append(words(command, options))
    return batch
