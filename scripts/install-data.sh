#!/usr/bin/env bash
# Installs the geodata that no Debian package holds (docs/terrain.md, Land cover):
#
#   swiss-maps 4.7.0 (npm registry; BSD-3-Clause, Interactive Things GmbH; generalised
#   boundaries of the Swiss Federal Statistical Office from swisstopo data): the lakes and the
#   municipalities of Switzerland as TopoJSON in WGS84 longitude and latitude.
#
# Into /usr/local/share/nephele/swiss-maps/ (ch-combined.json of 2026 and the LICENSE), where
# `nephele render` looks for it (--land-cover). The archive is checked against the registry's
# SHA-512 before anything is unpacked. Safe to run again: an installed copy is left alone.
# Sourced by scripts/quickstart.sh (which defines say, die and as_root) or run on its own.
set -euo pipefail

swiss_maps_version="4.7.0"
swiss_maps_url="https://registry.npmjs.org/swiss-maps/-/swiss-maps-${swiss_maps_version}.tgz"
# The registry's "integrity" (sha512-MRX9u8rm...) in hex.
swiss_maps_sha512="3115fdbbcae6eb11e6063025786be6cf64eacc8c6b81f94ee2aed62193f7983bf5d55f23fcbdc075b209b2eaeb2aa5084741655049dc50858d0cc1760e383f7a"
data_dir="/usr/local/share/nephele/swiss-maps"

if ! declare -F say >/dev/null; then
  say() { printf '==> %s\n' "$*"; }
  die() {
    printf 'install-data: %s\n' "$*" >&2
    exit 1
  }
  # shellcheck source=scripts/debian-root.sh
  source "$(dirname "${BASH_SOURCE[0]}")/debian-root.sh"
fi

install_swiss_maps() {
  if [[ -f "$data_dir/ch-combined.json" && "$(cat "$data_dir/VERSION" 2>/dev/null)" == "$swiss_maps_version" ]]; then
    say "data: swiss-maps $swiss_maps_version installed"
    return
  fi
  say "data: swiss-maps $swiss_maps_version from the npm registry"
  local work
  work="$(mktemp -d)"
  # curl (scripts/debian-packages.txt); npm pack where curl cannot reach the registry.
  if ! curl -fsSL --retry 3 -o "$work/swiss-maps.tgz" "$swiss_maps_url"; then
    command -v npm >/dev/null 2>&1 || die "cannot download $swiss_maps_url (curl failed, no npm)"
    (cd "$work" && npm pack --silent "swiss-maps@$swiss_maps_version" >/dev/null) ||
      die "cannot download swiss-maps $swiss_maps_version (curl and npm pack failed)"
    mv "$work/swiss-maps-$swiss_maps_version.tgz" "$work/swiss-maps.tgz"
  fi
  echo "$swiss_maps_sha512  $work/swiss-maps.tgz" | sha512sum -c --quiet - ||
    die "swiss-maps $swiss_maps_version: the archive's SHA-512 differs from the registry's"
  tar -xzf "$work/swiss-maps.tgz" -C "$work" package/2026/ch-combined.json package/LICENSE
  echo "$swiss_maps_version" >"$work/VERSION"
  as_root mkdir -p "$data_dir"
  as_root install -m 0644 "$work/package/2026/ch-combined.json" "$work/package/LICENSE" "$work/VERSION" "$data_dir/"
  rm -rf "$work"
}

install_swiss_maps
