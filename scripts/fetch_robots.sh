#!/usr/bin/env bash
# Fetches public humanoid robot models (TALOS, iCub, Romeo, ... from the `example-robot-data`
# package on PyPI) into a Python venv and tells where their URDF and SRDF files are.
#
#   source scripts/fetch_robots.sh [DIR]   # exports ROBOTS (e.g. $ROBOTS/talos_data/robots/...)
#   scripts/fetch_robots.sh [DIR]          # prints `export ROBOTS=...` (for eval "$(...)")
#
# DIR is the venv folder: default $BIPED_ROBOTS_VENV, else out/robots-venv in the repository
# (git ignores out/). A second call reuses the venv (no download). Needs python3 with venv and
# pip, and access to PyPI. The robots' licences are in the README files under $ROBOTS.

# When sourced, a failure must not close the caller's shell: no `set -e`, `return` instead.
_biped_fetch_robots() {
    local repo venv py purelib robots
    repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)" || return 1
    venv="${1:-${BIPED_ROBOTS_VENV:-$repo/out/robots-venv}}"
    py="$venv/bin/python"
    if [ ! -x "$py" ] || ! "$py" -m pip show -q example-robot-data >/dev/null 2>&1; then
        echo "fetch_robots: installing example-robot-data into $venv" >&2
        python3 -m venv "$venv" || return 1
        "$py" -m pip install -q --disable-pip-version-check example-robot-data >&2 || return 1
    fi
    purelib="$("$py" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')" || return 1
    robots="$purelib/cmeel.prefix/share/example-robot-data/robots"
    if [ ! -d "$robots/talos_data" ]; then
        # Other layouts of the package: look for the folder that holds talos_data.
        robots="$(dirname "$(find "$venv" -type d -name talos_data -print -quit)")"
        if [ ! -d "$robots/talos_data" ]; then
            echo "fetch_robots: no talos_data folder found under $venv" >&2
            return 1
        fi
    fi
    ROBOTS="$robots"
    export ROBOTS
}

if [ "${BASH_SOURCE[0]}" != "$0" ]; then
    if _biped_fetch_robots "$@"; then
        unset -f _biped_fetch_robots
        echo "ROBOTS=$ROBOTS" >&2
    else
        unset -f _biped_fetch_robots
        false
    fi
else
    _biped_fetch_robots "$@" || exit 1
    printf 'export ROBOTS=%q\n' "$ROBOTS"
fi
