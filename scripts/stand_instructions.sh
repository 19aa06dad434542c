#!/usr/bin/env bash
# Instructions per control cycle of `biped simulate --lola type2 --scenario stand` (RK4, 1 kHz,
# signals recorded every 1000th cycle only), counted by callgrind: the deterministic measure of
# the simulation loop's work where wall time on a shared VM drifts by tens of per cent.
#
# Usage: scripts/stand_instructions.sh [BINARY]
# Without BINARY it builds one for x86-64-v2 into target/callgrind (valgrind 3.19 decodes
# neither AVX-512 nor every AVX form LLVM emits; see .cargo/config.toml), with the workspace's
# FMA contraction. The count is the difference of a 0.4 s and a 0.2 s run divided by 200
# cycles, so start-up, model assembly and output writing cancel.
set -euo pipefail
bin=${1:+$(realpath "$1")}
cd "$(dirname "$0")/.."
if [ -z "$bin" ]; then
  CARGO_TARGET_DIR=target/callgrind \
    RUSTFLAGS="-C target-cpu=x86-64-v2 -C llvm-args=-fp-contract=fast" \
    cargo build --release -p biped --quiet
  bin=target/callgrind/release/biped
fi
command -v valgrind >/dev/null || { echo "valgrind not found" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
count() {
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.$1" "$bin" simulate --lola type2 \
    --scenario stand --duration "$1" --integrator rk4 --every 1000 --out "$tmp/out" \
    >/dev/null 2>"$tmp/log.$1"
  sed -n 's/.*Collected : *\([0-9,]*\).*/\1/p' "$tmp/log.$1" | tr -d ,
}
short=$(count 0.2)
long=$(count 0.4)
echo "$bin: $(( (long - short) / 200 )) instructions per control cycle"
