#!/usr/bin/env bash
# Everything the project's tests need, from a clean clone with only the Rust toolchain and
# python3: the Rust test suite (release profile), then the Python package `biped` built into
# a venv under the workspace's target dir and tested with pytest against the CLI just built,
# the viewer in a real browser (scripts/test_view.sh: chromium, npm), and the Ray sweeps on a
# two-node cluster in a network namespace with loopback only.
# Usage: scripts/test.sh   (CARGO_TARGET_DIR is honoured; the venv goes under it)
set -euo pipefail
start=$(date +%s)
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/target}

# Also builds target/release/biped (for the CLI tests), the reference of the Python tests.
cargo test --release --workspace
rust_done=$(date +%s)

venv=$CARGO_TARGET_DIR/python-venv
[ -x "$venv/bin/python" ] || python3 -m venv "$venv"
export PATH="$venv/bin:$PATH"  # the maturin build backend runs the venv's `maturin`
"$venv/bin/pip" install -q --upgrade pip
"$venv/bin/pip" install -q maturin numpy pytest ray
# maturin runs cargo with the same CARGO_TARGET_DIR and release profile. Cargo resolves
# features for the selected package only, so the dependencies whose features differ from the
# workspace test build (nalgebra, serde, ...) and pyo3 are compiled once more on the first run
# and reused after. No build isolation: the venv's maturin builds the wheel (its one
# dependency, numpy, is installed above).
"$venv/bin/pip" install -q --no-build-isolation --force-reinstall --no-deps ./python
BIPED_REQUIRE_CLI=1 "$venv/bin/python" -m pytest -q python/tests
"$root/scripts/test_view.sh"  # `biped view` in a real browser (chromium, npm)

# Ray binds to the machine's address: its cluster test runs where loopback is the only
# network (a namespace of its own; as root, or mapped to root in a user namespace).
ray_test='BIPED_REQUIRE_RAY=1 RAY_USAGE_STATS_ENABLED=0 "$0" -m pytest -q python/tests/test_ray.py'
if unshare --net true 2>/dev/null; then
  unshare --net bash -c "ip link set lo up && $ray_test" "$venv/bin/python"
elif unshare --map-root-user --net true 2>/dev/null; then
  unshare --map-root-user --net bash -c "ip link set lo up && $ray_test" "$venv/bin/python"
else
  echo "scripts/test.sh: warning: no network namespace (unshare --net) here: the Ray cluster" \
    "test runs on this machine's own address (Ray binds to it), its traffic still local" >&2
  BIPED_RAY_HOST_ADDRESS=1 bash -c "$ray_test" "$venv/bin/python"
fi

end=$(date +%s)
echo "scripts/test.sh: all passed in $((end - start)) s (cargo test $((rust_done - start)) s, Python, browser and Ray $((end - rust_done)) s)"
