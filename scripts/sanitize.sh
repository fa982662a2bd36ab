#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer in build-sanitize/
# (-DNEPHELE_SANITIZE=address,undefined, g++) and runs the whole test suite under them
# (docs/testing.md). Not part of .ci/run: it takes several times as long as the normal suite.
#
#   scripts/sanitize.sh [ctest options]   e.g. scripts/sanitize.sh -R json
#
# Any sanitizer report fails the test that caused it: UBSan halts on its first report, ASan
# always does, and LeakSanitizer fails the process at exit. Leaks inside Mesa, LLVM (llvmpipe's
# JIT) and libEGL are suppressed by scripts/lsan.supp; nephele's own are not.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNEPHELE_SANITIZE=address,undefined
cmake --build build-sanitize -j2

# The tests run `nephele` as a child process: it inherits these, so its findings fail the test.
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$repo_root/scripts/lsan.supp:print_suppressions=0"
start=$(date +%s)
status=0
ctest --test-dir build-sanitize --output-on-failure -j2 "$@" || status=$?
printf 'sanitize.sh: suite under address,undefined took %d s (exit %d)\n' "$(( $(date +%s) - start ))" "$status"
exit "$status"
