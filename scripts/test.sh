#!/usr/bin/env bash
# Everything the project's tests need, from a clean clone with only the Rust toolchain and
# python3: the Rust test suite (release profile), then the Python package `biped` built into
# a venv under the workspace's target dir and tested with pytest against the CLI just built.
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
"$venv/bin/pip" install -q maturin numpy pytest
# maturin runs cargo with the same CARGO_TARGET_DIR and release profile. Cargo resolves
# features for the selected package only, so the dependencies whose features differ from the
# workspace test build (nalgebra, serde, ...) and pyo3 are compiled once more on the first run
# and reused after. No build isolation: the venv's maturin builds the wheel (its one
# dependency, numpy, is installed above).
"$venv/bin/pip" install -q --no-build-isolation --force-reinstall --no-deps ./python
BIPED_REQUIRE_CLI=1 "$venv/bin/python" -m pytest -q python/tests
"$root/scripts/test_view.sh"  # `biped view` in a real browser (chromium, npm)

end=$(date +%s)
echo "scripts/test.sh: all passed in $((end - start)) s (cargo test $((rust_done - start)) s, Python $((end - rust_done)) s)"
