"""Batches (2-D arrays, one row per state) equal the single-state calls, bit for bit, for
every method and thread count."""

import numpy as np
import pytest

import biped
from conftest import random_states

N = 7


def methods(model):
    body = model.bodies[-1]
    return {
        "forward_on": (lambda q, v, x, **k: model.forward_dynamics(q, v, x, **k)),
        "forward_sparse": (lambda q, v, x, **k: model.forward_dynamics(q, v, x, algorithm="sparse", **k)),
        "inverse": (lambda q, v, x, **k: model.inverse_dynamics(q, v, x, **k)),
        "mass_matrix": (lambda q, v, x, **k: model.mass_matrix(q, **k)),
        "frame_pose": (lambda q, v, x, **k: model.frame_pose(q, body, **k)),
        "frame_jacobian": (lambda q, v, x, **k: model.frame_jacobian(q, body, reference="world", **k)),
        "body_poses": (lambda q, v, x, **k: model.body_poses(q, **k)),
        "com": (lambda q, v, x, **k: model.com(q, **k)),
        "com_jacobian": (lambda q, v, x, **k: model.com_jacobian(q, **k)),
        "centroidal_momentum": (lambda q, v, x, **k: model.centroidal_momentum(q, v, **k)),
        "centroidal_matrix": (lambda q, v, x, **k: model.centroidal_matrix(q, **k)),
        "centroidal_jacobian": (lambda q, v, x, **k: model.centroidal_jacobian(q, **k)),
    }


@pytest.mark.parametrize("threads", [1, 2, 3, None])
def test_batch_equals_single_calls(case, threads):
    _, model, _ = case
    q, v, x = random_states(model, N, seed=20)
    for name, f in methods(model).items():
        batch = f(q, v, x, threads=threads)
        single = np.stack([f(q[i], v[i], x[i]) for i in range(N)])
        assert batch.shape == single.shape, name
        np.testing.assert_array_equal(batch, single, err_msg=name)


def test_external_wrenches_single_and_batch():
    model = biped.Model.lola("type2")
    q, v, tau = random_states(model, 3, seed=21)
    fext = np.random.default_rng(0).standard_normal((3, model.nbodies, 6))
    batch = model.forward_dynamics(q, v, tau, fext=fext, threads=2)
    for i in range(3):
        np.testing.assert_array_equal(batch[i], model.forward_dynamics(q[i], v[i], tau[i], fext=fext[i]))
        back = model.inverse_dynamics(q[i], v[i], batch[i], fext=fext[i])
        np.testing.assert_allclose(back, tau[i], atol=1e-8)
    zero = model.forward_dynamics(q, v, tau, fext=np.zeros((3, model.nbodies, 6)))
    np.testing.assert_array_equal(zero, model.forward_dynamics(q, v, tau))


def test_empty_batch_and_lists():
    model = biped.Model.dill(2)
    assert model.forward_dynamics(np.zeros((0, 4)), np.zeros((0, 4)), np.zeros((0, 4))).shape == (0, 4)
    as_list = model.forward_dynamics([0.1, 0.2, 0.3, 0.4], [0, 0, 0, 0], [1, 2, 3, 4])
    np.testing.assert_array_equal(as_list, model.forward_dynamics(np.array([0.1, 0.2, 0.3, 0.4]), np.zeros(4), np.arange(1.0, 5)))


def test_bad_state_in_batch_is_named():
    model = biped.Model.lola("type2")
    q, v, tau = random_states(model, 5, seed=22)
    q[3, 3:7] = [0, 0, 0, 2.0]  # not a unit quaternion
    with pytest.raises(biped.BipedError, match="^state 3: "):
        model.forward_dynamics(q, v, tau, threads=2)
    # the failed call leaves the model usable
    np.testing.assert_array_equal(model.forward_dynamics(q[0], v[0], tau[0]), model.forward_dynamics(q[:1], v[:1], tau[:1])[0])
