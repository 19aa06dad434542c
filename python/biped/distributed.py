"""Parameter sweeps of ``biped simulate`` runs as Ray tasks on a cluster.

Connect first with ``ray.init(...)`` (``ray.init(address="HOST:PORT")`` for a cluster started
with ``ray start --head`` and joined by ``ray start --address HOST:PORT`` on every other
machine, each with this package installed); then ``sweep(list_of_option_dicts)`` runs them as
Ray tasks and returns what ``biped.simulate_batch`` (or, with ``command="walk"``,
``biped.walk_batch``) returns on one machine: the results in
input order, each ``(summary, signals)`` or the ``BipedError`` of a run that failed.

Runs are grouped into chunks, one Ray task each, sized from a first pilot run so that a task
takes about ``min_task_seconds`` (0.1 s by default) and Ray's per-task overhead stays small.
"""

from __future__ import annotations

import math
import sys
import time
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

from . import _native
from ._native import BipedError
from .run import _batch

_REMOTE = None


def _ray():
    try:
        import ray
    except ImportError:
        raise BipedError(
            'biped.distributed needs Ray: pip install "biped[ray]" (or pip install ray)'
        ) from None
    return ray


def _chunk_task(ray):
    """The Ray task: one chunk of runs on one core, with the node and time it took."""
    global _REMOTE
    if _REMOTE is None:

        def run_chunk(command: str, batch: List[List[str]], keep_signals: bool):
            start = time.perf_counter()
            run_batch = _native.walk_batch if command == "walk" else _native.simulate_batch
            results = run_batch(batch, 1)
            if not keep_signals:
                results = [r if isinstance(r, BaseException) else (r[0], {}) for r in results]
            node = ray.get_runtime_context().get_node_id()
            return results, node, time.perf_counter() - start

        _REMOTE = ray.remote(num_cpus=1)(run_chunk)
    return _REMOTE


def sweep(
    runs: Sequence[Mapping[str, Any]],
    chunk_size: Optional[int] = None,
    *,
    command: str = "simulate",
    signals: bool = True,
    progress: bool = True,
    min_task_seconds: float = 0.1,
    stats: Optional[Dict[str, Any]] = None,
) -> List[Union[tuple, BipedError]]:
    """Runs every option dict of ``runs`` as Ray tasks; results in input order.

    ``command`` is ``"simulate"`` (each run as ``biped.simulate``, the results those of
    ``simulate_batch``) or ``"walk"`` (as ``biped.walk``, those of ``walk_batch``).
    ``chunk_size`` runs per task (default: from a pilot run, so that a task takes at least
    ``min_task_seconds``); ``signals=False`` returns empty signal dicts (summaries only, far
    less data over the network); ``progress`` prints the runs done to stderr; ``stats``, if
    given, receives ``chunks``, ``chunk_size``, ``nodes`` (the node ids that ran chunks) and
    ``seconds``.
    """
    ray = _ray()
    if not ray.is_initialized():
        raise BipedError("biped.distributed.sweep: connect to a cluster first with ray.init(...)")
    if chunk_size is not None and (not isinstance(chunk_size, int) or chunk_size < 1):
        raise BipedError(f"sweep: chunk_size must be a whole number >= 1, not {chunk_size!r}")
    if command not in ("simulate", "walk"):
        raise BipedError(f'sweep: command must be "simulate" or "walk", not {command!r}')
    batch = _batch(command, runs)
    start = time.perf_counter()
    task = _chunk_task(ray)
    results: List[Any] = [None] * len(batch)
    nodes = set()
    pending = {}
    done_runs = 0
    first = 0
    if chunk_size is None and batch:
        # The pilot: one run, timed where it ran, sizes the chunks of the rest.
        out, node, seconds = ray.get(task.remote(command, batch[:1], signals))
        results[0], first = out[0], 1
        nodes.add(node)
        done_runs = 1
        chunk_size = max(1, math.ceil(min_task_seconds / max(seconds, 1e-6)))
    chunk_size = chunk_size or 1
    for lo in range(first, len(batch), chunk_size):
        hi = min(lo + chunk_size, len(batch))
        pending[task.remote(command, batch[lo:hi], signals)] = (lo, hi)
    chunks = len(pending) + first
    while pending:
        ready, _ = ray.wait(list(pending), num_returns=1)
        for ref in ready:
            lo, hi = pending.pop(ref)
            try:
                out, node, _ = ray.get(ref)
                nodes.add(node)
            except Exception as e:  # a lost worker or node: its runs fail, the others go on
                out = [BipedError(f"sweep: the Ray task of runs {lo}-{hi - 1} failed: {e}")] * (hi - lo)
            results[lo:hi] = out
            done_runs += hi - lo
            if progress:
                print(f"\rsweep: {done_runs}/{len(batch)} runs", end="", file=sys.stderr, flush=True)
    if progress and batch:
        print(file=sys.stderr)
    if stats is not None:
        stats.update(
            chunks=chunks,
            chunk_size=chunk_size,
            nodes=sorted(nodes),
            seconds=time.perf_counter() - start,
        )
    return results
