"""Whole-body IK on a URDF with `biped.Ik`: the G1's left foot steps 10 cm forward and lifts
5 cm while the right foot and the centre of mass stay, a soft posture holds the rest, and the
URDF's joint position and velocity limits are kept (on by default). The result is checked
with `biped.Model`'s forward kinematics. Run from the repository root:

    python python/examples/ik_urdf.py [ROBOT.urdf]
"""
import sys

import numpy as np

import biped

URDF = sys.argv[1] if len(sys.argv) > 1 else "crates/dynamics/data/g1_29dof_rev_1_0.urdf"
FEET = ("left_ankle_roll_link", "right_ankle_roll_link")

model = biped.Model.from_urdf(URDF, floating=True)
ik = biped.Ik(URDF, floating=True)

q = model.neutral()  # bent knees: a straight leg is singular for vertical foot motion
for joint, angle in [("hip_pitch", -0.3), ("knee", 0.6), ("ankle_pitch", -0.3)]:
    for side in ("left", "right"):
        q[model.q_names.index(f"{side}_{joint}_joint")] = angle

left, right = (model.frame_pose(q, foot) for foot in FEET)
step = left.copy()
step[:3, 3] += [0.10, 0.0, 0.05]
ik.frame_pose(FEET[0], step)
ik.frame_pose(FEET[1], right)
ik.com(model.com(q))
ik.posture(q, 1e-2)
for _ in range(300):
    q, report = ik.step(q, 0.01)

miss = np.linalg.norm(model.frame_pose(q, FEET[0])[:3, 3] - step[:3, 3])
print(f"left foot {miss:.1e} m from its target, smallest joint-limit margin {report['min_limit_margin']:.3f} rad")
