"""Dynamics of the bindings against the `biped dynamics` command line (JSON Lines), and
against identities that do not use the function under test."""

import numpy as np
import pytest

from conftest import random_states

N = 6


@pytest.mark.parametrize("algorithm", ["on", "crba", "sparse"])
def test_forward_dynamics_matches_cli(case, cli, algorithm):
    _, model, options = case
    q, v, tau = random_states(model, N)
    lines = [{"q": q[i].tolist(), "v": v[i].tolist(), "tau": tau[i].tolist()} for i in range(N)]
    expected = np.array([r["qdd"] for r in cli(["dynamics", *options, "--algorithm", algorithm], lines)])
    got = model.forward_dynamics(q, v, tau, algorithm=algorithm)
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12)


def test_inverse_dynamics_matches_cli(case, cli):
    _, model, options = case
    q, v, a = random_states(model, N, seed=1)
    lines = [{"q": q[i].tolist(), "v": v[i].tolist(), "a": a[i].tolist()} for i in range(N)]
    expected = np.array([r["tau"] for r in cli(["dynamics", *options, "--inverse"], lines)])
    np.testing.assert_allclose(model.inverse_dynamics(q, v, a), expected, rtol=1e-12, atol=1e-12)


def test_mass_matrix_matches_cli(case, cli):
    _, model, options = case
    q, _, _ = random_states(model, N, seed=2)
    lines = [{"q": q[i].tolist()} for i in range(N)]
    expected = np.array([r["M"] for r in cli(["dynamics", *options, "--mass-matrix"], lines)])
    np.testing.assert_allclose(model.mass_matrix(q), expected, rtol=1e-12, atol=1e-12)


def test_model_description_matches_cli(case, cli):
    _, model, options = case
    (desc,) = cli(["model", *options, "--json"])
    assert (model.nq, model.nv) == (desc["nq"], desc["nv"])
    assert [j[0] for j in model.joints] == [j["name"] for j in desc["joints"]]
    assert model.bodies == desc["bodies"]
    np.testing.assert_array_equal(model.neutral(), desc["neutral"])
    assert len(model.q_names) == model.nq and len(model.v_names) == model.nv


def test_forward_inverse_and_mass_matrix_agree(case):
    # tau = M qdd + h: RNEA of the forward result gives tau back, and M from RNEA columns
    _, model, _ = case
    q, v, tau = random_states(model, 3, seed=3)
    qdd = model.forward_dynamics(q, v, tau)
    np.testing.assert_allclose(model.inverse_dynamics(q, v, qdd), tau, atol=1e-8)
    bias = model.inverse_dynamics(q[0], v[0], np.zeros(model.nv))
    lhs = model.inverse_dynamics(q[0], v[0], qdd[0]) - bias
    np.testing.assert_allclose(model.mass_matrix(q[0]) @ qdd[0], lhs, rtol=1e-9, atol=1e-9)


def test_centroidal_quantities_agree(case):
    # h_G = A_G v, J_L = top rows of A_G, p = m J_C v, dCoM/dq along v = J_C v
    _, model, _ = case
    q, v, _ = random_states(model, 2, seed=4)
    h = model.centroidal_momentum(q[0], v[0])
    ag = model.centroidal_matrix(q[0])
    np.testing.assert_allclose(ag @ v[0], h, rtol=1e-9, atol=1e-9)
    np.testing.assert_array_equal(model.centroidal_jacobian(q[0]), ag[:3])
    jc = model.com_jacobian(q[0])
    np.testing.assert_allclose(model.mass * jc @ v[0], h[3:], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(model.com(q[0]), model.com(q)[0])
