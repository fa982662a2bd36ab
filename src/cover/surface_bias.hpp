#pragma once
// The land/ocean mask's share of the cloud density (--surface; docs/climate.md, "Land and
// ocean"): fewer clouds over the subtropical deserts, stratocumulus decks over the cool
// oceans off the subtropical west coasts. The density pass multiplies the warped noise by
// 1 + k b, b the bias of this file in [-1, 1] sampled at the texel's latitude and longitude,
// before the calibration keeps every band's coverage.
#include <memory>
#include <string>
#include <vector>

namespace nephele::cover {

// An equirectangular land fraction: row 0 at the north edge, column 0 at longitude -180 deg
// (the convention of the cover's own equirect and of the Earth textures), cell centres at
// (i + 0.5) / columns of the turn and 90 - (j + 0.5) 180 / rows degrees of latitude.
struct SurfaceMask {
  int columns = 0, rows = 0;
  std::vector<float> land;  // rows * columns, 0 ocean .. 1 land
  std::string source;       // the --surface value, for cover.json and messages
};

// Grid of the bias: 720 x 360 (half a degree), finer than any deck or desert and coarse
// enough for the CPU (0.26 M cells).
constexpr int surface_bias_columns = 720;
constexpr int surface_bias_rows = 360;

// The mask resampled to the bias grid by area averages of the cells each bias cell overlaps
// (nearest cell where the mask is coarser).
SurfaceMask resample_surface(const SurfaceMask& mask, int columns, int rows);

// The subtropical weights of the desert and of the deck terms at |latitude| (degrees):
// exp(-((|lat| - 24) / 8)^2) and exp(-((|lat| - 22) / 9)^2) (docs/climate.md gives sources).
double desert_weight(double latitude_deg);
double deck_weight(double latitude_deg);
// The mid-latitude continental interiors' weight at |latitude| (degrees), exp(-((|lat| - 43) / 8)^2),
// and how far inland a cell is by its distance to the nearest ocean cell, smoothstep(500, 1500 km):
// the dry interiors of Central Asia and of the American Great Basin and Plains, far from the sea
// that moistens the air (docs/climate.md, "Land and ocean").
double interior_weight(double latitude_deg);
double inland(double ocean_distance_km);
// Each cell's great-circle-like distance (km, on the 6371 km sphere) to the nearest cell whose land
// fraction is below 1/2, along paths through the grid's eight neighbours (a Dijkstra search;
// longitude wraps); a grid without ocean gives infinity everywhere.
std::vector<float> ocean_distance_km(const SurfaceMask& grid);

// b = deck - desert on the bias grid (surface_bias_columns x surface_bias_rows, the mask's
// convention): desert = land max(S_desert(lat), S_interior(lat) inland(distance to the ocean));
// deck = (1 - land) S_deck(lat) E W, E the largest
// land fraction within 15 degrees of longitude to the east weighted by 1 - distance / 15 deg
// (the ocean off a west coast), W smoothstep(10, 30 deg) of the stretch of open ocean to the west
// before the first land cell (an ocean basin's eastern side: no decks on seas with a coast close to
// their west, such as the Red Sea, the Arabian Sea or the Bay of Bengal); then three
// 9 x 9 box filters (wrapping in longitude; about a Gaussian of 2.2 degrees) so that coasts do
// not draw sharp lines into the cover.
std::vector<float> surface_bias(const SurfaceMask& mask);

// The bias's two terms on the same grid, each filtered as the bias, and the sea's share, filtered
// alike: (deck, desert, sea) per cell, interleaved, all >= 0, b = deck - desert, sea = 1 - land
// (where the cold air's open cells may form: weather_systems.glsl's cold_air and
// storm_track_cold_air). The decks' strength takes the deck term alone (weather_systems.glsl's
// deck_strength): the filtered difference falls steeply where a deck meets a desert coast (West Africa: +0.5 to -0.9
// within 6 degrees), and its zero 50-100 km off the coast drew the deck's bright edge as a line parallel to the coast
// across the cloud, while the deck term reaches the coast and fades over the land, where the desert term clears the
// cloud.
std::vector<float> surface_terms(const SurfaceMask& mask);

}  // namespace nephele::cover
