"""A pickled model is rebuilt from what it was made of (the URDF text, not its path) and
computes the same results; a corrupted pickle raises instead of crashing."""

import pickle
import shutil

import numpy as np
import pytest

import biped
from conftest import G1


def _same(a, b, rng):
    assert (a.nq, a.nv, a.q_names, a.joints) == (b.nq, b.nv, b.q_names, b.joints)
    q = a.neutral()
    v, tau = rng.standard_normal(a.nv), rng.standard_normal(a.nv)
    assert np.array_equal(a.forward_dynamics(q, v, tau), b.forward_dynamics(q, v, tau))


def test_models_round_trip_through_pickle(tmp_path):
    rng = np.random.default_rng(7)
    path = tmp_path / "robot.urdf"
    shutil.copy(G1, path)
    urdf = biped.Model.from_urdf(path, floating=True)
    copy = pickle.loads(pickle.dumps(urdf))
    path.unlink()  # the copy carries the text, not the path
    _same(urdf, pickle.loads(pickle.dumps(copy)), rng)
    for model in [biped.Model.lola("type3"), biped.Model.dill(3)]:
        _same(model, pickle.loads(pickle.dumps(model)), rng)


def test_a_corrupted_pickle_raises():
    with pytest.raises(biped.BipedError):
        biped.Model._restore(("nonsense", "", "", False, False))
    with pytest.raises(biped.BipedError):
        biped.Model._restore(("urdf", "<robot name='r'>", "bad.urdf", False, False))
    with pytest.raises(biped.BipedError):
        biped.Model._restore(("dill", "99", "", False, False))
