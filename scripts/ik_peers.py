"""Per-step time of the QP-based IK peers pink, mink and PlaCo on a walking-like humanoid task set,
beside `biped walk`'s IK cycle (issue: IK / walking).

Robot: the Unitree G1 URDF (29 joints + floating base, 35 velocity DoF; Lola-like has 31).
Tasks per step, both libraries alike: left and right foot frames (position + orientation),
centre of mass, pelvis orientation, posture regularisation; the CoM target sways sideways
and the left foot target lifts and moves forward like a step (targets move every cycle, as
in a 1 kHz walk). One timed step = set the targets, build and solve the QP (daqp for pink and
mink, PlaCo's own solver), integrate the velocity over dt = 1 ms (PlaCo: solve(True) + kinematics). Joint limits: each library's configuration limit.
Prints one JSON object per library with median and p99 step times in microseconds.

Usage: $PEERS_PY scripts/ik_peers.py G1.urdf MESHDIR [--steps 2000] [--peers pink,mink,placo]
           [--comfort crates/robots/data/g1.toml]
       (pip install pin-pink mink placo "qpsolvers[daqp]" into the peers venv first; PlaCo
       pins its own Pinocchio: where it conflicts, give it a venv of its own and run
       `--peers placo` with that venv's python)
"""
import argparse
import importlib.metadata
import json
import os
import re
import tempfile
import time

import numpy as np

DT = 1e-3
FEET = ("left_ankle_roll_link", "right_ankle_roll_link")
PELVIS = "pelvis"


def targets(k, com0, foot0):
    """CoM sway and a left-foot step as functions of the cycle index `k`."""
    t = k * DT
    com = com0 + np.array([0.05 * t, 0.04 * np.sin(2 * np.pi * t / 1.6), 0.0])
    phase = np.clip((t % 0.8) / 0.8, 0.0, 1.0)
    foot = foot0 + np.array([0.1 * phase, 0.0, 0.05 * np.sin(np.pi * phase)])
    return com, foot


def stats(samples):
    a = np.array(samples) * 1e6
    return {"median_us": float(np.median(a)), "p99_us": float(np.percentile(a, 99))}


def comfort_joints(path):
    """`[comfort.joints]` of a biped robot description file (joint name -> value)."""
    if path is None:
        return {}
    import tomllib

    with open(path, "rb") as f:
        return tomllib.load(f).get("comfort", {}).get("joints", {})


def run_pink(urdf, _meshdir, steps, pose):
    import pink
    import pinocchio as pin
    from pink.tasks import ComTask, FrameTask, PostureTask

    model = pin.buildModelFromUrdf(urdf, pin.JointModelFreeFlyer())
    data = model.createData()
    q = pin.neutral(model)
    q[2] = 0.75
    for name, value in pose.items():
        q[model.joints[model.getJointId(name)].idx_q] = value
    conf = pink.Configuration(model, data, q)
    feet = [FrameTask(f, position_cost=1.0, orientation_cost=1.0) for f in FEET]
    pelvis = FrameTask(PELVIS, position_cost=0.0, orientation_cost=1.0)
    com = ComTask(cost=1.0)
    posture = PostureTask(cost=1e-3)
    tasks = feet + [pelvis, com, posture]
    for task in tasks:
        task.set_target_from_configuration(conf)
    com0 = pin.centerOfMass(model, data, q).copy()
    left0 = feet[0].transform_target_to_world.copy()
    times = []
    for k in range(steps):
        start = time.perf_counter()
        c, f = targets(k, com0, left0.translation)
        com.set_target(c)
        target = left0.copy()
        target.translation = f
        feet[0].set_target(target)
        vel = pink.solve_ik(conf, tasks, DT, solver="daqp", safety_break=False)
        conf.integrate_inplace(vel, DT)
        times.append(time.perf_counter() - start)
    err = np.linalg.norm(pin.centerOfMass(model, data, conf.q) - c)
    return {"peer": "pink " + importlib.metadata.version("pin-pink"), "nv": model.nv, "final_com_error_m": float(err), **stats(times[100:])}


def run_mink(urdf, meshdir, steps, pose):
    import mink

    from mujoco_stand import load  # the same G1 model as the MuJoCo stand (scripts/)

    model = load(urdf, meshdir)
    conf = mink.Configuration(model)
    q = model.qpos0.copy()
    for name, value in pose.items():
        q[model.joint(name).qposadr[0]] = value
    conf.update(q)
    feet = [
        mink.FrameTask(f, "body", position_cost=1.0, orientation_cost=1.0) for f in FEET
    ]
    pelvis = mink.FrameTask(PELVIS, "body", position_cost=0.0, orientation_cost=1.0)
    com = mink.ComTask(cost=1.0)
    posture = mink.PostureTask(model, cost=1e-3)
    tasks = feet + [pelvis, com, posture]
    for task in tasks:
        task.set_target_from_configuration(conf)
    com0 = np.array(conf.data.subtree_com[1])
    left0 = conf.get_transform_frame_to_world(FEET[0], "body")
    limits = [mink.ConfigurationLimit(model)]
    times = []
    for k in range(steps):
        start = time.perf_counter()
        c, f = targets(k, com0, left0.translation())
        com.set_target(c)
        feet[0].set_target(mink.SE3.from_rotation_and_translation(left0.rotation(), f))
        vel = mink.solve_ik(conf, tasks, DT, solver="daqp", damping=1e-6, limits=limits)
        conf.integrate_inplace(vel, DT)
        times.append(time.perf_counter() - start)
    err = np.linalg.norm(np.array(conf.data.subtree_com[1]) - c)
    return {"peer": "mink " + importlib.metadata.version("mink"), "nv": model.nv, "final_com_error_m": float(err), **stats(times[100:])}


def run_placo(urdf, _meshdir, steps, pose):
    import placo

    # PlaCo loads meshes: give it the kinematic tree only.
    text = re.sub(r"<(visual|collision)\b.*?</\1>", "", open(urdf).read(), flags=re.S)
    path = os.path.join(tempfile.mkdtemp(), "robot.urdf")
    with open(path, "w") as out:
        out.write(text)
    robot = placo.RobotWrapper(path, placo.Flags.ignore_collisions)
    for name, value in pose.items():
        robot.set_joint(name, value)
    robot.set_T_world_frame("pelvis", np.array(
        [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.75], [0, 0, 0, 1]], dtype=float))
    robot.update_kinematics()
    solver = placo.KinematicsSolver(robot)
    solver.mask_fbase(False)
    solver.enable_joint_limits(True)
    solver.dt = DT
    feet = [solver.add_frame_task(f, robot.get_T_world_frame(f)) for f in FEET]
    for task in feet:
        task.configure("foot", "soft", 1.0, 1.0)
    pelvis = solver.add_orientation_task(PELVIS, robot.get_T_world_frame(PELVIS)[:3, :3])
    pelvis.configure("pelvis", "soft", 1.0)
    com0 = robot.com_world().copy()
    com = solver.add_com_task(com0)
    com.configure("com", "soft", 1.0)
    solver.add_regularization_task(1e-3)
    left0 = robot.get_T_world_frame(FEET[0]).copy()
    times = []
    for k in range(steps):
        start = time.perf_counter()
        c, f = targets(k, com0, left0[:3, 3])
        com.target_world = c
        target = left0.copy()
        target[:3, 3] = f
        feet[0].T_world_frame = target
        solver.solve(True)
        robot.update_kinematics()
        times.append(time.perf_counter() - start)
    err = np.linalg.norm(robot.com_world() - c)
    version = importlib.metadata.version("placo")
    return {"peer": "placo " + version, "nv": robot.model.nv, "final_com_error_m": float(err),
            **stats(times[100:])}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("urdf")
    ap.add_argument("meshdir")
    ap.add_argument("--steps", type=int, default=2000)
    ap.add_argument("--comfort", metavar="ROBOT.toml",
                    help="start at the [comfort.joints] pose of a biped robot description "
                         "(e.g. crates/robots/data/g1.toml, as `biped bench ik`); default: "
                         "the URDF's zero pose (straight legs)")
    ap.add_argument("--peers", default="pink,mink,placo",
                    help="comma-separated subset of pink, mink, placo, run in that order")
    args = ap.parse_args()
    runs = {"pink": run_pink, "mink": run_mink, "placo": run_placo}
    chosen = [p.strip() for p in args.peers.split(",") if p.strip()]
    unknown = [p for p in chosen if p not in runs]
    if unknown or not chosen:
        ap.error(f"--peers: unknown peer {unknown[0]!r} (choose from pink, mink, placo)"
                 if unknown else "--peers: no peer given")
    pose = comfort_joints(args.comfort)
    for name in chosen:
        print(json.dumps(runs[name](args.urdf, args.meshdir, args.steps, pose)), flush=True)


if __name__ == "__main__":
    main()
