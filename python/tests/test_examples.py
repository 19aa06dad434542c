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


def test_ik_urdf_reaches_the_target_inside_the_ranges():
    out = _run("ik_urdf.py")
    miss = float(out.split("left foot ")[1].split(" m ")[0])
    margin = float(out.split("margin ")[1].split(" rad")[0])
    assert miss < 1e-6 and margin >= 0.01 - 1e-9


def test_stand_gain_sweep():
    out = _run("stand_gain_sweep.py")
    assert out.count("bandwidth") == 15 and "failed" not in out


def test_friction_monte_carlo():
    out = _run("friction_monte_carlo.py", "2")
    assert out.strip().endswith("of 2")
