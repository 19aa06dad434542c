"""`biped.walk` against `biped walk` (summary.json and the CSV tables), and its errors."""

import csv
import gzip
import json

import numpy as np
import pytest

import biped

VOLATILE = {"wall_time", "realtime_factor", "status", "written_at", "ik_time_per_cycle_us"}


def _stable(value):
    if isinstance(value, dict):
        return {k: _stable(v) for k, v in value.items() if k not in VOLATILE and not k.startswith("ik_us")}
    if isinstance(value, list):
        return [_stable(v) for v in value]
    return value


def test_walk_equals_cli(cli_run, tmp_path):
    summary, tables = biped.walk(steps=2, method="none")
    done = cli_run(["walk", "--steps", "2", "--method", "none", "--out", tmp_path])
    assert done.returncode == 0, done.stderr
    reference = json.loads((tmp_path / "summary.json").read_text())
    assert _stable(summary) == _stable(reference)
    assert set(tables) == {"none", "none_trajectory", "none_recording"}
    for stem, table in tables.items():
        if stem.endswith("_recording"):
            with gzip.open(tmp_path / f"{stem}.csv.gz", "rt", newline="") as f:
                rows = list(csv.reader(f))
        else:
            with open(tmp_path / f"{stem}.csv", newline="") as f:
                rows = list(csv.reader(f))
        header, data = rows[0], np.array(rows[1:], dtype=float)
        assert len(header) == len(table)
        for k, name in enumerate(header):
            key = "t" if name == "time" else name
            np.testing.assert_allclose(table[key], data[:, k], rtol=1e-12, atol=1e-12, err_msg=f"{stem}: {name}")


def test_walk_errors(cli_run, tmp_path):
    with pytest.raises(biped.BipedError, match="--step-length"):
        biped.walk(step_length=3.0)
    with pytest.raises(biped.BipedError, match="--method"):
        biped.walk(method="moonwalk")
    with pytest.raises(biped.BipedError, match="unknown option `robot_name`"):
        biped.walk(robot_name="x")


def test_walk_batch_equals_walk():
    runs = [dict(steps=2, method="none"), dict(steps=2, method="compensation", step_length=0.3), dict(step_time=0.01)]
    batch = biped.walk_batch(runs, threads=2)
    assert isinstance(batch[2], biped.BipedError) and "--step-time" in str(batch[2])
    for options, got in zip(runs[:2], batch):
        summary, tables = biped.walk(**options)
        assert _stable(got[0]) == _stable(summary)
        assert got[1].keys() == tables.keys()
        for stem in tables:
            for k in tables[stem]:
                np.testing.assert_array_equal(got[1][stem][k], tables[stem][k], err_msg=f"{stem}: {k}")


def test_walk_robot_g1():
    summary, tables = biped.walk(robot="g1", steps=2, method="minimization")
    assert summary["robot"]["name"] == "g1" and summary["robot"]["dof"] == 35
    assert summary["violations"] == []
    assert summary["minimization"]["min_distance"] > 0 and summary["minimization"]["min_joint_margin"] >= 0
    assert set(tables) == {"minimization", "minimization_trajectory", "minimization_recording"}
    assert "q[left_knee_joint]" in tables["minimization_trajectory"]
    with pytest.raises(biped.BipedError, match="--robot"):
        biped.walk(robot="nosuch")


def test_walk_robot_g1_dynamic():
    summary, tables = biped.walk(robot="g1", steps=4, method="minimization", dynamic=True)
    d = summary["dynamic"]
    assert d["walked"] and d["fell_at"] is None
    assert d["contact_kept"] and d["friction_kept"] and d["limits_kept"] and d["collision_free"]
    assert d["end_stops"] and d["min_joint_margin"] > 0 and d["min_distance"] > 0
    assert d["distance"] > 0.95 * d["planned_distance"] > 0
    assert summary["violations"] == []
    assert {"dynamic", "dynamic_recording"} <= set(tables)
    x = tables["dynamic"]["base_x"]
    assert abs((x[-1] - x[0]) - d["distance"]) < 1e-6
    assert "q[left_knee_joint]" in tables["dynamic_recording"]
