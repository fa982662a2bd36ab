#!/usr/bin/env bash
# Checks the Slurm recipes of scripts/slurm/: a cover made by a job array equals the
# single-process cover to the bit.
#
#   scripts/slurm-check.sh [NEPHELE]
#
# Starts a private one-node Slurm cluster on this machine: Debian's slurm-wlm and munge
# (installed when missing), a test configuration (proctrack/linuxproc, task/none, no cgroup, no
# accounting) with its own munge key, socket, ports and state in a temporary directory; neither
# /etc/slurm nor the system's munged is used. Then it submits scripts/slurm/cover-tiles.sbatch as
# an array of 4 tasks (24 tiles), scripts/slurm/cover-assemble.sbatch after it, compares the six
# faces with those of one `nephele generate`, and submits the array once more (complete parts
# are kept). Exit 0 when every face equals byte for byte, 1 when one differs or something
# failed, 2 when no nephele is found. Needs root, directly or through sudo (slurmd starts jobs
# as their user). docs/scale.md describes the recipes; docs/testing.md this check.
#
# NEPHELE: the first argument, else build/nephele, else nephele on PATH. The environment may set
# NEPHELE_SLURM_SIZE (64), _SEED (7), _TILES (24), _TASKS (4), _TIMEOUT (seconds per wait, 600)
# and NEPHELE_SLURM_KEEP=1 (keep the temporary directory). With CI=true nothing asks questions.
set -euo pipefail
# munged, slurmctld and slurmd live in /usr/sbin, which a user's PATH may lack.
PATH="$PATH:/usr/sbin:/sbin"
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

size="${NEPHELE_SLURM_SIZE:-64}"
seed="${NEPHELE_SLURM_SEED:-7}"
tiles="${NEPHELE_SLURM_TILES:-24}"
tasks="${NEPHELE_SLURM_TASKS:-4}"
timeout="${NEPHELE_SLURM_TIMEOUT:-600}"
faces=(px nx py ny pz nz)

say() {
  printf '==> %s\n' "$*"
}

die() {
  printf 'slurm-check: %s\n' "$*" >&2
  exit 1
}

# Seconds since a start taken from $EPOCHREALTIME, one decimal.
since() {
  awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'
}

# --- nephele -----------------------------------------------------------------------------
# The jobs run in the work directory, so the path is made absolute here.
if [[ $# -gt 1 ]]; then
  printf 'slurm-check: at most one argument, the nephele executable\n' >&2
  exit 2
fi
nephele="${1:-}"
if [[ -z "$nephele" && -x "$repo_root/build/nephele" ]]; then
  nephele="$repo_root/build/nephele"
fi
nephele="$(command -v "${nephele:-nephele}" || true)"
if [[ -z "$nephele" || ! -x "$nephele" ]]; then
  printf 'slurm-check: no nephele: pass its path, build build/nephele or put nephele on PATH\n' >&2
  exit 2
fi
nephele="$(cd "$(dirname "$nephele")" && pwd)/$(basename "$nephele")"

# --- packages ----------------------------------------------------------------------------
# is_installed, as_root
# shellcheck source=scripts/debian-root.sh
source "$repo_root/scripts/debian-root.sh"

missing=()
for package in slurm-wlm munge; do
  is_installed "$package" || missing+=("$package")
done
if [[ ${#missing[@]} -gt 0 ]]; then
  say "packages: installing ${missing[*]}"
  as_root env DEBIAN_FRONTEND=noninteractive apt-get update
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi

# The daemons need root: slurmd starts each job as the user who submitted it. Without root the
# script runs itself again through sudo, with the settings it reads from the environment.
if [[ "$(id -u)" -ne 0 ]]; then
  say "not root: running again through sudo"
  settings=()
  for name in CI NEPHELE_SLURM_SIZE NEPHELE_SLURM_SEED NEPHELE_SLURM_TILES NEPHELE_SLURM_TASKS \
    NEPHELE_SLURM_TIMEOUT NEPHELE_SLURM_KEEP; do
    if [[ -n "${!name:-}" ]]; then settings+=("$name=${!name}"); fi
  done
  as_root env "${settings[@]}" "$repo_root/scripts/slurm-check.sh" "$nephele"
  exit 0
fi

# A surrounding job's or user's Slurm settings must not leak into the private cluster.
while IFS= read -r name; do
  unset "$name"
done < <(compgen -e | grep -E '^(SLURM|SBATCH|SQUEUE|SINFO|SCONTROL)_' || true)

started="$EPOCHREALTIME"

# --- private cluster ---------------------------------------------------------------------
# munged checks its files' modes: the key must be the owner's alone (0600) and every directory
# on the way to the socket must let others pass (x), which mktemp's 0700 does not.
tmp="$(mktemp -d "${TMPDIR:-/tmp}/nephele-slurm.XXXXXX")"
chmod 0711 "$tmp"
mkdir -p "$tmp/state" "$tmp/spool" "$tmp/work"
work="$tmp/work"
munged_pid="" slurmctld_pid="" slurmd_pid=""

# Stops a daemon started below: TERM, up to 10 s to exit, then KILL.
stop() {
  local pid="$1" i
  [[ -n "$pid" ]] || return 0
  kill -TERM "$pid" 2>/dev/null || return 0
  for ((i = 0; i < 100; i++)); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -KILL "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
}

# The daemons' own logs; what they wrote before opening them (a bad slurm.conf) is in .out.
show_logs() {
  local name log
  for name in munged slurmctld slurmd; do
    log="$tmp/$name.log"
    [[ -s "$log" ]] || log="$tmp/$name.out"
    if [[ -s "$log" ]]; then
      printf -- '--- last lines of %s\n' "$log" >&2
      tail -n 25 "$log" >&2
    fi
  done
}

cleanup() {
  local rc=$? i pid
  trap - EXIT
  if [[ -n "$slurmctld_pid" ]] && kill -0 "$slurmctld_pid" 2>/dev/null; then
    # Jobs still running (a failure, an interrupt) end before the daemons.
    scancel --quiet --full --user="$(id -un)" 2>/dev/null || true
    for ((i = 0; i < 50; i++)); do
      kill -0 "$slurmd_pid" 2>/dev/null || break
      [[ -z "$(squeue -h -o %i 2>/dev/null)" ]] && break
      sleep 0.2
    done
  fi
  stop "$slurmd_pid"
  stop "$slurmctld_pid"
  stop "$munged_pid"
  # A slurmd that died cannot cancel its jobs: their slurmstepd (it holds this cluster's
  # slurmd.log open) and the job's processes, all in one session, are ended here.
  for pid in $(pgrep -x slurmstepd || true); do
    if [[ "$(readlink /proc/"$pid"/fd/* 2>/dev/null)" == *"$tmp/"* ]]; then
      pkill -KILL -s "$(ps -o sid= -p "$pid" | tr -d ' ')" || true
    fi
  done
  if [[ $rc -ne 0 ]]; then show_logs; fi
  if [[ "${NEPHELE_SLURM_KEEP:-}" == 1 ]]; then
    printf 'slurm-check: kept %s\n' "$tmp" >&2
  else
    rm -rf "$tmp"
  fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# The jobs' output files, on a failure.
show_job_outputs() {
  local out
  for out in "$work"/*.out; do
    [[ -f "$out" ]] || continue
    printf -- '--- %s\n' "$(basename "$out")" >&2
    tail -n 20 "$out" >&2
  done
}

# Fails with the logs when one of the daemons has died.
check_daemons() {
  local name pid
  for name in munged slurmctld slurmd; do
    pid="${name}_pid"
    pid="${!pid}"
    if [[ -n "$pid" ]] && ! kill -0 "$pid" 2>/dev/null; then
      die "$name exited; see its log below"
    fi
  done
}

say "cluster: munged, slurmctld and slurmd in $tmp"
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 0600 "$tmp/munge.key"
# In the foreground munged logs to stderr, not to --log-file.
munged --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" \
  --pid-file="$tmp/munged.pid" --seed-file="$tmp/munged.seed" >"$tmp/munged.log" 2>&1 &
munged_pid=$!
for ((i = 0; i < 50; i++)); do
  [[ -S "$tmp/munge.socket" ]] && break
  check_daemons
  sleep 0.1
done
munge -n -S "$tmp/munge.socket" | unmunge -S "$tmp/munge.socket" >/dev/null ||
  die "munge cannot encode and decode a credential with the private key"

# Two random high ports that nothing listens on, so that two runs do not collide.
free_port() {
  local port
  while true; do
    port=$((20000 + RANDOM % 40000))
    if ! command -v ss >/dev/null 2>&1 || [[ -z "$(ss -Hltn "sport = :$port")" ]]; then
      printf '%s\n' "$port"
      return
    fi
  done
}
ctld_port="$(free_port)"
slurmd_port="$(free_port)"
while [[ "$slurmd_port" == "$ctld_port" ]]; do slurmd_port="$(free_port)"; done

# The controller finds itself by its short host name; addresses are given as 127.0.0.1, so
# nothing depends on how the host name resolves. RealMemory stays below the machine's, or
# slurmd's registration would drain the node.
host="$(hostname -s)"
memory=$(awk '/^MemTotal:/ { printf "%d", $2 / 1024 * 0.9 }' /proc/meminfo)
user="$(id -un)"
: >"$tmp/plugstack.conf"
cat >"$tmp/slurm.conf" <<EOF
ClusterName=nephele-check
SlurmctldHost=$host(127.0.0.1)
SlurmUser=$user
SlurmdUser=$user
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
PlugStackConfig=$tmp/plugstack.conf
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
# Schedule at once after a submission or a job's end (by default batch jobs wait up to 3 s).
SchedulerParameters=batch_sched_delay=0
ReturnToService=2
# Finished jobs stay visible to scontrol long enough to read their states.
MinJobAge=3600
# An array that fails cancels the assembly waiting on it instead of leaving it pending.
DependencyParameters=kill_invalid_depend
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$memory State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"

slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
slurmctld_pid=$!
slurmd -D -f "$SLURM_CONF" -N "$host" >"$tmp/slurmd.out" 2>&1 &
slurmd_pid=$!

# The single-process reference, made while slurmd registers.
say "single process: nephele generate --size $size --seed $seed --files faces"
t="$EPOCHREALTIME"
"$nephele" generate --size "$size" --seed "$seed" --files faces --out "$work/single" --quiet
say "single process: $(since "$t") s"

# The node is usable once slurmd has registered with the controller and it reports idle.
state=""
deadline=$((SECONDS + 30))
while [[ "$state" != idle ]]; do
  check_daemons
  ((SECONDS < deadline)) || die "node not idle after 30 s (state: ${state:-none})"
  sleep 0.2
  state="$(sinfo -h -N -o %T 2>/dev/null || true)"
done
say "cluster: node $host idle after $(since "$started") s (ports $ctld_port, $slurmd_port)"

# --- jobs --------------------------------------------------------------------------------
# Waits until none of the jobs is pending or running, then fails unless every record (each
# task of an array) COMPLETED.
wait_jobs() {
  local ids="$1" deadline=$((SECONDS + timeout)) states pending
  while true; do
    check_daemons
    # A failing squeue (the controller busy or gone) is no answer, not an empty queue.
    if pending="$(squeue -h -j "$ids" -o %i 2>/dev/null)" && [[ -z "$pending" ]]; then
      break
    fi
    if ((SECONDS >= deadline)); then
      squeue -j "$ids" >&2 || true
      show_job_outputs
      die "jobs $ids not finished after $timeout s"
    fi
    sleep 0.2
  done
  states="$(for id in ${ids//,/ }; do scontrol -o show job "$id"; done |
    grep -o 'JobState=[A-Z_]*' | sed 's/^JobState=//' || true)"
  if [[ -n "$states" ]] && ! grep -qv '^COMPLETED$' <<<"$states"; then
    return 0
  fi
  show_job_outputs
  die "jobs $ids did not all complete: $(sort <<<"$states" | uniq -c | xargs)"
}

# The recipes read their settings from the environment that sbatch exports (--export=ALL).
export NEPHELE="$nephele" SIZE="$size" SEED="$seed" TILES="$tiles" PARTS="$work/parts"
export OUT="$work/assembled" FILES=faces

submit_array() {
  local id
  id="$(sbatch --parsable --export=ALL --chdir="$work" --array="0-$((tasks - 1))" \
    "$repo_root/scripts/slurm/cover-tiles.sbatch")"
  printf '%s\n' "${id%%;*}"
}

say "array: $tasks tasks of cover-tiles.sbatch ($tiles tiles), then cover-assemble.sbatch"
t="$EPOCHREALTIME"
array_id="$(submit_array)"
assemble_id="$(sbatch --parsable --export=ALL --chdir="$work" --dependency="afterok:$array_id" \
  "$repo_root/scripts/slurm/cover-assemble.sbatch")"
assemble_id="${assemble_id%%;*}"
wait_jobs "$array_id,$assemble_id"
say "array and assembly: $(since "$t") s (jobs $array_id, $assemble_id)"

# nephele's files are reproducible (no time of writing in the headers), so the assembled faces
# must equal the single process's byte for byte.
different=()
for face in "${faces[@]}"; do
  cmp -s "$work/single/cover_$face.exr" "$work/assembled/cover_$face.exr" || different+=("$face")
done
if [[ ${#different[@]} -gt 0 ]]; then
  die "the assembled cover differs from the single-process cover in ${different[*]}"
fi

# A second submission finds every part complete; it must still succeed and leave the parts
# as they are (no second copy, no leftover temporary file).
say "array again: parts complete, kept"
before="$(ls -A "$work/parts")"
t="$EPOCHREALTIME"
again_id="$(submit_array)"
wait_jobs "$again_id"
[[ "$(ls -A "$work/parts")" == "$before" ]] || die "the second array changed the parts' names"
say "array again: $(since "$t") s (job $again_id)"

# Frames: an array of 2 frames of the moving cover, 6 hours apart; frame 1 must equal the cover
# that one generate makes at its time.
say "frames: 2 tasks of cover-frames.sbatch"
t="$EPOCHREALTIME"
frames_id="$(START=2026-06-21T00:00Z INTERVAL=6 OUT="$work/frames" sbatch --parsable --export=ALL \
  --chdir="$work" --array=0-1 "$repo_root/scripts/slurm/cover-frames.sbatch")"
frames_id="${frames_id%%;*}"
"$nephele" generate --size "$size" --seed "$seed" --time 2026-06-21T06:00:00Z --files faces --out "$work/frame_single" \
  --quiet
wait_jobs "$frames_id"
for face in "${faces[@]}"; do
  cmp -s "$work/frame_single/cover_$face.exr" "$work/frames/frame_0001/cover_$face.exr" ||
    die "frame 1 of the array differs from generate --time 2026-06-21T06:00:00Z in face $face"
done
say "frames: $(since "$t") s (job $frames_id)"

say "total: $(since "$started") s"
printf 'slurm-check: %s array tasks, %s tiles, assembled cover equals the single-process cover to the bit;' \
  "$tasks" "$tiles"
printf ' an array frame equals generate --time\n'
