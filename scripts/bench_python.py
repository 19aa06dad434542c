#!/usr/bin/env python3
"""Python-level forward-dynamics timing: `biped.Model.forward_dynamics` against
`pinocchio.aba` on the same URDF (alternating rounds), and a batch of states per state with
1 and 2 threads against the single call. Needs a venv with both `biped` and `pin`.

Usage: python scripts/bench_python.py ROBOT.urdf [--floating] [--rounds 9] [--batch 10000]
Prints one JSON object of medians in ns per call (per state for batches).
"""
import argparse, json, time
import numpy as np
import biped
import pinocchio as pin


def per_call(f, n):
    t = time.perf_counter()
    for _ in range(n):
        f()
    return (time.perf_counter() - t) / n * 1e9


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("urdf")
    ap.add_argument("--floating", action="store_true")
    ap.add_argument("--rounds", type=int, default=9)
    ap.add_argument("--calls", type=int, default=3000)
    ap.add_argument("--batch", type=int, default=10000)
    a = ap.parse_args()
    ours = biped.Model.from_urdf(a.urdf, floating=a.floating)
    pm = pin.buildModelFromUrdf(a.urdf, pin.JointModelFreeFlyer()) if a.floating else pin.buildModelFromUrdf(a.urdf)
    pd = pm.createData()
    rng = np.random.default_rng(0)
    q, v, tau = ours.neutral(), rng.standard_normal(ours.nv), rng.standard_normal(ours.nv)
    pq = pin.neutral(pm)
    pv, ptau = rng.standard_normal(pm.nv), rng.standard_normal(pm.nv)
    n = a.batch
    off = 7 if a.floating else 0  # keep the root quaternion a unit quaternion
    qs = np.tile(q, (n, 1))
    qs[:, off:] += 0.1 * rng.standard_normal((n, ours.nq - off))
    vs, taus = rng.standard_normal((n, ours.nv)), rng.standard_normal((n, ours.nv))
    # Distinct states call after call: our forward dynamics reuses the kinematic pass for a
    # repeated (q, v), which would flatter the single-call figure.
    k = 64
    ours_states = [(qs[i].copy(), vs[i].copy(), taus[i].copy()) for i in range(k)]
    pin_states = [(pin.randomConfiguration(pm, -np.ones(pm.nq), np.ones(pm.nq)) if not a.floating else pq, vs[i].copy(), taus[i].copy()) for i in range(k)]
    reps = max(1, a.calls // k)

    def loop(f, states):
        def run():
            for _ in range(reps):
                for s in states:
                    f(*s)
        return run

    rows = {"biped_single": [], "pinocchio_aba": [], "biped_batch_1": [], "biped_batch_2": [], "biped_loop": []}
    for _ in range(a.rounds):
        rows["biped_single"].append(per_call(loop(ours.forward_dynamics, ours_states), 1) / (reps * k))
        rows["pinocchio_aba"].append(per_call(loop(lambda *s: pin.aba(pm, pd, *s), pin_states), 1) / (reps * k))
        for t in (1, 2):
            rows[f"biped_batch_{t}"].append(per_call(lambda: ours.forward_dynamics(qs, vs, taus, threads=t), 1) / n)
        rows["biped_loop"].append(per_call(lambda: [ours.forward_dynamics(qs[i], vs[i], taus[i]) for i in range(n)], 1) / n)
    med = {k: float(np.median(x)) for k, x in rows.items()}
    med.update(model=a.urdf, nv=ours.nv, pin_nv=pm.nv, rounds=a.rounds, batch=n)
    print(json.dumps(med))


if __name__ == "__main__":
    main()
