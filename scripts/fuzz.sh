#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz in build-fuzz/ (clang, -DNEPHELE_FUZZ=ON) and runs
# each in turn on one core (docs/testing.md).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]   fuzz each TARGET (default: json time scene weather cloud_model profile text)
#                                           for SECONDS (default 120)
#
# Needs clang++ and libFuzzer's runtime: on Debian bookworm the packages clang and
# libclang-rt-14-dev (not in scripts/debian-packages.txt: the normal build does not need them).
# New inputs go to build-fuzz/corpus/<target>/ (the seeds in tests/fuzz/corpus/<target>/ are
# only read); a crashing input is written to build-fuzz/crash-*: add it to the seed corpus
# with the fix, so that the replay test of the normal suite (test_fuzz_corpus.cpp) keeps it.
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

seconds="${1:-120}"
if [[ ! "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  printf 'fuzz.sh: SECONDS must be a whole number of seconds from 1, not %s\n' "$seconds" >&2
  exit 2
fi
[[ $# -gt 0 ]] && shift
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(json time scene weather cloud_model profile text)
for target in "${targets[@]}"; do
  if [[ ! -d "tests/fuzz/corpus/$target" ]]; then
    printf 'fuzz.sh: unknown target %s (allowed: json, time, scene, weather, cloud_model, profile, text)\n' "$target" >&2
    exit 2
  fi
done
command -v clang++ >/dev/null 2>&1 || { printf 'fuzz.sh: clang++ not found (Debian: apt-get install clang libclang-rt-14-dev)\n' >&2; exit 3; }

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DNEPHELE_FUZZ=ON -DNEPHELE_BUILD_TESTS=OFF
cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for target in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$target"
  printf '==> fuzz_%s for %s s\n' "$target" "$seconds"
  # -max_len: the example weather files are about 4 KiB; twice that leaves room to grow them.
  (cd build-fuzz && "./fuzz_$target" -max_total_time="$seconds" -max_len=8192 -timeout=10 \
    -print_final_stats=1 "corpus/$target" "../tests/fuzz/corpus/$target")
done
