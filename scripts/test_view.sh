#!/usr/bin/env bash
# Browser tests of `biped view`, with all their set-up: builds the CLI, installs Debian's
# chromium when /usr/bin/chromium is missing (as root, like CI), installs the page's npm
# packages from the lockfile and builds the bundle, walks the robot two steps for a
# recording, serves it with a copy of the Lola collision model on a free 127.0.0.1 port (and
# another copy for the panel tests, a small URDF robot, one drawn from a VRML97 file and the
# G1 of `--robot g1`),
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

# A small URDF robot: a cylinder on the floating base, an STL cube and a sphere on the leg.
mkdir -p "$out/urdf"
cat >"$out/urdf/cube.stl" <<'STL'
solid cube
facet normal -1 0 0
outer loop
vertex -0.05 -0.05 -0.05
vertex -0.05 -0.05 0.05
vertex -0.05 0.05 0.05
endloop
endfacet
facet normal -1 0 0
outer loop
vertex -0.05 -0.05 -0.05
vertex -0.05 0.05 0.05
vertex -0.05 0.05 -0.05
endloop
endfacet
facet normal 1 0 0
outer loop
vertex 0.05 -0.05 -0.05
vertex 0.05 0.05 -0.05
vertex 0.05 0.05 0.05
endloop
endfacet
facet normal 1 0 0
outer loop
vertex 0.05 -0.05 -0.05
vertex 0.05 0.05 0.05
vertex 0.05 -0.05 0.05
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex -0.05 -0.05 -0.05
vertex 0.05 -0.05 -0.05
vertex 0.05 -0.05 0.05
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex -0.05 -0.05 -0.05
vertex 0.05 -0.05 0.05
vertex -0.05 -0.05 0.05
endloop
endfacet
facet normal 0 1 0
outer loop
vertex -0.05 0.05 -0.05
vertex -0.05 0.05 0.05
vertex 0.05 0.05 0.05
endloop
endfacet
facet normal 0 1 0
outer loop
vertex -0.05 0.05 -0.05
vertex 0.05 0.05 0.05
vertex 0.05 0.05 -0.05
endloop
endfacet
facet normal 0 0 -1
outer loop
vertex -0.05 -0.05 -0.05
vertex -0.05 0.05 -0.05
vertex 0.05 0.05 -0.05
endloop
endfacet
facet normal 0 0 -1
outer loop
vertex -0.05 -0.05 -0.05
vertex 0.05 0.05 -0.05
vertex 0.05 -0.05 -0.05
endloop
endfacet
facet normal 0 0 1
outer loop
vertex -0.05 -0.05 0.05
vertex 0.05 -0.05 0.05
vertex 0.05 0.05 0.05
endloop
endfacet
facet normal 0 0 1
outer loop
vertex -0.05 -0.05 0.05
vertex 0.05 0.05 0.05
vertex -0.05 0.05 0.05
endloop
endfacet
endsolid cube
STL
inertial='<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>'
cat >"$out/urdf/robot.urdf" <<URDF
<robot name="test_view">
  <link name="base">$inertial
    <visual><geometry><cylinder radius="0.1" length="0.4"/></geometry></visual></link>
  <link name="leg">$inertial
    <visual><origin xyz="0 0 -0.1"/><geometry><mesh filename="cube.stl" scale="1 1 2"/></geometry></visual>
    <visual><origin xyz="0 0 -0.3"/><geometry><sphere radius="0.06"/></geometry></visual></link>
  <joint name="hip" type="revolute"><parent link="base"/><child link="leg"/><origin xyz="0 0 -0.2"/>
    <axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
URDF

# A robot whose one visual is a VRML97 box (an IndexedFaceSet), drawn by three's VRMLLoader.
mkdir -p "$out/vrml"
cat >"$out/vrml/box.wrl" <<'WRL'
#VRML V2.0 utf8
# A 0.2 m cube, its six faces as quads.
Shape {
  appearance Appearance { material Material { diffuseColor 0.85 0.35 0.1 } }
  geometry IndexedFaceSet {
    coord Coordinate { point [ -0.1 -0.1 -0.1, 0.1 -0.1 -0.1, 0.1 0.1 -0.1, -0.1 0.1 -0.1,
                               -0.1 -0.1 0.1, 0.1 -0.1 0.1, 0.1 0.1 0.1, -0.1 0.1 0.1 ] }
    coordIndex [ 0 3 2 1 -1, 4 5 6 7 -1, 0 1 5 4 -1, 1 2 6 5 -1, 2 3 7 6 -1, 3 0 4 7 -1 ]
  }
}
WRL
cat >"$out/vrml/robot.urdf" <<URDF
<robot name="test_vrml">
  <link name="base">$inertial
    <visual><origin xyz="0 0 0.3"/><geometry><mesh filename="box.wrl"/></geometry></visual></link>
</robot>
URDF
cp crates/robots/data/lola_ssv.toml "$out/tables.toml"

servers=()
stop() { for s in "${servers[@]}"; do kill -INT "$s" 2>/dev/null || true; wait "$s" 2>/dev/null || true; done; }
trap stop EXIT
# Starts `biped view ARGS` on a free port; sets $url to the address it prints.
serve() {
  local name=$1
  shift
  "$biped" view --port 0 "$@" >"$out/$name.out" 2>"$out/$name.err" &
  servers+=($!)
  for _ in $(seq 100); do
    grep -q '^serving ' "$out/$name.out" 2>/dev/null && break
    kill -0 "${servers[-1]}" 2>/dev/null || { cat "$out/$name.err" >&2; exit 1; }
    sleep 0.1
  done
  url=$(sed -n '1s/^serving //p' "$out/$name.out")
  [ -n "$url" ] || { echo "test_view.sh: biped view printed no address" >&2; exit 1; }
}
serve lola --lola type2 --ssv "$out/model.toml" --recording "$out/walk"
lola_url=$url
serve urdf --urdf "$out/urdf/robot.urdf" --floating
urdf_url=$url
serve vrml --urdf "$out/vrml/robot.urdf" --floating
vrml_url=$url
serve tables --lola type2 --ssv "$out/tables.toml" --recording "$out/walk"
tables_url=$url
serve g1 --robot g1
g1_url=$url

(cd web && VIEW_URL=$lola_url VIEW_URDF_URL=$urdf_url VIEW_VRML_URL=$vrml_url VIEW_TABLES_URL=$tables_url \
  VIEW_G1_URL=$g1_url VIEW_SSV=$out/model.toml VIEW_TABLES_SSV=$out/tables.toml BIPED=$biped OUT=$out node --test tests/)

trap - EXIT
for s in "${servers[@]}"; do
  kill -INT "$s"
  status=0
  wait "$s" || status=$?
  [ "$status" -eq 0 ] || { echo "test_view.sh: biped view exited with $status on SIGINT" >&2; exit 1; }
done
echo "scripts/test_view.sh: all passed in $(($(date +%s) - start)) s (screenshots in out/view/)"
