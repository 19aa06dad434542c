"""The scripts in python/examples run as their docstrings say (from the repository root) and
reach what they print."""

import subprocess
import sys

from conftest import ROOT


def _run(name, *args):
    done = subprocess.run(
        [sys.executable, str(ROOT / "python" / "examples" / name), *args],
        cwd=ROOT, capture_output=True, text=True, timeout=300,
    )
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_ik_urdf_reaches_the_targets_inside_the_ranges():
    out = _run("ik_urdf.py")
    assert "inside the joint ranges: True" in out
    error_mm = float(out.split("hand error ")[1].split(" mm")[0])
    assert error_mm < 0.2


def test_stand_gain_sweep():
    out = _run("stand_gain_sweep.py")
    assert out.count("bandwidth") == 15 and "failed" not in out


def test_friction_monte_carlo():
    out = _run("friction_monte_carlo.py", "2")
    assert out.strip().endswith("of 2")
