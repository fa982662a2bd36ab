# Sourced by scripts/quickstart.sh and scripts/slurm-check.sh: whether a Debian package is
# installed, and running a command as root. The sourcing script defines die().

is_installed() {
  local status
  status="$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)"
  [[ "$status" == *"ok installed"* ]]
}

# Runs a command as root: directly when root, else through sudo (never prompting in CI).
as_root() {
  if [[ "$(id -u)" -eq 0 ]]; then
    "$@"
  elif command -v sudo >/dev/null 2>&1; then
    if [[ "${CI:-}" == "true" ]]; then
      sudo -n "$@"
    else
      sudo "$@"
    fi
  else
    die "not root and sudo is missing: as root, run $*"
  fi
}
