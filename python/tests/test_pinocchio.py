"""The bindings against Pinocchio on the bundled G1 URDF (free-flyer root), coordinates
matched by joint name; skipped where Pinocchio is not installed."""

import numpy as np
import pytest

import biped
from conftest import G1, random_states

pin = pytest.importorskip("pinocchio")


@pytest.fixture(scope="module")
def pair():
    ours = biped.Model.from_urdf(str(G1), floating=True)
    theirs = pin.buildModelFromUrdf(str(G1), pin.JointModelFreeFlyer())
    iq, iv = np.zeros(ours.nq, int), np.zeros(ours.nv, int)
    for name, q0, nq, v0, nv in ours.joints:
        jid = theirs.getJointId("root_joint" if name == "root" else name)
        iq[q0 : q0 + nq] = np.arange(theirs.idx_qs[jid], theirs.idx_qs[jid] + nq)
        iv[v0 : v0 + nv] = np.arange(theirs.idx_vs[jid], theirs.idx_vs[jid] + nv)
    return ours, theirs, theirs.createData(), iq, iv


def states(pair, seed):
    ours, _, _, iq, iv = pair
    q, v, x = random_states(ours, 3, seed)
    # Pinocchio's vector p has p[iq[k]] = ours[k], i.e. p = ours[argsort(iq)]
    return [(a, b, c, a[np.argsort(iq)], b[np.argsort(iv)], c[np.argsort(iv)]) for a, b, c in zip(q, v, x)]


def test_dynamics_match_pinocchio(pair):
    ours, m, d, iq, iv = pair
    for q, v, tau, pq, pv, ptau in states(pair, 10):
        np.testing.assert_allclose(ours.forward_dynamics(q, v, tau), pin.aba(m, d, pq, pv, ptau)[iv], rtol=1e-8, atol=1e-8)
        np.testing.assert_allclose(ours.inverse_dynamics(q, v, tau), pin.rnea(m, d, pq, pv, ptau)[iv], rtol=1e-8, atol=1e-8)
        mm = pin.crba(m, d, pq)
        mm = np.triu(mm) + np.triu(mm, 1).T
        np.testing.assert_allclose(ours.mass_matrix(q), mm[np.ix_(iv, iv)], rtol=1e-8, atol=1e-10)


def test_kinematics_and_centroidal_match_pinocchio(pair):
    ours, m, d, iq, iv = pair
    body = "left_ankle_roll_link"
    fid = m.getFrameId(body)
    for q, v, _, pq, pv, _ in states(pair, 11):
        np.testing.assert_allclose(ours.com(q), pin.centerOfMass(m, d, pq), atol=1e-12)
        pin.framesForwardKinematics(m, d, pq)
        np.testing.assert_allclose(ours.frame_pose(q, body), d.oMf[fid].homogeneous, atol=1e-12)
        jac = pin.computeFrameJacobian(m, d, pq, fid, pin.LOCAL_WORLD_ALIGNED)
        ref = np.vstack([jac[3:], jac[:3]])[:, iv]  # ours: rows [angular; linear]
        np.testing.assert_allclose(ours.frame_jacobian(q, body), ref, atol=1e-12)
        h = pin.computeCentroidalMomentum(m, d, pq, pv)
        np.testing.assert_allclose(ours.centroidal_momentum(q, v), np.r_[h.angular, h.linear], rtol=1e-9, atol=1e-10)
        ag = pin.computeCentroidalMap(m, d, pq)
        np.testing.assert_allclose(ours.centroidal_matrix(q), np.vstack([ag[3:], ag[:3]])[:, iv], atol=1e-10)
