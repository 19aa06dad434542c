"""`biped.Ik` on the G1 URDF: it reaches reachable targets (checked by `Model`'s forward
kinematics), keeps every joint inside its URDF range (read here from the file itself) under a
target that asks to leave it, moves with its targets, and refuses bad input."""

import xml.etree.ElementTree as ET

import numpy as np
import pytest

import biped
from conftest import G1

FEET = ("left_ankle_roll_link", "right_ankle_roll_link")


@pytest.fixture(scope="module")
def g1():
    model = biped.Model.from_urdf(str(G1), floating=True)
    limits = {
        j.get("name"): (float(j.find("limit").get("lower")), float(j.find("limit").get("upper")))
        for j in ET.parse(G1).getroot().iter("joint")
        if j.find("limit") is not None and j.get("type") == "revolute"
    }
    names = model.q_names
    lower = np.array([limits.get(n, (-np.inf, np.inf))[0] for n in names])
    upper = np.array([limits.get(n, (-np.inf, np.inf))[1] for n in names])
    q = model.neutral()
    for joint, angle in [("hip_pitch", -0.3), ("knee", 0.6), ("ankle_pitch", -0.3)]:
        for side in ("left", "right"):
            q[names.index(f"{side}_{joint}_joint")] = angle
    return model, lower, upper, q


def test_reaches_a_foot_target(g1):
    model, _, _, q = g1
    ik = biped.Ik(str(G1))
    assert ik.nq == model.nq
    target = model.frame_pose(q, FEET[0])
    target[:3, 3] += [0.05, 0.02, 0.04]
    ik.frame_pose(FEET[0], target)
    ik.frame_pose(FEET[1], model.frame_pose(q, FEET[1]))
    ik.posture(q, 1e-2)
    for _ in range(200):
        q, _ = ik.step(q, 0.01)
    np.testing.assert_allclose(model.frame_pose(q, FEET[0]), target, atol=1e-6)


def test_limits_hold_when_targets_ask_to_leave_them(g1):
    model, lower, upper, q = g1
    ik = biped.Ik(str(G1))
    far = model.frame_pose(q, FEET[0])
    far[:3, 3] += [0.3, 0.0, 0.9]  # the leg would have to fold past its ranges
    ik.frame_position(FEET[0], far[:3, 3])
    ik.frame_pose(FEET[1], model.frame_pose(q, FEET[1]))
    worst, held = np.inf, 0
    for _ in range(300):
        q, report = ik.step(q, 0.01)
        worst = min(worst, report["min_limit_margin"])
        held = max(held, report["joints_at_limits"])
        inside = (q >= lower - 1e-12) & (q <= upper + 1e-12)
        assert inside[7:].all(), [n for n, ok in zip(model.q_names, inside) if not ok]
    assert worst >= 0.01 - 1e-9
    assert held > 0, "the target asked for nothing past a limit"


def test_moving_target(g1):
    model, _, _, q = g1
    ik = biped.Ik(str(G1))
    start = model.frame_pose(q, FEET[0])[:3, 3]
    task = ik.frame_position(FEET[0], start)
    for k in range(1, 101):
        ik.set_target(task, start + [0.0004 * k, 0.0, 0.0])
        q, _ = ik.step(q, 0.01)
    reached = model.frame_pose(q, FEET[0])[:3, 3]
    assert abs(reached[0] - (start[0] + 0.04)) < 2e-3


def test_offset_of_a_hand_from_the_com_in_yawed_axes(g1):
    model, _, _, q = g1
    ik = biped.Ik(str(G1))
    c, s = np.cos(0.4), np.sin(0.4)
    axes = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    hand = "left_wrist_yaw_link"

    def offset(q):
        return axes.T @ (model.frame_pose(q, hand)[:3, 3] - model.com(q))

    target = offset(q) + [0.03, 0.0, 0.02]
    for foot in FEET:
        ik.frame_pose(foot, model.frame_pose(q, foot))
    task = ik.offset(hand, "com", target, axes=axes)
    for _ in range(300):
        q, _ = ik.step(q, 0.01)
    np.testing.assert_allclose(offset(q), target, atol=1e-5)
    ik.set_target(task, target + [0.01, 0.0, 0.0])
    with pytest.raises(biped.BipedError, match="no_such_link"):
        ik.offset("subtree:no_such_link", "com", target)


def test_bad_input():
    ik = biped.Ik(str(G1))
    with pytest.raises(biped.BipedError, match="no_such_link"):
        ik.frame_position("no_such_link", [0, 0, 0])
    with pytest.raises(biped.BipedError, match="shape"):
        ik.com([0, 0])
    with pytest.raises(biped.BipedError, match="orthonormal"):
        ik.frame_orientation(FEET[0], np.ones((3, 3)))
    with pytest.raises(biped.BipedError, match="not finite"):
        ik.com([0, np.nan, 0])
    with pytest.raises(biped.BipedError):
        ik.step(np.zeros(3), 0.01)
    with pytest.raises(FileNotFoundError):
        biped.Ik("/no/such.urdf")
