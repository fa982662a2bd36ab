#pragma once
// The planet's surface images for the orbit view (docs/orbit_view.md): equirect day and night
// (city lights) maps read with OpenImageIO and decoded from sRGB to linear values.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/coastline_files.hpp"
#include "render/orbit_renderer.hpp"

namespace nephele::io {

// Debian's xplanet-images: NASA Visible Earth maps, 2048 x 1024, longitude -180 at the left edge,
// north up.
inline const char* const default_earth_texture = "/usr/share/xplanet/images/earth.jpg";
inline const char* const default_night_texture = "/usr/share/xplanet/images/night.jpg";

struct PlanetTextures {
  render::PlanetImages images;
  std::string day_source;               // the file, or "procedural"
  std::string night_source;             // the file, or "none"
  std::string water_source;             // ETOPO5's file, "procedural" or "none" (no sun glint)
  std::string relief_source;            // ETOPO5's file or "none" (flat ground)
  std::vector<std::string> warnings;    // e.g. the default maps are missing: procedural fallback
  std::vector<std::string> from_cache;  // the maps read from the disk cache (sea_free_day, decoded, ...)
};

// `day`: an equirect image (any size, ideally 2:1); "" means the xplanet map, and when that is
// missing a procedural ocean/land map with a warning. `night`: city lights, "" means the xplanet
// map when `day` is also the default (else none). A named file that cannot be read throws
// core::InputError naming `option`. 8-bit images are taken as sRGB, float images as linear.
// With the default day map the water where the sun glints and the ground's relief come from
// ETOPO5 (ferret-datasets: below sea level is water), a warning saying so when it is missing; a
// named day map gets neither.
// `cache_directory` (empty: none): the maps as decoded and derived (the sea-free day map, ETOPO5's
// water and relief) kept in the disk cache of files/float_cache.hpp, keyed on their source files'
// paths, sizes and times and on the program's build (files::program_fingerprint), so that a
// later render reads them instead of decoding and deriving them again (the same values).
PlanetTextures read_planet_textures(const std::string& day, const std::string& night = "",
                                    const std::string& option = "--earth-texture",
                                    const std::filesystem::path& cache_directory = {});

// The window of the ground in view whose water add_view_coast rasters: where the camera's nearest
// pixels are finer than a quarter of the texel of a water map `water_width` texels
// around, the latitudes and longitudes (about the camera's) the frame's rays meet plus a degree,
// every longitude with a pole in view, texels about as fine as those pixels (at most 2048 x
// 2048); none from higher up.
std::optional<GeoWindow> view_coast_window(const render::OrbitCamera& camera, double planet_radius_m, int water_width);

// Whether the camera's nearest pixels (straight below it) are finer than `share` of the texel of
// a water map `water_width` texels around: view_coast_window's first test.
bool coast_pixels_finer(const render::OrbitCamera& camera, double planet_radius_m, int water_width, double share);

// `window` grown by `share` of its size each way (clamped at the poles, at most a whole turn),
// with texels as fine as its own where the 2048 texels a side allow: what a moving camera keeps.
GeoWindow widened_coast_window(const GeoWindow& window, double share);

// The warning for a missing GSHHG shorelines file, or none where it is there.
std::optional<std::string> missing_shorelines_warning();

// With the default day map (sea_colour), within view_coast_window: the water along the ground in
// view from GSHHG's full-resolution shorelines (coastline_files.hpp) as PlanetImages::coast, and
// water_source saying so; a warning where the file is missing.
// `cache_directory` (empty: none) as read_planet_textures'.
void add_view_coast(PlanetTextures& textures, const render::OrbitCamera& camera, double planet_radius_m,
                    const std::filesystem::path& cache_directory = {});

// The checks read_planet_textures makes of named maps, from their headers alone (a missing or
// unreadable file, fewer than 2 pixels across, more than half the available memory as floats):
// a caller that decodes the maps on a thread of its own refuses a bad one before any other work.
void check_planet_maps(const std::string& day, const std::string& night = "",
                       const std::string& option = "--earth-texture");

// A cover directory written by `nephele generate` as a cube map for the renderer.
render::CoverCube read_cover_cube(const std::filesystem::path& directory);

}  // namespace nephele::io
