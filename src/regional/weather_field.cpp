#include "regional/weather_field.hpp"

#include <algorithm>
#include <cmath>

#include "regional/sites.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::regional {

float WeatherField::max_of(int channel) const {
  const size_t n = static_cast<size_t>(size) * size;
  return *std::max_element(values.begin() + channel * n, values.begin() + (channel + 1) * n);
}

void ground_position(const GeographicLib::LocalCartesian& frame, double east, double north, double& lat, double& lon) {
  // The tangent plane falls below the surface by about r^2 / 2R; follow the curvature down.
  const double drop = (east * east + north * north) / (2.0 * 6371000.0);
  double h = 0;
  frame.Reverse(east, north, -drop, lat, lon, h);
}

std::vector<double> station_weights(const std::vector<Station>& stations, double lat, double lon) {
  std::vector<double> w(stations.size(), 0.0);
  for (size_t i = 0; i < stations.size(); ++i) {
    const double d = geodesic_distance_m(lat, lon, stations[i].latitude_deg, stations[i].longitude_deg);
    if (d < 1.0) {  // at a station: its own data
      std::fill(w.begin(), w.end(), 0.0);
      w[i] = 1.0;
      return w;
    }
    w[i] = 1.0 / d;
  }
  double sum = 0;
  for (double x : w) sum += x;
  for (double& x : w) x /= sum;
  return w;
}

WeatherField field_from_stations(const std::vector<Station>& stations, const GeographicLib::LocalCartesian& frame,
                                 int size, double extent_m) {
  WeatherField f{size, extent_m, std::vector<float>(static_cast<size_t>(coverage_channels) * size * size, 0.0f)};
  for (int row = 0; row < size; ++row)
    for (int column = 0; column < size; ++column) {
      double lat = 0, lon = 0;
      ground_position(frame, f.east_of(column), f.north_of(row), lat, lon);
      const std::vector<double> w = station_weights(stations, lat, lon);
      for (int c = 0; c < coverage_channels; ++c) {
        double v = 0;
        for (size_t i = 0; i < stations.size(); ++i) v += w[i] * stations[i].coverage.channel[c];
        f.values[(static_cast<size_t>(c) * size + row) * size + column] = static_cast<float>(v);
      }
    }
  return f;
}

WeatherField field_from_cover(const std::vector<float>& cover, int cover_size, std::uint32_t seed,
                              const GeographicLib::LocalCartesian& frame, int size, double extent_m) {
  std::vector<glsl::vec4> texels(cover.size());
  for (size_t k = 0; k < cover.size(); ++k) texels[k] = glsl::vec4(cover[k], 0.0f, 0.0f, 0.0f);
  const glsl::CubeSource source{cover_size, texels.data()};
  const glsl::vec3 turns = glsl::hash_to_unit3(glsl::pcg3d(glsl::uvec3(seed, 0x51u, 0xC0u)));
  const double angle[coverage_channels] = {0.0, 2.0 * M_PI * turns.x, 2.0 * M_PI * turns.y, 0.0, 0.0};
  const int channels_from_cover[3] = {int(CoverageChannel::low), int(CoverageChannel::mid), int(CoverageChannel::high)};
  const double channel_angle[3] = {angle[0], angle[1], angle[2]};
  // Mid and high cloud cover less of the sky than low cloud in satellite climatologies; half the
  // cover's value keeps them thinner and more often broken.
  const float channel_scale[3] = {1.0f, 0.5f, 0.5f};
  WeatherField f{size, extent_m, std::vector<float>(static_cast<size_t>(coverage_channels) * size * size, 0.0f)};
  for (int row = 0; row < size; ++row)
    for (int column = 0; column < size; ++column) {
      double lat = 0, lon = 0;
      ground_position(frame, f.east_of(column), f.north_of(row), lat, lon);
      for (int k = 0; k < 3; ++k) {
        // The cover's direction of a geographic latitude and longitude is the sphere's, as the
        // orbit view, the cover's latitude profile and its equirect take it; the ellipsoid's
        // point of that latitude lies in a direction 0.19 degrees (21 km) further south at Bern.
        const double phi = lat * M_PI / 180, lambda = lon * M_PI / 180 + channel_angle[k];
        const glsl::vec3 direction(float(std::cos(phi) * std::cos(lambda)), float(std::cos(phi) * std::sin(lambda)),
                                   float(std::sin(phi)));
        const float c = channel_scale[k] * glsl::sample_cube_bilinear(direction, source).x;
        f.values[(static_cast<size_t>(channels_from_cover[k]) * size + row) * size + column] = c;
      }
    }
  return f;
}

WeatherSample sample_from_field(const WeatherField& field, double time) {
  const int centre = field.size / 2;
  WeatherSample s;
  s.time = time;
  s.cloud_low = field.at(int(CoverageChannel::low), centre, centre);
  s.cloud_mid = field.at(int(CoverageChannel::mid), centre, centre);
  s.cloud_high = field.at(int(CoverageChannel::high), centre, centre);
  s.cloud_cover = 1.0 - (1.0 - s.cloud_low) * (1.0 - s.cloud_mid) * (1.0 - s.cloud_high);
  return s;
}

}  // namespace nephele::regional
