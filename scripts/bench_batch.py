#!/usr/bin/env python3
"""Throughput of batched stands, in simulated seconds per wall second: `biped.simulate_batch`
of G1 stands against `mujoco.rollout` of the same G1 (scripts/mujoco_stand.py's model: the
URDF with a free joint, ground plane and a position actuator per joint) on the same threads,
and a `biped.distributed.sweep` on a local Ray instance against `simulate_batch`.

Usage (one side per call; alternate them in rounds):
  python scripts/bench_batch.py biped  G1.urdf [--runs 16] [--duration 2] [--threads 2]
  $PEERS_PY scripts/bench_batch.py mujoco G1.urdf --meshdir DIR [--integrator rk4|implicitfast]
  python scripts/bench_batch.py ray    G1.urdf     (Ray: sweep vs simulate_batch, same runs)
Prints one JSON object.
"""
import argparse
import json
import os
import sys
import time

FEET = "left_ankle_roll_link,right_ankle_roll_link"


def runs(a):
    return [
        dict(urdf=a.urdf, floating=True, feet=FEET, scenario="stand", duration=a.duration, every=1000)
        for _ in range(a.runs)
    ]


def bench_biped(a):
    import biped

    start = time.perf_counter()
    results = biped.simulate_batch(runs(a), threads=a.threads)
    wall = time.perf_counter() - start
    failed = [r for r in results if isinstance(r, Exception)]
    if failed:
        sys.exit(f"bench_batch: {failed[0]}")
    return dict(peer="biped.simulate_batch", integrator="rk4", wall_time=wall)


def bench_mujoco(a):
    import mujoco
    import numpy as np
    from mujoco import rollout

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from mujoco_stand import load

    model = load(a.urdf, a.meshdir)
    model.opt.timestep = 1e-3
    model.opt.integrator = {
        "rk4": mujoco.mjtIntegrator.mjINT_RK4,
        "implicitfast": mujoco.mjtIntegrator.mjINT_IMPLICITFAST,
    }[a.integrator]
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    state = np.empty(mujoco.mj_stateSize(model, spec))
    mujoco.mj_getState(model, data, state, spec)
    nstep = int(round(a.duration / model.opt.timestep))
    initial = np.tile(state, (a.runs, 1))
    control = np.zeros((a.runs, nstep, model.nu))
    datas = [mujoco.MjData(model) for _ in range(a.threads)]
    start = time.perf_counter()
    rollout.rollout(model, datas, initial, control, nstep=nstep)
    wall = time.perf_counter() - start
    return dict(peer="mujoco.rollout " + mujoco.__version__, integrator=a.integrator, wall_time=wall)


def bench_ray(a):
    import biped
    import biped.distributed
    import ray

    ray.init(num_cpus=a.threads, include_dashboard=False, log_to_driver=False)
    biped.distributed.sweep(runs(a)[:2], chunk_size=1, progress=False)  # start the workers
    out = {}
    for name, f in [
        ("simulate_batch", lambda: biped.simulate_batch(runs(a), threads=a.threads)),
        ("sweep", lambda: biped.distributed.sweep(runs(a), signals=False, progress=False, stats=out)),
    ]:
        start = time.perf_counter()
        f()
        out[name + "_wall_time"] = time.perf_counter() - start
    ray.shutdown()
    out["overhead"] = out["sweep_wall_time"] / out["simulate_batch_wall_time"] - 1.0
    out.pop("nodes", None)
    return dict(peer="ray " + ray.__version__, **out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("side", choices=["biped", "mujoco", "ray"])
    ap.add_argument("urdf")
    ap.add_argument("--meshdir")
    ap.add_argument("--runs", type=int, default=16)
    ap.add_argument("--duration", type=float, default=2.0)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--integrator", default="rk4")
    a = ap.parse_args()
    out = {"biped": bench_biped, "mujoco": bench_mujoco, "ray": bench_ray}[a.side](a)
    sim = a.runs * a.duration
    if "wall_time" in out:
        out["throughput"] = sim / out["wall_time"]
    print(json.dumps(dict(runs=a.runs, duration=a.duration, threads=a.threads, **out)))


if __name__ == "__main__":
    main()
