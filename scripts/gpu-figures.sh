#!/usr/bin/env bash
# Takes every GPU figure the docs promise in one go, so that whenever a GPU is lent they are
# taken in one call (docs/performance.md, "On a GPU"):
#
#   scripts/gpu-figures.sh OUTDIR [NEPHELE]
#
# NEPHELE defaults to build/nephele, else `nephele` on PATH. Writes OUTDIR/figures.txt (every
# command, its wall time and its output) and OUTDIR/agreement.tar (small outputs of fixed seeds,
# to be compared with the same commands on llvmpipe by scripts/gpu-agreement.sh). Progress goes
# to stderr. The 16384-texel cover is computed in tiles within the GPU's free memory
# (docs/scale.md), its faces and equirect EXR written (the preview excluded).
set -uo pipefail

if [[ $# -lt 1 || "$1" == -h || "$1" == --help ]]; then
  sed -n '2,11s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"
  [[ $# -lt 1 ]] && exit 2 || exit 0
fi
out="$1"
nephele="${2:-}"
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [[ -z "$nephele" ]]; then
  if [[ -x "$repo_root/build/nephele" ]]; then nephele="$repo_root/build/nephele"; else nephele="$(command -v nephele || true)"; fi
fi
[[ -n "$nephele" && -x "$nephele" ]] || { printf 'gpu-figures.sh: no nephele executable (build first, or pass its path)\n' >&2; exit 2; }
mkdir -p "$out" || exit 1
log="$out/figures.txt"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
: >"$log"

note() { printf '%s\n' "$*" | tee -a "$log" >&2; }

# Runs one command, appends it, its wall time in ms and its output to the log.
timed() {
  local start end status
  printf '\n$ %s\n' "$*" >>"$log"
  start=$(date +%s%N)
  timeout "${limit:-150}" "$@" >>"$log" 2>&1
  status=$?
  end=$(date +%s%N)
  printf '[wall %d ms, exit %d]\n' $(((end - start) / 1000000)) "$status" >>"$log"
  printf '  %-70.70s %6d ms (exit %d)\n' "$*" $(((end - start) / 1000000)) "$status" >&2
}

note "nephele GPU figures, $(date -u +%Y-%m-%dT%H:%MZ)"
note "host: $(uname -srm), $(nproc) CPUs"
if command -v nvidia-smi >/dev/null 2>&1; then
  nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader >>"$log" 2>&1
fi

# The cover pipeline (issue 16's targets): whole commands with their files, then device time
# per pass (bench cover reads GL_TIME_ELAPSED where the driver has it).
for run in 1 2 3; do timed "$nephele" generate --size 1024 --out "$work/g1024" --verbose --quiet; done
for run in 1 2; do timed "$nephele" generate --size 4096 --out "$work/g4096" --verbose --quiet; done
timed "$nephele" generate --size 4096 --files faces --out "$work/g4096f" --quiet
rm -rf "$work/g1024" "$work/g4096" "$work/g4096f"
# 1.6 G texels in tiles (issue 34's target: under a minute with its files on a GPU).
limit=300 timed "$nephele" generate --size 16384 --files faces,equirect --out "$work/g16384" --verbose --quiet
rm -rf "$work/g16384"
timed "$nephele" bench cover --sizes 256,1024,4096 --repeat 3
timed "$nephele" bench noise --size 512 --repeat 5
timed "$nephele" bench model --size 256 --repeat 3

# Views: the orbit frame and the ground frames at 1080p, whole commands and the benches.
timed "$nephele" bench orbit --repeat 10
for run in 1 2; do
  timed "$nephele" render --view orbit --size 1920x1080 --out "$work/orbit.png" --verbose --quiet
done
timed "$nephele" bench render --size 1920x1080 --repeat 3 --no-sweep
for view in gurten bantiger; do
  timed "$nephele" render --view "$view" --size 1920x1080 --quality final --out "$work/$view.png" --verbose --quiet
done
timed "$nephele" render --scene "$repo_root/scenes/gurten-thunderstorm.json" --size 1920x1080 --quality final \
  --out "$work/storm.png" --verbose --quiet

# Agreement across drivers: small outputs of fixed seeds, the same commands as
# scripts/gpu-agreement.sh runs on this machine's llvmpipe.
agree="$work/agreement"
mkdir -p "$agree"
"$repo_root/scripts/gpu-agreement.sh" produce "$agree" "$nephele" >>"$log" 2>&1
tar cf "$out/agreement.tar" -C "$work" agreement
note "done: $log and $out/agreement.tar"
