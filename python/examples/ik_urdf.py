"""Differential IK on a URDF with biped's kinematics: the G1 (fixed pelvis) reaches two hand
targets while the posture stays close to its start, inside the URDF's joint ranges.

Damped least squares on the stacked hand position Jacobians, a posture term in the null
space, and each step clipped into the joint ranges. Run from the repository root:

    python python/examples/ik_urdf.py [ROBOT.urdf]
"""
import sys
import xml.etree.ElementTree as ET

import numpy as np

import biped

URDF = sys.argv[1] if len(sys.argv) > 1 else "crates/dynamics/data/g1_29dof_rev_1_0.urdf"
HANDS = ["left_wrist_yaw_link", "right_wrist_yaw_link"]

model = biped.Model.from_urdf(URDF)
# Joint ranges from the URDF, in the model's coordinate order.
limits = {
    j.get("name"): (float(j.find("limit").get("lower")), float(j.find("limit").get("upper")))
    for j in ET.parse(URDF).getroot().iter("joint")
    if j.find("limit") is not None and j.get("type") in ("revolute", "prismatic")
}
lower = np.array([limits[n][0] for n in model.q_names])
upper = np.array([limits[n][1] for n in model.q_names])

q = model.neutral()
q0 = q.copy()
start = [model.frame_pose(q, hand)[:3, 3] for hand in HANDS]
targets = [start[0] + [0.15, 0.05, 0.20], start[1] + [0.15, -0.05, 0.10]]

for step in range(200):
    error = np.concatenate([t - model.frame_pose(q, h)[:3, 3] for h, t in zip(HANDS, targets)])
    if np.linalg.norm(error) < 1e-4:
        break
    J = np.vstack([model.frame_jacobian(q, h)[3:] for h in HANDS])  # linear rows
    damped = J.T @ np.linalg.inv(J @ J.T + 1e-4 * np.eye(len(error)))
    null = np.eye(model.nv) - damped @ J
    dq = damped @ error + null @ (0.1 * (q0 - q))
    q = np.clip(q + dq, lower + 1e-3, upper - 1e-3)

print(f"{step} steps, hand error {np.linalg.norm(error) * 1e3:.2f} mm")
print("inside the joint ranges:", bool(np.all((q >= lower) & (q <= upper))))
