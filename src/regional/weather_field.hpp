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

// From the global cover (6 faces of cover_size^2 in GL order): the low channel is the cover
// under each point; mid and high are half the cover at directions turned about the polar axis
// by seed-derived angles, so that layers differ. No fog or convective cells come from the cover.
WeatherField field_from_cover(const std::vector<float>& cover, int cover_size, std::uint32_t seed,
                              const GeographicLib::LocalCartesian& frame, int size, double extent_m);

// The weather the layer rules read at the camera, synthesised from a cover-driven field.
WeatherSample sample_from_field(const WeatherField& field, double time);

}  // namespace nephele::regional
