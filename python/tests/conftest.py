"""Shared fixtures: the repository root, the `biped` command-line binary built by cargo (the
reference the bindings are compared with), models and valid random states."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import biped

ROOT = pathlib.Path(__file__).resolve().parents[2]
G1 = ROOT / "crates" / "dynamics" / "data" / "g1_29dof_rev_1_0.urdf"
HUMANOID = ROOT / "crates" / "ssv" / "data" / "humanoid.toml"


def _cli_path():
    if os.environ.get("BIPED_CLI"):
        return pathlib.Path(os.environ["BIPED_CLI"])
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "biped"


@pytest.fixture(scope="session")
def cli():
    """Runs the CLI with JSON Lines on stdin; returns the parsed output lines."""
    path = _cli_path()
    if not path.exists():
        if os.environ.get("BIPED_REQUIRE_CLI"):
            pytest.fail(f"{path} not built (cargo build --release)")
        pytest.skip(f"{path} not built (cargo build --release)")

    def run(args, lines=()):
        text = "".join(json.dumps(line) + "\n" for line in lines)
        out = subprocess.run([str(path), *args], input=text, capture_output=True, text=True, check=True)
        return [json.loads(line) for line in out.stdout.splitlines() if line.strip()]

    return run


@pytest.fixture(scope="session")
def cli_run():
    """Runs the CLI with arguments; returns the completed process (not checked)."""
    path = _cli_path()
    if not path.exists():
        if os.environ.get("BIPED_REQUIRE_CLI"):
            pytest.fail(f"{path} not built (cargo build --release)")
        pytest.skip(f"{path} not built (cargo build --release)")

    def run(args):
        return subprocess.run([str(path), *map(str, args)], capture_output=True, text=True)

    return run


# (model factory, CLI model options) of every model the tests cover.
MODELS = {
    "lola2": (lambda: biped.Model.lola("type2"), ["--lola", "type2"]),
    "lola3": (lambda: biped.Model.lola("type3"), ["--lola", "type3"]),
    "dill4": (lambda: biped.Model.dill(4), ["--dill", "4"]),
    "g1": (lambda: biped.Model.from_urdf(str(G1)), ["--urdf", str(G1)]),
    "g1_floating": (lambda: biped.Model.from_urdf(str(G1), floating=True), ["--urdf", str(G1), "--floating"]),
}


@pytest.fixture(scope="session", params=sorted(MODELS))
def case(request):
    """(name, model, CLI options) for each covered model."""
    make, options = MODELS[request.param]
    return request.param, make(), options


def random_states(model, n, seed=0):
    """`n` valid states (q near neutral with unit quaternions, v, and a third nv vector)."""
    rng = np.random.default_rng(seed)
    q = model.neutral() + 0.3 * rng.standard_normal((n, model.nq))
    for _name, iq, nq, _iv, _nv in model.joints:
        if nq == 7:
            quat = q[:, iq + 3 : iq + 7]
            quat /= np.linalg.norm(quat, axis=1, keepdims=True)
    v = rng.standard_normal((n, model.nv))
    x = rng.standard_normal((n, model.nv))
    return q, v, x
