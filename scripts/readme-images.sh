#!/usr/bin/env bash
# Regenerates the README's pictures in docs/images from today's code (after a build in build/):
#   docs/images/cover_equirect.png           nephele generate (defaults), the equirect preview
#   docs/images/cover_stats.png              nephele stats of that cover (coverage by latitude, spectrum, D)
#   docs/images/cover_equirect_no_surface.png  nephele generate --surface none (no land/ocean mask)
#   docs/images/cover_cells.png              a 1024 cover's equirect, 11-46 N, 74 W-15 E (docs/climate.md, "Cells")
#   docs/images/cover_trades.png             the same cover, 34 N-3 S, 171-83 W: the trades' mesoscale patterns
#   docs/images/cover_storm_track.png        the same cover, 33-68 S, 158-68 W: open cells between the storm track's fronts
#   docs/images/cover_itcz.png               the same cover, 22 N-10 S, 160 W-20 E: the ITCZ's meandering line and superclusters
#   docs/images/cover_monsoons.png           a February cover, 35 N-35 S: the ITCZ's monsoons over land
#   docs/images/cover_spcz.png               the same cover, 5.6 N-39 S, 120 E-100 W: the SPCZ
#   docs/images/cover_streets.png            a 4096 cover's equirect, 36-47 N, 48-26 W: cloud streets (6.5 minutes)
#   docs/images/cover_sequence.gif           nephele generate --sequence 24 --interval 3 (a day of the moving cover)
#   docs/images/cover_motion.svg             nephele stats of that sequence (speeds by band, decorrelation)
#   docs/images/render_gurten.png/.json      nephele render --view gurten (--quality final)
#   docs/images/render_gurten_panorama.*     the same scene as a panorama
#   docs/images/render_bantiger.png/.json    nephele render --view bantiger (--quality final)
#   docs/images/model_examples.png           nephele model previews of the four built-in clouds
#   docs/images/render_orbit.png/.json       nephele render --view orbit of the default cover at the render's time
#   docs/images/render_orbit_{36000,2000,400}.png  the same cover from 36000, 2000 and 400 km
#   docs/images/gurten-thunderstorm.png      scenes/gurten-thunderstorm.json (convective clouds)
#   docs/images/bantiger-fog.png             scenes/bantiger-fog.json (the sea of fog from the Bantiger)
# With --orbit it makes the orbit view's images alone (about a minute).
# With --report it also runs `nephele report` (about 35 minutes on two cores) and copies its
# work-precision diagrams (error_vs_runtime*.svg, render_error_vs_runtime.svg,
# moving_error_vs_runtime.svg, noise_grid_error_vs_runtime.svg; `nephele report moving` alone makes the
# last two in about 6 minutes).
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"
nephele=build/nephele
[[ -x "$nephele" ]] || { echo "readme-images: build first (scripts/quickstart.sh)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

orbit_images() {
  # The orbit view's cover at 512 per face, of the moment the view shows (render alone makes 128).
  "$nephele" generate --time 2026-06-21T17:00Z --files faces --quiet --out "$work/cover-orbit"
  # Run from the work folder so that the sidecar records the cover as `cover-orbit`, not a
  # temporary path.
  (cd "$work" && "$repo_root/$nephele" render --view orbit --cover cover-orbit --altitude-km 12000 \
    --time 2026-06-21T17:00Z --quiet --out render_orbit.png)
  cp "$work/render_orbit.png" "$work/render_orbit.json" docs/images/
  # The same cover from geostationary height (the full disk), 2000 km, and 400 km (the ISS's
  # height) looking west-north-west towards the evening sun.
  "$nephele" render --view orbit --cover "$work/cover-orbit" --altitude-km 36000 --time 2026-06-21T12:00Z --quiet \
    --out "$work/render_orbit_36000.png"
  "$nephele" render --view orbit --cover "$work/cover-orbit" --altitude-km 2000 --time 2026-06-21T17:00Z --quiet \
    --out "$work/render_orbit_2000.png"
  "$nephele" render --view orbit --cover "$work/cover-orbit" --altitude-km 400 --heading 290 --pitch -25 --fov 70 \
    --time 2026-06-21T17:00Z --quiet --out "$work/render_orbit_400.png"
  for km in 36000 2000 400; do cp "$work/render_orbit_$km.png" docs/images/; done
}
if [[ "${1:-}" == "--orbit" ]]; then
  orbit_images
  exit 0
fi

"$nephele" generate --out "$work/cover"
cp "$work/cover/cover_equirect.png" docs/images/cover_equirect.png
"$nephele" stats "$work/cover" --out "$work/stats"
cp "$work/stats/stats.png" docs/images/cover_stats.png
"$nephele" generate --sequence 24 --interval 3 --files equirect,png --quiet --out "$work/sequence"
cp "$work/sequence/sequence.gif" docs/images/cover_sequence.gif
"$nephele" stats "$work/sequence" --out "$work/motion"
cp "$work/motion/motion.svg" docs/images/cover_motion.svg
"$nephele" generate --surface none --files png --quiet --out "$work/cover-bare"
cp "$work/cover-bare/cover_equirect.png" docs/images/cover_equirect_no_surface.png
# The convective cells show from 1024 texels a face: a crop of the 4096 x 2048 equirect's Y.
"$nephele" generate --size 1024 --time 2026-06-21T12:00Z --files equirect --quiet --out "$work/cover-cells"
oiiotool "$work/cover-cells/cover_equirect.exr" --ch 0,0,0 --cut 1024x400+1200+500 -d uint8 -o docs/images/cover_cells.png
# The trades' mesoscale patterns (docs/climate.md, "The trades' mesoscale patterns"): the eastern Pacific.
oiiotool "$work/cover-cells/cover_equirect.exr" --ch 0,0,0 --cut 1000x420+100+640 -d uint8 -o docs/images/cover_trades.png
# The ITCZ's line, its superclusters and their systems (docs/climate.md, "The ITCZ's line"): half the tropics.
oiiotool "$work/cover-cells/cover_equirect.exr" --ch 0,0,0 --cut 2048x364+227+774 -d uint8 -o docs/images/cover_itcz.png
# The monsoons (docs/climate.md, "The monsoons"): the tropics of a February cover, the ITCZ south
# over Africa, South America and Australia and near the equator over the oceans.
"$nephele" generate --size 512 --month 2 --files equirect --quiet --out "$work/cover-february"
oiiotool "$work/cover-february/cover_equirect.exr" --ch 0,0,0 --cut 2048x400+0+312 -d uint8 -o docs/images/cover_monsoons.png
# The SPCZ (docs/climate.md, "The SPCZ"): the South Pacific across the date line, the equirect's
# two ends (120 E-180 and 180-100 W) put side by side.
february="$work/cover-february/cover_equirect.exr"
oiiotool "$february" --ch 0,0,0 --cut 455x256+0+480 --origin +341+0 --fullsize 796x256+0+0 \
  "$february" --ch 0,0,0 --cut 341x256+1707+480 --origin +0+0 --fullsize 796x256+0+0 \
  --add --cut 796x256+0+0 -d uint8 -o docs/images/cover_spcz.png
# The storm tracks' open cells between the fronts (docs/climate.md, "The storm tracks' cold air"): the South Pacific.
oiiotool "$work/cover-cells/cover_equirect.exr" --ch 0,0,0 --cut 1024x400+250+1400 -d uint8 -o docs/images/cover_storm_track.png
# The cloud streets show from about 2700 texels a face: a crop of a 4096 cover's 16384 x 8192 equirect.
"$nephele" generate --size 4096 --time 2026-06-21T12:00Z --files equirect --quiet --out "$work/cover-streets"
oiiotool "$work/cover-streets/cover_equirect.exr" --ch 0,0,0 --cut 1000x500+6000+1950 -d uint8 \
  -o docs/images/cover_streets.png
rm -rf "$work/cover-streets"
"$nephele" render --view gurten --quality final --no-cache --out "$work/render_gurten.png"
cp "$work/render_gurten.png" "$work/render_gurten.json" docs/images/
"$nephele" render --view gurten --panorama --quality final --no-cache --out "$work/render_gurten_panorama.png"
cp "$work/render_gurten_panorama.png" "$work/render_gurten_panorama.json" docs/images/
"$nephele" render --view bantiger --quality final --no-cache --quiet --out "$work/render_bantiger.png"
cp "$work/render_bantiger.png" "$work/render_bantiger.json" docs/images/
orbit_images
"$nephele" render --scene scenes/gurten-thunderstorm.json --quality final --no-cache --quiet --out "$work/storm"
cp "$work/storm/gurten-thunderstorm.png" docs/images/gurten-thunderstorm.png
"$nephele" render --scene scenes/bantiger-fog.json --quality final --no-cache --quiet --out "$work/fog"
cp "$work/fog/bantiger-fog.png" docs/images/bantiger-fog.png
# docs/terrain.md: the ground alone towards the Alps, and above it the same without land cover
# and fractal detail (the ETOPO5 surface as before them).
"$nephele" render --scene scenes/gurten-alps-clear.json --quality final --no-cache --quiet --out "$work/alps"
cp "$work/alps/gurten-alps-clear.png" docs/images/terrain_gurten_alps.png
"$nephele" render --scene scenes/gurten-alps-clear.json --land-cover none --terrain-detail 0 --quality final \
  --no-cache --quiet --out "$work/alps-plain"
oiiotool "$work/alps-plain/gurten-alps-clear.png" "$work/alps/gurten-alps-clear.png" --mosaic 1x2 \
  -o docs/images/terrain_side_by_side.png
examples=(fair-weather towering cumulonimbus stratocumulus)
for example in "${examples[@]}"; do
  "$nephele" model --example "$example" --preview 256x256 --quiet --out "$work/model-$example"
done
previews=()
for example in "${examples[@]}"; do previews+=("$work/model-$example/preview.png"); done
oiiotool "${previews[@]}" --mosaic 4x1 -o docs/images/model_examples.png
if [[ "${1:-}" == "--report" ]]; then
  "$nephele" report --out "$work/report"
  cp "$work/report/error_vs_runtime.svg" docs/images/error_vs_runtime.svg
  cp "$work/report/render_error_vs_runtime.svg" docs/images/render_error_vs_runtime.svg
  cp "$work/report/moving_error_vs_runtime.svg" docs/images/moving_error_vs_runtime.svg
  cp "$work/report/noise_grid_error_vs_runtime.svg" docs/images/noise_grid_error_vs_runtime.svg
fi
echo "readme-images: docs/images updated"
