#pragma once
// Coverage of each layer channel over the region around the viewpoint: from weather stations
// blended by geodesic distance, or from the global cover when no weather is given.
#include <GeographicLib/LocalCartesian.hpp>

#include <cstdint>
#include <vector>

#include "regional/cloud_layers.hpp"

namespace nephele::regional {

struct WeatherField {
  int size = 0;               // texels per side
  double extent_m = 0;        // half-size of the square, metres east and north of the camera
  std::vector<float> values;  // [channel][row][column]; row 0 is the south edge
  float at(int channel, int column, int row) const {
    return values[(static_cast<size_t>(channel) * size + row) * size + column];
  }
  float max_of(int channel) const;
  // East and north offset (m) of a texel centre.
  double east_of(int column) const { return extent_m * (2.0 * (column + 0.5) / size - 1.0); }
  double north_of(int row) const { return extent_m * (2.0 * (row + 0.5) / size - 1.0); }
};

struct Station {
  double latitude_deg, longitude_deg;
  StationCoverage coverage;
};

// Geodetic position of the ground point at an east/north offset from the frame's origin.
void ground_position(const GeographicLib::LocalCartesian& frame, double east, double north, double& lat, double& lon);

// Inverse-distance weights of power 1 with geodesic distances: at a station its own data, and on
// the geodesic between two stations the linear blend of the original system (weight of A is
// d_B / (d_A + d_B)).
std::vector<double> station_weights(const std::vector<Station>& stations, double lat, double lon);
WeatherField field_from_stations(const std::vector<Station>& stations, const GeographicLib::LocalCartesian& frame,
                                 int size, double extent_m);

// The global cover as the layer rules see it: its cover, and where it has them its optical
// thickness and cloud-top channels (6 faces of size^2 in GL order each; empty: derived from the
// cover by cloud_properties.glsl's fallbacks, with the log-normal's median and spread).
struct CoverChannels {
  int size = 0;
  const std::vector<float>* cover = nullptr;
  const std::vector<float>* optical_thickness = nullptr;  // tau; null or empty: the fallback
  const std::vector<float>* cloud_top = nullptr;          // km above sea level; likewise
  float tau_median = 0, tau_spread = 0;
  double planet_radius_m = 0;  // the sphere the orbit view draws the cover on (its sub-texel field's scale)
};

// Where the base of the cloud with its top at top_km and optical thickness tau lies
// (cloud_thickness_km: the slab the orbit view draws), the share of it in each of the field's
// low, mid and high channels, which follow Open-Meteo's levels (low below 3 km, mid 3-8 km, high
// above; the layer rules' heights): a cloud is in the layer of its base, the first cloud seen
// from below, wholly (1 in one channel, 0 in the others). A blend about the boundaries put half of
// an overcast's cover into each of two layers, whose clouds stand apart: three quarters of the sky
// where the orbit view drew all of it.
struct LevelShares {
  float low = 0, mid = 0, high = 0;
};
LevelShares level_shares(float top_km, float tau);

// From the global cover, as the orbit view draws it, so that the ground renderer's layers put the
// cloud where that view does and hide the share of the sky it covers: the point of geographic
// latitude and longitude is the cover's direction (cos lat cos lon, cos lat sin lon, sin lat) (the
// orbit view's sphere, not the ellipsoid's normal, 21 km apart at Bern); cover, tau and top
// filtered by the cubic B-spline (orbit.comp's cover_at), tau and top weighted by the cover (a
// clear texel's top says nothing); the cover's share below its texels from the orbit view's
// sub-texel field (cloud_properties.glsl's subtexel_cloud) at the footprint of a field texel; and
// that cloud in the channel of its level (level_shares). No fog or convective cells come from the
// cover.
WeatherField field_from_cover(const CoverChannels& cover, const GeographicLib::LocalCartesian& frame, int size,
                              double extent_m);

// The weather's own scale: what a station's cover describes, a region some 5 km across (the
// scale of the global cover's texels at 512 per face is 20 km). A finer field (the cover-driven
// one carries the orbit view's cloud outlines) is read in blocks of texels of about this size:
// a 1.25 km texel is cloudy or clear, a 5 km block has a coverage.
inline constexpr double weather_block_m = 5000.0;
int weather_block(const WeatherField& field);  // texels per block side, >= 1
double block_mean(const WeatherField& field, CoverageChannel channel, int column0, int row0, int block);

// The weather at the camera, synthesised from a cover-driven field (the mean of the block of
// weather_block texels at the field's centre).
WeatherSample sample_from_field(const WeatherField& field, double time);

// What the layer rules read of a cover-driven field: the camera's sample, except that a channel
// with cloud (layer_threshold or more) in any of the field's blocks (weather_block) takes the mean
// of its cloudy blocks.
// A layer then exists wherever the field has its cloud, not only where the camera stands (from
// 16 km up the view spans tens of km: the orbit view draws that cloud, the ground view would have
// had no layer for it), and its type follows the region's cloud.
WeatherSample sample_for_layers(const WeatherField& field, double time);

}  // namespace nephele::regional
