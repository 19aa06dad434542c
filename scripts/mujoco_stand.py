"""MuJoCo's speed on a comparable humanoid stand, beside `biped simulate` (issue: simulation).

Loads the Unitree G1 URDF (29 DoF + floating base, from example-robot-data) into MuJoCo, adds a
free joint, a ground plane and a position actuator (PD) per joint, keeps only the feet
colliding with the ground, and times `mj_step` for a stand of DURATION seconds at a 1 ms step
with the chosen integrator. Prints one JSON object (realtime factor = sim time / wall time).

Usage: $PEERS_PY scripts/mujoco_stand.py G1.urdf MESHDIR [--integrator rk4|euler|implicitfast]
       [--duration 5]
"""
import argparse
import json
import re
import time

import mujoco


def load(urdf_path, meshdir):
    text = open(urdf_path).read()
    text = re.sub(r'filename="package://[^"]*/meshes/', 'filename="', text)
    text = text.replace(
        "<robot",
        "<robot",
        1,
    )
    text = re.sub(
        r"(<robot[^>]*>)",
        r'\1<mujoco><compiler meshdir="%s" discardvisual="true" balanceinertia="true"/></mujoco>'
        % meshdir,
        text,
        count=1,
    )
    spec = mujoco.MjSpec.from_string(text)
    root = spec.worldbody.first_body()
    root.add_freejoint()
    root.pos = [0, 0, 0.80]
    spec.worldbody.add_geom(
        type=mujoco.mjtGeom.mjGEOM_PLANE, size=[5, 5, 0.1], contype=1, conaffinity=1
    )
    for geom in spec.geoms:
        body = geom.parent.name if geom.parent else ""
        feet = "ankle_roll" in body
        if geom.type != mujoco.mjtGeom.mjGEOM_PLANE:
            geom.contype = 1 if feet else 0
            geom.conaffinity = 0 if feet else 0
    for joint in spec.joints:
        if joint.type == mujoco.mjtJoint.mjJNT_HINGE:
            act = spec.add_actuator()
            act.name = joint.name
            act.target = joint.name
            act.trntype = mujoco.mjtTrn.mjTRN_JOINT
            act.set_to_position(kp=300.0, kv=10.0)
    return spec.compile()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("urdf")
    ap.add_argument("meshdir")
    ap.add_argument("--integrator", default="rk4")
    ap.add_argument("--duration", type=float, default=5.0)
    args = ap.parse_args()
    model = load(args.urdf, args.meshdir)
    model.opt.timestep = 1e-3
    model.opt.integrator = {
        "euler": mujoco.mjtIntegrator.mjINT_EULER,
        "rk4": mujoco.mjtIntegrator.mjINT_RK4,
        "implicitfast": mujoco.mjtIntegrator.mjINT_IMPLICITFAST,
    }[args.integrator]
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    steps = int(round(args.duration / model.opt.timestep))
    # Settle the feet on the ground before timing.
    for _ in range(200):
        mujoco.mj_step(model, data)
    start = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    wall = time.perf_counter() - start
    print(
        json.dumps(
            {
                "peer": "mujoco " + mujoco.__version__,
                "model": "G1 (URDF)",
                "nq": model.nq,
                "nv": model.nv,
                "integrator": args.integrator,
                "sim_time": args.duration,
                "wall_time": wall,
                "realtime_factor": args.duration / wall,
                "base_height": float(data.qpos[2]),
                "contacts": int(data.ncon),
            }
        )
    )


if __name__ == "__main__":
    main()
