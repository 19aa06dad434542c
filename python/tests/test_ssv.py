"""SSV distances of the bindings against `biped ssv query` and `biped ssv model`, and the
vectorised form against single queries."""

import numpy as np
import pytest

import biped
from conftest import HUMANOID

KINDS = {"point": 1, "line": 2, "triangle": 3}


def random_shape(rng, kind):
    corners = rng.uniform(-1, 1, (KINDS[kind], 3)) + rng.uniform(-2, 2, 3)
    radius = float(rng.uniform(0, 0.5))
    value = corners[0].tolist() if kind == "point" else corners.tolist()
    return {kind: value, "radius": radius}, np.r_[corners.ravel(), radius]


def queries(n=60, seed=0):
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        ka, kb = list(KINDS)[i % 3], list(KINDS)[(i // 3) % 3]
        out.append((ka, kb, *random_shape(rng, ka), *random_shape(rng, kb)))
    return out


def test_distance_matches_cli(cli):
    qs = queries()
    answers = cli(["ssv", "query"], [{"a": a, "b": b} for _, _, a, _, b, _ in qs])
    for (_, _, a, _, b, _), ref in zip(qs, answers):
        r = biped.ssv.distance(a, b)
        assert r.distance == pytest.approx(ref["distance"], abs=1e-15)
        np.testing.assert_allclose(r.point_a, ref["point_a"], atol=1e-15)
        np.testing.assert_allclose(r.point_b, ref["point_b"], atol=1e-15)
        assert np.linalg.norm(r.normal) == pytest.approx(1.0)


def test_distance_by_hand():
    # unit sphere at the origin and a capsule of radius 0.5 on x = 3: d = 3 - 1 - 0.5
    r = biped.ssv.distance({"point": np.zeros(3), "radius": 1}, {"line": [[3, -1, 0], [3, 1, 0]], "radius": 0.5})
    assert r.distance == 1.5
    np.testing.assert_array_equal(r.point_a, [1, 0, 0])
    np.testing.assert_array_equal(r.point_b, [2.5, 0, 0])
    np.testing.assert_array_equal(r.normal, [1, 0, 0])


@pytest.mark.parametrize("threads", [1, 2])
def test_distances_equal_single_queries(threads):
    qs = queries(90, seed=1)
    for ka in KINDS:
        for kb in KINDS:
            rows = [q for q in qs if q[0] == ka and q[1] == kb]
            arr_a, arr_b = np.array([q[3] for q in rows]), np.array([q[5] for q in rows])
            res = biped.ssv.distances(ka, arr_a, kb, arr_b, threads=threads)
            for i, q in enumerate(rows):
                r = biped.ssv.distance(q[2], q[4])
                assert res.distance[i] == r.distance
                np.testing.assert_array_equal(res.point_a[i], r.point_a)
                np.testing.assert_array_equal(res.point_b[i], r.point_b)
                np.testing.assert_array_equal(res.normal[i], r.normal)


def test_distances_broadcast_one_row():
    caps = np.array([[3, -1, 0, 3, 1, 0, 0.5], [0, 0, 5, 1, 0, 5, 0.0]])
    res = biped.ssv.distances("point", [0, 0, 0, 1], "line", caps)
    np.testing.assert_allclose(res.distance, [1.5, 4.0])


def test_collision_model_matches_cli(cli):
    model = biped.ssv.CollisionModel(str(HUMANOID))
    assert model.pairs and model.activation_distance > 0
    for pose in model.poses:
        (ref,) = cli(["ssv", "model", str(HUMANOID), "--pose", pose, "--json"])
        model.update(pose)
        rows = model.distances()
        assert [(r[0], r[1]) for r in rows] == [(p["a"], p["b"]) for p in ref["pairs"]]
        for row, p in zip(rows, ref["pairs"]):
            assert row[2] == p["distance"] and row[3] == p["point_a"] and row[4] == p["point_b"]
        # the same posture given as an array of poses
        model.update(model.poses[pose])
        again = model.distances()
        for row, p in zip(again, ref["pairs"]):
            assert row[2] == pytest.approx(p["distance"], abs=1e-12)
        best = model.min_distance()
        assert best[2] == min(p["distance"] for p in ref["pairs"] if p["distance"] is not None)


def test_collision_model_moves_with_the_bodies():
    model = biped.ssv.CollisionModel(str(HUMANOID))
    name = next(iter(model.poses))
    poses = model.poses[name].copy()
    model.update(poses)
    before = {r[:2]: r[2] for r in model.distances()}
    poses[:, 2, 3] += 0.25  # every body up by 0.25 m: distances unchanged
    model.update(poses)
    for r in model.distances():
        assert r[2] == pytest.approx(before[r[:2]], abs=1e-12)
