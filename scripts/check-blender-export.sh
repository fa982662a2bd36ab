#!/bin/sh
# Checks the blender export preset in a real Blender (Debian bookworm: Blender 3.4.1): exports
# the marker cover of tests/test_export.cpp (one bright dot at 30 N 60 E), sets it up as the
# World with the preset's own nephele_world.py and renders probe directions with Cycles
# (scripts/blender_probe.py). Prints the PROBE lines: the marker must read 1 at 30 N 60 E with
# the Mapping's Y = -1, and at 30 N 60 W without it (docs/export.md, "blender"). Then imports a
# `nephele model` density.vdb as a Volume object (scripts/blender_volume_probe.py, docs/model.md).
# Usage: scripts/check-blender-export.sh [BUILD_DIR]   (default: build)
set -eu
build=${1:-build}
command -v blender > /dev/null || { echo "blender not found: apt-get install -y --no-install-recommends blender" >&2; exit 1; }
blender --version | head -n 1
"$build/tests/nephele_tests" "export blender: Blender renders*" -s 2>&1 | grep -E '^PROBE|passed|failed' | sort -u
"$build/tests/nephele_tests" "model's density.vdb opens in Blender*" -s 2>&1 | grep -oE 'GRID [^ ]+ [^ ]+ [0-9]+|BOUNDS( [0-9.-]+){6}|All tests passed.*|failed.*' | sort -u
