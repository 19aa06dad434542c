"""Frame poses, Jacobians and CoM Jacobians against central finite differences of the poses
and the CoM (fixed-base models, where v = dq/dt)."""

import numpy as np
import pytest

import biped
from conftest import G1, random_states


def fixed_base_models():
    return [biped.Model.dill(3), biped.Model.from_urdf(str(G1))]


def numeric_jacobian(f, q, eps=1e-6):
    cols = []
    for i in range(q.size):
        dq = np.zeros_like(q)
        dq[i] = eps
        cols.append((f(q + dq) - f(q - dq)) / (2 * eps))
    return np.stack(cols, axis=-1)


@pytest.mark.parametrize("model", fixed_base_models(), ids=["dill3", "g1"])
def test_frame_jacobian_is_pose_derivative(model):
    q, _, _ = random_states(model, 1, seed=5)
    q = q[0]
    body = model.bodies[-1]
    point = [0.01, -0.02, 0.03]
    jac = model.frame_jacobian(q, body, point=point)
    pos = lambda x: model.frame_pose(x, body, point=point)[:3, 3]
    np.testing.assert_allclose(jac[3:], numeric_jacobian(pos, q), atol=1e-7)
    # angular rows: d R / dq_i R^T is the cross-product matrix of column i
    rot = lambda x: model.frame_pose(x, body)[:3, :3]
    d_rot = numeric_jacobian(rot, q)
    r = rot(q)
    for i in range(model.nv):
        w = d_rot[:, :, i] @ r.T
        np.testing.assert_allclose([w[2, 1], w[0, 2], w[1, 0]], jac[:3, i], atol=1e-7)
    local = model.frame_jacobian(q, body, reference="local", point=point)
    np.testing.assert_allclose(local[:3], r.T @ jac[:3], atol=1e-12)


@pytest.mark.parametrize("model", fixed_base_models(), ids=["dill3", "g1"])
def test_com_jacobian_is_com_derivative(model):
    q, _, _ = random_states(model, 1, seed=6)
    np.testing.assert_allclose(model.com_jacobian(q[0]), numeric_jacobian(model.com, q[0]), atol=1e-7)


def test_body_poses_match_frame_pose():
    model = biped.Model.lola("type2")
    q, _, _ = random_states(model, 1, seed=7)
    poses = model.body_poses(q[0])
    for i, name in enumerate(model.bodies):
        np.testing.assert_array_equal(poses[i], model.frame_pose(q[0], name))
    np.testing.assert_allclose(poses[:, 3], np.tile([0, 0, 0, 1.0], (model.nbodies, 1)))
