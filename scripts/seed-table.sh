#!/bin/sh
# The measures of docs/climate.md ("Cloud objects", "Measured") for six seeds of the default
# cover: `nephele generate` and `nephele stats` each, printed as the Markdown rows of its tables
# (the cloud objects', then the optical thickness and cloud tops' of "Optical thickness and cloud
# tops").
# Usage: scripts/seed-table.sh [SIZE] [TIME] [extra generate options...]
set -eu
cd "$(dirname "$0")/.."
size=${1:-512}
time=${2:-2026-06-21T12:00Z}
[ $# -ge 2 ] && shift 2 || shift $#
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| seed | objects | alpha (fit range km^2) | D | largest system | elongation | mid-tones | edge contrast | worst 10-degree band | generate s |"
echo "|-----:|--------:|-----------------------:|--:|---------------:|-----------:|----------:|--------------:|---------:|---:|"
for seed in 1 2 3 4 5 6; do
  start=$(date +%s.%N)
  build/nephele generate --size "$size" --seed "$seed" --time "$time" --files faces,equirect --quiet --out "$work/c$seed" "$@" >/dev/null
  end=$(date +%s.%N)
  build/nephele stats "$work/c$seed" >/dev/null
  python3 - "$work/c$seed/stats/stats.json" "$seed" "$start" "$end" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
o = s["cloud_objects"]
sizes = o["size_distribution"]
contrast = o["edge_contrast"]  # edge cover over the cloudy mean
print("| %s | %d | %.2f (%.0f-%.0f) | %.3f | %.3f | %.2f | %.3f | %.3f | %.3f | %.1f |" % (
    sys.argv[2], o["count"], sizes["exponent"], sizes["fit_low_km2"], sizes["fit_high_km2"],
    s["perimeter_dimension"]["dimension"], o["largest_share"], o["elongation_median"],
    o["mid_tone_share"], contrast, s["coverage_by_latitude"]["bands_10deg"]["max_abs_error"],
    float(sys.argv[4]) - float(sys.argv[3])))
p = s["cloud_properties"]
with open(sys.argv[1].rsplit("/", 3)[0] + "/properties.md", "a") as rows:
    rows.write("| %s | %.3f | %.3f | %.3f | %.3f +- %.3f | %.3f | %.3f | %.3f | %.2f km |\n" % (
        sys.argv[2], p["thin"], p["medium"], p["thick"], p["log_tau_mean"], p["log_tau_sd"], p["low"],
        p["middle"], p["high"], p["top_mean_km"]))
PY
done
echo
echo "| seed | thin | medium | thick | ln tau | low | middle | high | mean top |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
cat "$work/properties.md"
