#!/bin/sh
# Records the golden hashes of this machine's renderer (tests/test_golden.cpp) in
# tests/data/golden/hashes.json: run it before a change that must not alter any output, commit
# the entry, and the suite then checks every later build against it.
set -eu
cd "$(dirname "$0")/.."
NEPHELE_GOLDEN_RECORD=1 build/tests/nephele_tests "[golden]" "$@"
