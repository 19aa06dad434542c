"""`biped.distributed.sweep` on a two-node Ray cluster that the test starts on 127.0.0.1 (a
head and a worker node process, one CPU each): the results equal `simulate_batch`, in input
order, with a failed run's error in its slot, and both nodes ran chunks.

Ray binds its servers to the machine's network address, not to a chosen one; the tests run
only where loopback is the one network (scripts/test.sh starts them in a network namespace
of their own: `unshare --net`), so that the cluster lives on 127.0.0.1 alone."""

import os
import pathlib
import shutil
import socket
import subprocess
import sys
import tempfile

import numpy as np
import pytest

import biped

if os.environ.get("BIPED_REQUIRE_RAY"):
    import ray  # noqa: F401  (a missing Ray fails the run where it is required)
else:
    ray = pytest.importorskip("ray")

import biped.distributed


def _loopback_only():
    """Whether no route leaves the machine (a UDP `connect` sends nothing)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.connect(("192.0.2.1", 9))
        except OSError:
            return True
        return s.getsockname()[0].startswith("127.")


if not _loopback_only() and not os.environ.get("BIPED_RAY_HOST_ADDRESS"):
    why = "Ray would listen on the machine's network address: run in a loopback-only network namespace (unshare --net, as scripts/test.sh does)"
    if os.environ.get("BIPED_REQUIRE_RAY"):
        raise RuntimeError(why)
    pytest.skip(why, allow_module_level=True)

TIMING = {"wall_time", "realtime_factor"}


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _ray_cli(*args, env):
    exe = pathlib.Path(sys.executable).with_name("ray")
    done = subprocess.run([str(exe), *args], env=env, capture_output=True, text=True, timeout=180)
    if done.returncode != 0:
        raise RuntimeError(f"ray {' '.join(args)} failed ({done.returncode}):\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")


@pytest.fixture(scope="module")
def cluster():
    """A head node and a worker node on 127.0.0.1; the driver connected to the head."""
    port = _free_port()
    temp = tempfile.mkdtemp(prefix="ray", dir="/tmp")
    # Ray keeps state under the home directory (an auth token from an earlier local
    # instance would be sent to this cluster): every part of it gets the same fresh one.
    home = os.environ.get("HOME")
    env = dict(os.environ, RAY_USAGE_STATS_ENABLED="0", HOME=temp)
    os.environ["HOME"] = temp
    common = ["--node-ip-address=127.0.0.1", "--num-cpus=1", "--disable-usage-stats"]
    try:
        _ray_cli("start", "--head", f"--port={port}", "--include-dashboard=false", f"--temp-dir={temp}", *common, env=env)
        _ray_cli("start", f"--address=127.0.0.1:{port}", *common, env=env)
        os.environ["RAY_USAGE_STATS_ENABLED"] = "0"
        ray.init(address=f"127.0.0.1:{port}", _node_ip_address="127.0.0.1", log_to_driver=False)
        _warm_up(ray)
        yield ray
    finally:
        if ray.is_initialized():
            ray.shutdown()
        subprocess.run([str(pathlib.Path(sys.executable).with_name("ray")), "stop", "--force"], env=env, capture_output=True, timeout=120)
        if home is None:
            os.environ.pop("HOME", None)
        else:
            os.environ["HOME"] = home
        shutil.rmtree(temp, ignore_errors=True)


def _warm_up(ray):
    """Starts a worker process on both nodes (so the sweep's short tasks find both warm)."""

    @ray.remote(num_cpus=1)
    def node_of_slow_task():
        import time

        time.sleep(0.5)
        return ray.get_runtime_context().get_node_id()

    nodes = set(ray.get([node_of_slow_task.remote() for _ in range(4)]))
    assert len(nodes) == 2, nodes


def _same(a, b):
    if isinstance(a, BaseException):
        assert isinstance(b, biped.BipedError) and str(b) == str(a)
        return
    (sa, ga), (sb, gb) = a, b
    assert {k: v for k, v in sa.items() if k not in TIMING} == {k: v for k, v in sb.items() if k not in TIMING}
    assert ga.keys() == gb.keys()
    for k in ga:
        np.testing.assert_array_equal(ga[k], gb[k], err_msg=k)


RUNS = [dict(scenario="stand", duration=1.0, bandwidth=20.0 + 5.0 * k) for k in range(7)]
RUNS.insert(3, dict(scenario="stand", duration=-1.0))  # fails in its slot


def test_two_nodes_equal_simulate_batch(cluster):
    nodes = [n for n in cluster.nodes() if n["Alive"]]
    assert len(nodes) == 2
    expected = biped.simulate_batch(RUNS, threads=1)
    stats = {}
    got = biped.distributed.sweep(RUNS, chunk_size=1, stats=stats, progress=False)
    assert len(got) == len(RUNS)
    for a, b in zip(expected, got):
        _same(a, b)
    assert "--duration" in str(got[3])
    assert stats["chunks"] == len(RUNS)
    assert len(stats["nodes"]) == 2, stats


def test_pilot_sizes_chunks(cluster):
    stats = {}
    got = biped.distributed.sweep(RUNS[:4], stats=stats, signals=False, progress=False)
    expected = biped.simulate_batch(RUNS[:4])
    for a, b in zip(expected, got):
        if isinstance(a, BaseException):
            _same(a, b)
        else:
            _same((a[0], {}), b)
    assert stats["chunk_size"] >= 1
    assert stats["chunks"] == 1 + -(-(len(RUNS[:4]) - 1) // stats["chunk_size"])


def test_walk_sweep_equals_walk_batch(cluster):
    walks = [dict(steps=2, method=m) for m in ("none", "minimization")] + [dict(steps=0)]
    expected = biped.walk_batch(walks)
    got = biped.distributed.sweep(walks, chunk_size=1, command="walk", progress=False)
    assert isinstance(got[2], biped.BipedError) and str(got[2]) == str(expected[2])
    for a, b in zip(expected[:2], got[:2]):
        assert {k: v for k, v in a[0].items() if k not in TIMING | {"none", "minimization"}} == {
            k: v for k, v in b[0].items() if k not in TIMING | {"none", "minimization"}
        }
        assert a[1].keys() == b[1].keys()
        for stem in a[1]:
            for k in a[1][stem]:
                np.testing.assert_array_equal(a[1][stem][k], b[1][stem][k], err_msg=f"{stem}: {k}")


def test_bad_input_raises(cluster):
    with pytest.raises(biped.BipedError, match="unknown option `speed`"):
        biped.distributed.sweep([dict(speed=1)])
    with pytest.raises(biped.BipedError, match="chunk_size"):
        biped.distributed.sweep(RUNS, chunk_size=0)
    with pytest.raises(biped.BipedError, match="not a dict"):
        biped.distributed.sweep([3])
    with pytest.raises(biped.BipedError, match="command"):
        biped.distributed.sweep(RUNS, command="run")
