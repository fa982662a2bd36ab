#!/usr/bin/env bash
# Set-up entry point for a fresh Debian bookworm machine (root, or a user with sudo).
#
#   scripts/quickstart.sh [run] [generate options]  set up, build, then run
#                                                   `build/nephele generate` (into cubemaps/)
#   scripts/quickstart.sh test                      set up, build, then run the test suite
#
# Set-up installs the packages of scripts/debian-packages.txt that are missing and the geodata
# of scripts/install-data.sh, and builds in build/ (CMake, Release). Safe to run again:
# installed packages and data and an up-to-date build are left alone. With CI=true nothing
# asks questions (sudo fails instead of prompting).
set -euo pipefail

# Everything below uses paths relative to the repository root, whatever the caller's
# directory; relative --out paths given to `run` are therefore relative to the root too.
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

usage() {
  sed -n '2,11s/^# \{0,1\}//p' scripts/quickstart.sh
}

say() {
  printf '==> %s\n' "$*"
}

die() {
  printf 'quickstart: %s\n' "$*" >&2
  exit 1
}

# Bad arguments: exit code 2, as for nephele itself.
usage_error() {
  printf 'quickstart: %s (see scripts/quickstart.sh --help)\n' "$*" >&2
  exit 2
}

# Package names from the list: comments and blank lines dropped.
wanted_packages() {
  local line
  while IFS= read -r line || [[ -n "$line" ]]; do
    line="${line%%#*}"
    line="${line//[[:space:]]/}"
    if [[ -n "$line" ]]; then
      printf '%s\n' "$line"
    fi
  done <scripts/debian-packages.txt
}

# is_installed, as_root
# shellcheck source=scripts/debian-root.sh
source "$repo_root/scripts/debian-root.sh"

install_missing_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
    die "dpkg-query or apt-get not found: this script expects Debian bookworm; install the packages of scripts/debian-packages.txt by hand"
  fi
  local packages missing=() package
  mapfile -t packages < <(wanted_packages)
  for package in "${packages[@]}"; do
    is_installed "$package" || missing+=("$package")
  done
  if [[ ${#missing[@]} -eq 0 ]]; then
    say "packages: all ${#packages[@]} installed"
    return
  fi
  say "packages: installing ${missing[*]}"
  # sudo resets the environment, so DEBIAN_FRONTEND goes through env.
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
}

# build [TARGET]: the run mode builds only the executable, the test mode everything.
build() {
  say "configure: build/ (Release)"
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
  say "build"
  if [[ $# -gt 0 ]]; then
    cmake --build build -j2 --target "$1"
  else
    cmake --build build -j2
  fi
}

mode="run"
case "${1:-}" in
  -h | --help)
    usage
    exit 0
    ;;
  "" | run)
    if [[ $# -gt 0 ]]; then shift; fi
    ;;
  test)
    shift
    [[ $# -eq 0 ]] || usage_error "'test' takes no further arguments"
    mode="test"
    ;;
  -*)
    # Options without a mode word go to `nephele generate`.
    ;;
  *)
    usage_error "unknown mode '$1' (allowed: run, test)"
    ;;
esac

install_missing_packages
# shellcheck source=scripts/install-data.sh
source scripts/install-data.sh
if [[ "$mode" == "test" ]]; then build; else build nephele; fi

if [[ "$mode" == "test" ]]; then
  say "format: scripts/check-format.sh"
  scripts/check-format.sh
  # Three at a time on two cores: a group waits on its subprocesses, files and llvmpipe's
  # threads often enough that two left a third of the cores idle (docs/testing.md).
  say "test: ctest --test-dir build --output-on-failure -j3"
  ctest --test-dir build --output-on-failure -j3
else
  say "generate: build/nephele generate $*"
  build/nephele generate "$@"
fi
