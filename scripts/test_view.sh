#!/usr/bin/env bash
# Browser tests of `biped view`, with all their set-up: builds the CLI, installs Debian's
# chromium when /usr/bin/chromium is missing (as root, like CI), installs the page's npm
# packages from the lockfile and builds the bundle, walks the robot two steps for a
# recording, serves it with a copy of the Lola collision model on a free 127.0.0.1 port,
# runs web/tests with node's test runner (playwright-core driving chromium) and stops the
# server with SIGINT, which must end it cleanly. Screenshots: out/view/*.png.
# Usage: scripts/test_view.sh   (CARGO_TARGET_DIR is honoured)
set -euo pipefail
start=$(date +%s)
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/target}
biped=$CARGO_TARGET_DIR/release/biped
cargo build --release --bin biped

if [ ! -x /usr/bin/chromium ]; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver >/dev/null
fi
(cd web && npm ci --no-audit --no-fund --loglevel=error && npm run build --silent)

out=$root/out/view
rm -rf "$out"
mkdir -p "$out"
cp crates/robots/data/lola_ssv.toml "$out/model.toml"
"$biped" walk --steps 2 --method minimization --out "$out/walk" >/dev/null

"$biped" view --port 0 --lola type2 --ssv "$out/model.toml" --recording "$out/walk" \
  >"$out/server.out" 2>"$out/server.err" &
server=$!
stop() { kill -INT "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true; }
trap stop EXIT
for _ in $(seq 100); do
  grep -q '^serving ' "$out/server.out" 2>/dev/null && break
  kill -0 "$server" 2>/dev/null || { cat "$out/server.err"; exit 1; }
  sleep 0.1
done
url=$(sed -n '1s/^serving //p' "$out/server.out")
[ -n "$url" ] || { echo "test_view.sh: biped view printed no address" >&2; exit 1; }

(cd web && VIEW_URL=$url VIEW_SSV=$out/model.toml BIPED=$biped OUT=$out node --test tests/)

trap - EXIT
kill -INT "$server"
status=0
wait "$server" || status=$?
[ "$status" -eq 0 ] || { echo "test_view.sh: biped view exited with $status on SIGINT" >&2; exit 1; }
echo "scripts/test_view.sh: all passed in $(($(date +%s) - start)) s (screenshots in out/view/)"
