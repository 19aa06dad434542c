"""`biped.simulate` and `biped.simulate_batch` against the command line (`biped simulate`
writes summary.json and signals.csv, the reference), batch against single runs, the Python
controller in the loop, and bad input."""

import csv
import json

import numpy as np
import pytest

import biped

# What differs from one run to the next (wall-clock timing) or names the run's files.
VOLATILE = {"wall_time", "realtime_factor", "files", "status", "written_at"}


def _stable(summary):
    return {k: v for k, v in summary.items() if k not in VOLATILE}


def _read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array(rows[1:], dtype=float)
    return {name: data[:, k] for k, name in enumerate(header)}


@pytest.mark.parametrize(
    "options",
    [
        dict(scenario="stand", duration=0.4),
        dict(scenario="drop", duration=0.3, integrator="dopri5", lola="type2"),
        dict(scenario="stand", duration=0.2, bandwidth=30, pose={"l_shank": 0.1}, every=3),
    ],
)
def test_simulate_equals_cli(cli_run, tmp_path, options):
    summary, signals = biped.simulate(**options)
    args = ["simulate", "--out", tmp_path]
    for k, v in options.items():
        v = ",".join(f"{a}={b}" for a, b in v.items()) if isinstance(v, dict) else v
        args += ["--" + k.replace("_", "-"), v]
    done = cli_run(args)
    assert done.returncode == 0, done.stderr
    reference = json.loads((tmp_path / "summary.json").read_text())
    assert _stable(summary) == _stable(reference)
    table = _read_csv(tmp_path / "signals.csv")
    # The CSV's `time` column is the arrays' `t`; every other column is an array of its name.
    assert set(table) - {"time"} == set(signals) - {"t"}
    np.testing.assert_allclose(signals["t"], table["time"], rtol=0, atol=1e-12)
    for name, column in table.items():
        if name != "time":
            np.testing.assert_allclose(signals[name], column, rtol=1e-12, atol=1e-12, err_msg=name)


def test_summary_has_steps_checks_and_final_state():
    summary, signals = biped.simulate(scenario="stand", duration=0.3)
    assert summary["steps"] == 300 and summary["control_cycles"] == 300
    assert summary["realtime_factor"] > 0
    assert {c["name"] for c in summary["checks"]} and isinstance(summary["passed"], bool)
    final = summary["final"]
    assert final["t"] == pytest.approx(0.3)
    q_names = [k[2:-1] for k in signals if k.startswith("q[")]
    assert len(final["q"]) == len(q_names)
    # The final state is the last recorded row.
    last = np.array([signals[f"q[{n}]"][-1] for n in q_names])
    np.testing.assert_allclose(final["q"], last, rtol=0, atol=0)


def test_batch_equals_single_runs():
    runs = [dict(scenario="stand", duration=0.2, bandwidth=b) for b in (25.0, 40.0, 55.0)]
    runs.append(dict(scenario="drop", duration=0.2))
    runs.insert(2, dict(scenario="stand", integrator="leapfrog"))
    batch = biped.simulate_batch(runs, threads=2)
    assert len(batch) == len(runs)
    for options, got in zip(runs, batch):
        if options.get("integrator") == "leapfrog":
            assert isinstance(got, biped.BipedError)
            assert str(got).startswith("--integrator:")
            with pytest.raises(biped.BipedError, match="--integrator:"):
                biped.simulate(**options)
            continue
        summary, signals = biped.simulate(**options)
        assert _stable(got[0]) == _stable(summary)
        for k in signals:
            np.testing.assert_array_equal(got[1][k], signals[k], err_msg=k)


def test_controller_none_keeps_the_pd():
    seen = []

    def observe(t, sensors):
        seen.append((t, sensors))
        return None

    summary, signals = biped.simulate(scenario="stand", duration=0.1, controller=observe)
    plain, plain_signals = biped.simulate(scenario="stand", duration=0.1)
    assert _stable(summary) == _stable(plain)
    assert len(seen) == summary["control_cycles"]
    t, s = seen[5]
    n = len(s["actuators"])
    assert n > 0 and all(isinstance(a, str) for a in s["actuators"])
    for key in ("joint_positions", "joint_velocities", "motor_positions", "motor_velocities", "motor_currents", "commands"):
        assert s[key].shape == (n,), key
    assert s["foot_wrenches"].ndim == 2 and s["foot_wrenches"].shape[1] == 6
    assert s["imu_orientation"].shape == (4,)
    # The sample's joint positions are the recorded joint angles at that time.
    name = s["actuators"][0]
    k = int(np.argmin(np.abs(plain_signals["t"] - t)))
    assert s["joint_positions"][0] == pytest.approx(plain_signals[f"q[{name}]"][k], abs=1e-12)


def test_controller_commands_are_applied():
    target = {}

    def hold_one(t, sensors):
        cmd = sensors["commands"].copy()
        cmd[0] = 1.25  # N m on the first actuator, the PD elsewhere
        target["name"] = sensors["actuators"][0]
        return cmd

    _, signals = biped.simulate(scenario="stand", duration=0.05, controller=hold_one)
    column = signals[f"cmd[{target['name']}]"]
    np.testing.assert_array_equal(column[1:], 1.25)


def test_controller_without_torque_collapses():
    summary, _ = biped.simulate(scenario="stand", duration=0.5, controller=lambda t, s: np.zeros(len(s["commands"])))
    held, _ = biped.simulate(scenario="stand", duration=0.5)
    assert summary["final_com_height"] < held["final_com_height"] - 0.05


def test_controller_errors():
    class Boom(RuntimeError):
        pass

    def boom(t, sensors):
        if t > 0.01:
            raise Boom("controller gave up")

    with pytest.raises(Boom, match="gave up"):
        biped.simulate(scenario="stand", duration=0.1, controller=boom)
    with pytest.raises(biped.BipedError, match="expected None or"):
        biped.simulate(scenario="stand", duration=0.1, controller=lambda t, s: [1.0, 2.0])
    with pytest.raises(biped.BipedError, match="not finite"):
        biped.simulate(scenario="stand", duration=0.1, controller=lambda t, s: s["commands"] * np.nan)


def test_bad_options_give_the_cli_message(cli_run, tmp_path):
    for options, words in [
        (dict(duration=-1), ["--duration", "-1"]),
        (dict(scenario="fly"), ["--scenario", "fly"]),
        (dict(urdf="/no/such.urdf", floating=True, feet="a,b"), ["--urdf", "/no/such.urdf", "--floating", "--feet", "a,b"]),
        (dict(floating=True), ["--floating"]),
    ]:
        with pytest.raises(biped.BipedError) as e:
            biped.simulate(**options)
        done = cli_run(["simulate", "--out", tmp_path / "x", *words])
        assert done.returncode != 0
        assert str(e.value) in done.stderr, (str(e.value), done.stderr)
    with pytest.raises(biped.BipedError, match="unknown option `speed`"):
        biped.simulate(speed=2)
    with pytest.raises(biped.BipedError, match="is a flag"):
        biped.simulate(floating="yes")
    with pytest.raises(biped.BipedError, match="takes a value"):
        biped.simulate(duration=True)
    with pytest.raises(biped.BipedError, match="threads"):
        biped.simulate_batch([{}], threads=0)
    with pytest.raises(biped.BipedError, match="not a dict"):
        biped.simulate_batch(["stand"])


def test_out_writes_the_cli_files(tmp_path):
    summary, _ = biped.simulate(scenario="stand", duration=0.1, out=tmp_path / "run")
    written = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert "signals.csv" in written["files"] and summary["files"] == written["files"]
    assert (tmp_path / "run" / "signals.csv").exists()
