"""Bad input raises `BipedError` (a ValueError) with the library's located message, or
`OSError` for unreadable files; nothing crashes the interpreter."""

import numpy as np
import pytest

import biped
from conftest import G1


@pytest.fixture(scope="module")
def lola():
    return biped.Model.lola("type2")


def test_error_type():
    assert issubclass(biped.BipedError, ValueError)


def test_wrong_lengths_and_shapes(lola):
    q, v = lola.neutral(), np.zeros(lola.nv)
    with pytest.raises(biped.BipedError, match=r'^"q" has 31 entries, expected 32$'):
        lola.forward_dynamics(q[:-1], v, v)
    with pytest.raises(biped.BipedError, match=r'"tau" has 30 entries'):
        lola.forward_dynamics(q, v, v[:-1])
    with pytest.raises(biped.BipedError, match="dimensions"):
        lola.mass_matrix(q.reshape(1, 1, -1))
    with pytest.raises(biped.BipedError, match="does not match"):
        lola.forward_dynamics(np.tile(q, (2, 1)), np.zeros((3, lola.nv)), np.zeros((2, lola.nv)))
    with pytest.raises(biped.BipedError, match="does not match"):
        lola.forward_dynamics(np.tile(q, (2, 1)), v, v)
    with pytest.raises(biped.BipedError, match='"fext" has shape'):
        lola.forward_dynamics(q, v, v, fext=np.zeros((3, 6)))
    with pytest.raises(biped.BipedError, match="expected an array of numbers"):
        lola.com("not numbers")


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_input(lola, bad):
    q, v = lola.neutral(), np.zeros(lola.nv)
    v_bad = v.copy()
    v_bad[4] = bad
    with pytest.raises(biped.BipedError, match=r'^"v"\[4\] is not finite$'):
        lola.forward_dynamics(q, v_bad, v)
    with pytest.raises(biped.BipedError, match=r'^state 1: "q"\[0\] is not finite$'):
        lola.com(np.array([q, np.r_[bad, q[1:]]]))
    with pytest.raises(biped.BipedError, match="not finite"):
        lola.frame_pose(q, "pelvis", point=[0, bad, 0])


def test_bad_options(lola):
    q, v = lola.neutral(), np.zeros(lola.nv)
    with pytest.raises(biped.BipedError, match="algorithm"):
        lola.forward_dynamics(q, v, v, algorithm="aba")
    with pytest.raises(biped.BipedError, match="reference"):
        lola.frame_jacobian(q, "pelvis", reference="LOCAL")
    with pytest.raises(biped.BipedError, match='unknown body "nose"'):
        lola.frame_pose(q, "nose")
    with pytest.raises(biped.BipedError, match="threads"):
        lola.com(q, threads=0)
    with pytest.raises(biped.BipedError, match="type4"):
        biped.Model.lola("type4")
    for n in (-1, 17):
        with pytest.raises(biped.BipedError, match="dill: level"):
            biped.Model.dill(n)


def test_bad_quaternion_is_an_error(lola):
    q = lola.neutral()
    q[3:7] = 0.0
    with pytest.raises(biped.BipedError):
        lola.forward_dynamics(q, np.zeros(lola.nv), np.zeros(lola.nv))


def test_model_files(tmp_path):
    with pytest.raises(FileNotFoundError, match="missing.urdf"):
        biped.Model.from_urdf(str(tmp_path / "missing.urdf"))
    with pytest.raises(OSError):
        biped.Model.from_urdf(str(tmp_path))  # a directory
    bad = tmp_path / "bad.urdf"
    bad.write_text('<robot name="r">\n  <link name="a"/>\n  <joint name="j" type="revolute">\n</robot>\n')
    with pytest.raises(biped.BipedError, match=r"bad\.urdf:\d+"):
        biped.Model.from_urdf(str(bad))
    model = biped.Model.from_urdf(G1)  # path-like objects are accepted
    assert model.nv == 29


def test_ssv_bad_input(tmp_path):
    ok = {"point": [0, 0, 0], "radius": 1}
    with pytest.raises(biped.BipedError, match=r'^"b": radius must be >= 0'):
        biped.ssv.distance(ok, {"point": [0, 0, 0], "radius": -1})
    with pytest.raises(biped.BipedError, match="exactly one"):
        biped.ssv.distance(ok, {"point": [0, 0, 0], "line": [[0, 0, 0], [1, 0, 0]], "radius": 1})
    with pytest.raises(biped.BipedError, match='"a"'):
        biped.ssv.distance({"point": [0, 0, float("nan")], "radius": 1}, ok)
    with pytest.raises(biped.BipedError, match='"a"'):
        biped.ssv.distance({"point": [0, 0], "radius": 1}, ok)
    with pytest.raises(biped.BipedError, match="unknown kind"):
        biped.ssv.distances("box", [0, 0, 0, 1], "point", [0, 0, 0, 1])
    with pytest.raises(biped.BipedError, match='"b" has rows of 4 entries, expected 7'):
        biped.ssv.distances("point", np.zeros((2, 4)), "line", np.zeros((2, 4)))
    with pytest.raises(biped.BipedError, match=r'^state 1: "a": '):
        biped.ssv.distances("point", [[0, 0, 0, 1], [0, 0, 0, -1]], "point", [[1, 0, 0, 0], [1, 0, 0, 0]])
    with pytest.raises(FileNotFoundError):
        biped.ssv.CollisionModel(str(tmp_path / "none.toml"))
    bad = tmp_path / "bad.toml"
    bad.write_text("activation_distance = -1\n")
    with pytest.raises(biped.BipedError, match=r"bad\.toml"):
        biped.ssv.CollisionModel(str(bad))


def test_collision_model_bad_poses():
    from conftest import HUMANOID

    model = biped.ssv.CollisionModel(str(HUMANOID))
    poses = model.poses[next(iter(model.poses))].copy()
    with pytest.raises(biped.BipedError, match="no pose named"):
        model.update("flying")
    with pytest.raises(biped.BipedError, match="expected"):
        model.update(poses[:-1])
    skew = poses.copy()
    skew[0, 0, 0] = 2.0
    with pytest.raises(biped.BipedError, match=r"poses\[0\]: rotation"):
        model.update(skew)
    skew = poses.copy()
    skew[2, 1, 3] = np.nan
    with pytest.raises(biped.BipedError, match=r"poses\[2\]: not finite"):
        model.update(skew)
