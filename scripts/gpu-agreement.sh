#!/usr/bin/env bash
# Checks that two drivers agree: the same small commands with fixed seeds, run on a GPU and on
# Mesa's llvmpipe, compared image by image (docs/performance.md, "Agreement across drivers").
#
#   scripts/gpu-agreement.sh produce DIR [NEPHELE]   write the outputs into DIR
#   scripts/gpu-agreement.sh compare GPU_DIR CPU_DIR print oiiotool's differences per file;
#                                                    exit 1 when one passes its bound
#
# Integer hashing makes the noise exact on every driver; only floating-point rounding (fma,
# transcendental functions, reduction order) differs. The cover's threshold turns a rounding
# difference into a step only at texels within rounding of it, so the bounds are on the RMS and
# on the share of texels that differ by more than 1e-3, not on the largest difference.
set -uo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

produce() {
  local dir="$1" nephele="$2"
  mkdir -p "$dir"
  "$nephele" generate --size 256 --seed 1 --out "$dir/cover" --quiet
  "$nephele" generate --size 256 --seed 7 --curl-mode procedural --files faces --out "$dir/cover_procedural" --quiet
  "$nephele" noise --type perlin-worley --size 64 --octaves 3 --seed 3 --out "$dir/perlin_worley.exr" --quiet
  "$nephele" noise --type worley --size 64 --octaves 4 --seed 3 --out "$dir/worley.exr" --quiet
  "$nephele" model --example towering --size 64 --no-preview --out "$dir/model" --quiet
  "$nephele" render --view gurten --size 320x180 --quality final --terrain flat --no-cache --out "$dir/gurten.exr" --quiet
  "$nephele" render --view orbit --size 320x180 --earth-texture "$repo_root/docs/images/cover_equirect.png" \
    --out "$dir/orbit.exr" --quiet
  # Only the images are compared; sidecars hold timings and the device's name.
  find "$dir" -type f ! -name '*.exr' -delete
}

compare() {
  local gpu="$1" cpu="$2" failed=0 file mean_max share rms
  printf '%-44s %10s %10s %10s %10s %6s\n' file mean_abs rms max share_1e-3 bound
  while IFS= read -r file; do
    if [[ ! -f "$cpu/$file" ]]; then
      printf '%-44s missing on the CPU side\n' "$file"
      failed=1
      continue
    fi
    read -r mean max < <(oiiotool "$gpu/$file" "$cpu/$file" --sub --abs --mulc 1e6 --printstats 2>/dev/null | awk '
      /Stats Avg:/ { for (i = 3; i <= NF; i++) if ($i ~ /^[-+0-9.eE]+$/) { m += $i; n++ } }
      /Stats Max:/ { for (i = 3; i <= NF; i++) if ($i ~ /^[-+0-9.eE]+$/ && $i + 0 > x) x = $i + 0 }
      END { printf "%.4g %.4g\n", (n ? m / n : 0) / 1e6, x / 1e6 }')
    rms=$(oiiotool "$gpu/$file" "$cpu/$file" --sub --mulc 1e4 --dup --mul --printstats 2>/dev/null | awk '
      /Stats Avg:/ { for (i = 3; i <= NF; i++) if ($i ~ /^[-+0-9.eE]+$/) { m += $i; n++ } }
      END { printf "%.4g\n", sqrt(n ? m / n : 0) / 1e4 }')
    share=$(oiiotool "$gpu/$file" "$cpu/$file" --sub --abs --subc 0.001 --mulc 1e30 --clamp:min=0:max=1 \
      --printstats 2>/dev/null | awk '
      /Stats Avg:/ { for (i = 3; i <= NF; i++) if ($i ~ /^[-+0-9.eE]+$/) { m += $i; n++ } } END { printf "%.4g\n", (n ? m / n : 0) }')
    # Bounds. Data (covers, noise, model volumes): float rounding moves values by a few ulps,
    # and a texel near the coverage threshold may step further, so RMS <= 1e-4 and at most 0.1 %
    # of the values off by more than 1e-3. Rendered images (gurten, orbit): texture units filter
    # with fixed-point weights (8 bits of sub-texel precision on NVIDIA; Mesa filters in float),
    # so every bilinear fetch may move by 1/256 of its texels' difference: RMS <= 1e-2 of the
    # linear radiance, no bound on the share.
    local verdict=ok
    case "$file" in
      gurten.exr | orbit.exr) awk -v r="$rms" 'BEGIN { exit !(r > 1e-2) }' && verdict=FAIL ;;
      *) awk -v r="$rms" -v s="$share" 'BEGIN { exit !(r > 1e-4 || s > 1e-3) }' && verdict=FAIL ;;
    esac
    [[ "$verdict" == ok ]] || failed=1
    printf '%-44s %10s %10s %10s %10s %6s\n' "$file" "$mean" "$rms" "$max" "$share" "$verdict"
  done < <(cd "$gpu" && find . -type f -name '*.exr' | sed 's|^\./||' | sort)
  return "$failed"
}

case "${1:-}" in
  produce)
    [[ $# -ge 2 ]] || { printf 'usage: gpu-agreement.sh produce DIR [NEPHELE]\n' >&2; exit 2; }
    nephele="${3:-$repo_root/build/nephele}"
    [[ -x "$nephele" ]] || nephele="$(command -v nephele || true)"
    [[ -n "$nephele" ]] || { printf 'gpu-agreement.sh: no nephele executable\n' >&2; exit 2; }
    produce "$2" "$nephele"
    ;;
  compare)
    [[ $# -eq 3 ]] || { printf 'usage: gpu-agreement.sh compare GPU_DIR CPU_DIR\n' >&2; exit 2; }
    compare "$2" "$3"
    ;;
  *)
    sed -n '2,12s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"
    [[ "${1:-}" == -h || "${1:-}" == --help ]] && exit 0 || exit 2
    ;;
esac
