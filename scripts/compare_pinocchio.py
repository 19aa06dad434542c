#!/usr/bin/env python3
"""Offline cross-check of `biped dynamics` against Pinocchio on one URDF (not run in CI).

Usage (with the peers venv, see /work/shared/peers/setup.sh):
    $PEERS_PY scripts/compare_pinocchio.py ROBOT.urdf [--floating] [--biped PATH] [--samples N]

Loads the URDF in both libraries, maps coordinates by joint name (our free joint "root" is
Pinocchio's "root_joint"; Pinocchio's unbounded revolute joints use (cos, sin) coordinates),
draws random states and prints, per quantity, the largest relative error
max_k ||ours_k - pin_k||_inf / max(||pin_k||_inf, 1):
  aba_<algo>  forward dynamics (our O(n), CRBA, sparse LTL) vs pinocchio.aba
  crba        mass matrix vs pinocchio.crba (symmetrised)
  rnea        inverse dynamics vs pinocchio.rnea
"""
import argparse, json, os, subprocess, sys
import numpy as np
import pinocchio as pin

HERE = os.path.dirname(os.path.abspath(__file__))


def biped(exe, args, lines=None, allow_line_errors=False):
    """Runs our CLI; returns parsed JSON output lines (lines may be {"error"} if allowed)."""
    text = "".join(json.dumps(l) + "\n" for l in (lines or []))
    out = subprocess.run([exe] + args, input=text, capture_output=True, text=True)
    answers = [json.loads(l) for l in out.stdout.splitlines()]
    line_errors = out.returncode == 1 and answers and allow_line_errors
    if out.returncode != 0 and not line_errors:
        sys.exit(f"biped {' '.join(args)} failed ({out.returncode}):\n{out.stdout[:2000]}\n{out.stderr}")
    return answers


class Mapping:
    """Coordinate maps between our model (by joint order) and Pinocchio's (by joint name)."""

    def __init__(self, ours, pm):
        self.joints = []  # (our q idx, our nq, our v idx, nv, pin joint)
        qi = vi = 0
        for j in ours["joints"]:
            name = "root_joint" if j["name"] == "root" else j["name"]
            if not pm.existJointName(name):
                sys.exit(f"joint {name} missing in Pinocchio's model")
            pj = pm.joints[pm.getJointId(name)]
            if pj.nv != j["nv"]:
                sys.exit(f"joint {name}: nv {j['nv']} vs Pinocchio {pj.nv}")
            self.joints.append((qi, j["nq"], vi, j["nv"], pj))
            qi += j["nq"]
            vi += j["nv"]
        self.nq, self.nv = qi, vi
        self.vperm = np.concatenate([np.arange(pj.idx_v, pj.idx_v + nv) for _, _, _, nv, pj in self.joints]) \
            if self.joints else np.zeros(0, dtype=int)

    def q_to_ours(self, q):
        out = np.zeros(self.nq)
        for qi, nq, _, _, pj in self.joints:
            part = q[pj.idx_q:pj.idx_q + pj.nq]
            if pj.nq == nq:
                out[qi:qi + nq] = part
            elif pj.nq == 2 and nq == 1:  # unbounded revolute: (cos, sin)
                out[qi] = np.arctan2(part[1], part[0])
            else:
                sys.exit(f"cannot map joint with nq {pj.nq} to {nq}")
        return out

    def v_to_ours(self, v):
        return v[self.vperm]


def rel(a, b):
    return float(np.max(np.abs(a - b)) / max(np.max(np.abs(b)), 1.0))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("urdf")
    ap.add_argument("--floating", action="store_true")
    ap.add_argument("--biped", default=os.environ.get("BIPED", os.path.join(HERE, "..", "target", "release", "biped")))
    ap.add_argument("--samples", type=int, default=20)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    src = ["--urdf", a.urdf] + (["--floating"] if a.floating else [])
    ours = biped(a.biped, ["model"] + src + ["--json"])[0]
    pm = pin.buildModelFromUrdf(a.urdf, pin.JointModelFreeFlyer()) if a.floating else pin.buildModelFromUrdf(a.urdf)
    pd = pm.createData()
    mp = Mapping(ours, pm)
    if (mp.nq, mp.nv) != (ours["nq"], ours["nv"]) or mp.nv != pm.nv:
        sys.exit(f"size mismatch: ours nq {ours['nq']} nv {ours['nv']}, Pinocchio nq {pm.nq} nv {pm.nv}")
    np.random.seed(a.seed)
    lo, hi = -np.ones(pm.nq), np.ones(pm.nq)
    states = []
    for _ in range(a.samples):
        q = pin.randomConfiguration(pm, lo, hi)
        states.append((q, np.random.uniform(-1, 1, pm.nv), np.random.uniform(-1, 1, pm.nv), np.random.uniform(-1, 1, pm.nv)))
    ours_q = [mp.q_to_ours(q) for q, _, _, _ in states]
    err = {}
    fwd = [{"q": oq.tolist(), "v": mp.v_to_ours(v).tolist(), "tau": mp.v_to_ours(t).tolist()}
           for oq, (q, v, t, _) in zip(ours_q, states)]
    for algo in ["on", "crba", "sparse"]:
        res = biped(a.biped, ["dynamics"] + src + ["--algorithm", algo], fwd, allow_line_errors=True)
        bad = [r["error"] for r in res if "error" in r]
        if bad:  # e.g. massless leaf bodies: M is singular, Pinocchio's ABA divides by zero too
            err["aba_" + algo] = f"{len(bad)}/{len(res)} states rejected: {bad[0]}"
            continue
        err["aba_" + algo] = max(rel(np.array(r["qdd"]), mp.v_to_ours(pin.aba(pm, pd, q, v, t)))
                                 for r, (q, v, t, _) in zip(res, states))
    res = biped(a.biped, ["dynamics"] + src + ["--mass-matrix"], [{"q": oq.tolist()} for oq in ours_q])
    worst = 0.0
    for r, (q, _, _, _) in zip(res, states):
        m = pin.crba(pm, pd, q)
        m = np.triu(m) + np.triu(m, 1).T
        worst = max(worst, rel(np.array(r["M"]), m[np.ix_(mp.vperm, mp.vperm)]))
    err["crba"] = worst
    err["crba_min_eig"] = float(min(np.linalg.eigvalsh(np.array(r["M"]))[0] for r in res))
    inv = [{"q": oq.tolist(), "v": mp.v_to_ours(v).tolist(), "a": mp.v_to_ours(acc).tolist()}
           for oq, (q, v, _, acc) in zip(ours_q, states)]
    res = biped(a.biped, ["dynamics"] + src + ["--inverse"], inv)
    err["rnea"] = max(rel(np.array(r["tau"]), mp.v_to_ours(pin.rnea(pm, pd, q, v, acc)))
                      for r, (q, v, _, acc) in zip(res, states))
    print(json.dumps({"urdf": os.path.basename(a.urdf), "floating": a.floating, "nv": pm.nv,
                      "samples": a.samples, "max_rel_err": err}))


if __name__ == "__main__":
    main()
