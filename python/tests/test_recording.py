"""`biped.read_recording` against the recording tables `biped.walk` returns and the files
`biped walk` and `biped simulate` write; its errors."""

import gzip

import numpy as np
import pytest

import biped


def test_walk_recording_reads_as_the_walk_returned_it(tmp_path):
    summary, tables = biped.walk(steps=2, method="none", out=str(tmp_path))
    rec = biped.read_recording(tmp_path / "none_recording.csv.gz")
    table = tables["none_recording"]
    np.testing.assert_array_equal(rec.time, table["t"])
    for name, column in table.items():
        if name != "t":
            np.testing.assert_array_equal(rec.columns[name], column, err_msg=name)
    # Every body of the Lola-like model, its pose the seven columns of the file.
    model = biped.Model.lola("type2")
    assert rec.bodies == list(model.bodies)
    assert rec.poses.shape == (len(rec.time), len(rec.bodies), 7)
    # The poses are the model's forward kinematics of the recorded q (batch of every frame).
    q = np.stack([rec.columns[f"q[{n}]"] for n in model.q_names], axis=1)
    poses = model.body_poses(q)
    np.testing.assert_allclose(rec.poses[:, :, :3], poses[:, :, :3, 3], atol=2e-5)
    sole = rec.pose("l_sole")
    np.testing.assert_array_equal(sole[:, 2], table["body[l_sole].z"])
    # Unit quaternions, to the file's rounding.
    norms = np.linalg.norm(rec.poses[:, :, 3:], axis=2)
    assert np.max(np.abs(norms - 1.0)) < 1e-5
    with pytest.raises(KeyError, match="no body 'wing'"):
        rec.pose("wing")


def test_simulate_recording_at_100_hz(tmp_path):
    biped.simulate(duration=0.2, out=str(tmp_path))
    rec = biped.read_recording(tmp_path / "recording.csv.gz")
    np.testing.assert_allclose(np.diff(rec.time), 0.01, atol=1e-9)
    assert "q[root.z]" in rec.columns and "com.z" in rec.columns
    np.testing.assert_allclose(rec.pose("pelvis")[:, 2], rec.columns["q[root.z]"], atol=1e-5)


def test_bad_recordings_name_file_and_line(tmp_path):
    bad = tmp_path / "bad.csv.gz"
    with gzip.open(bad, "wt") as f:
        f.write("time,x\n0,1\n0.01\n")
    with pytest.raises(biped.BipedError, match=r"bad.csv.gz:3: 1 fields, the header has 2"):
        biped.read_recording(bad)
    plain = tmp_path / "plain.csv.gz"
    plain.write_text("time,x\n0,1\n")
    with pytest.raises(biped.BipedError, match="not a gzip-compressed recording"):
        biped.read_recording(plain)
    nothing = tmp_path / "x.csv"
    nothing.write_text("t,x\n")
    with pytest.raises(biped.BipedError, match=r"x.csv:1: the first column must be `time`"):
        biped.read_recording(nothing)
    with pytest.raises(OSError):
        biped.read_recording(tmp_path / "missing.csv.gz")
