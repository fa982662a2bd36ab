#include "regional/weather_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/parallel_rows.hpp"
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

LevelShares level_shares(float top_km, float tau) {
  const float base = top_km - glsl::cloud_thickness_km(top_km, tau);
  LevelShares s;
  s.low = base < 3.0f ? 1.0f : 0.0f;
  s.high = base >= 8.0f ? 1.0f : 0.0f;
  s.mid = 1.0f - s.low - s.high;
  return s;
}

WeatherField field_from_cover(const CoverChannels& cover, const GeographicLib::LocalCartesian& frame, int size,
                              double extent_m) {
  const std::size_t texel_count = std::size_t(6) * cover.size * cover.size;
  if (cover.cover == nullptr || cover.size <= 0 || cover.cover->size() != texel_count)
    throw std::logic_error("field_from_cover: the cover is not six faces of " + std::to_string(cover.size) + "^2");
  if (!(cover.planet_radius_m > 0)) throw std::logic_error("field_from_cover: no planet radius");
  const auto channel = [&](const std::vector<float>* values) {
    if (values != nullptr && !values->empty() && values->size() != texel_count)
      throw std::logic_error("field_from_cover: a channel of " + std::to_string(values->size()) + " texels");
    return values != nullptr && !values->empty() ? values : nullptr;
  };
  const std::vector<float>* tau = channel(cover.optical_thickness);
  const std::vector<float>* top = channel(cover.cloud_top);
  // (c, c tau, c top, 0) per texel: the filter then gives the cover-weighted means.
  std::vector<glsl::vec4> texels(texel_count);
  for (std::size_t k = 0; k < texel_count; ++k) {
    const float c = (*cover.cover)[k];
    texels[k] = glsl::vec4(c, tau != nullptr ? c * (*tau)[k] : 0.0f, top != nullptr ? c * (*top)[k] : 0.0f, 0.0f);
  }
  const glsl::CubeSource source{cover.size, texels.data()};
  const float radius = static_cast<float>(cover.planet_radius_m);
  const float cover_texel = static_cast<float>(cover.planet_radius_m * (M_PI / 2) / cover.size);
  WeatherField f{size, extent_m, std::vector<float>(static_cast<size_t>(coverage_channels) * size * size, 0.0f)};
  const float footprint = static_cast<float>(2.0 * extent_m / size);
  const auto put = [&](CoverageChannel c, int row, int column, float value) {
    f.values[(static_cast<size_t>(c) * size + row) * size + column] = value;
  };
  // Rows on the machine's threads: the texels are independent (the B-spline filter and the sub-texel
  // cloud on the CPU, about 0.12 s for 256^2 on one core) and each thread writes only its own rows.
  core::parallel_rows(size, [&](int first, int end) {
    for (int row = first; row < end; ++row)
      for (int column = 0; column < size; ++column) {
        double lat = 0, lon = 0;
        ground_position(frame, f.east_of(column), f.north_of(row), lat, lon);
        // The cover's direction of a geographic latitude and longitude is the sphere's, as the orbit
        // view, the cover's latitude profile and its equirect take it; the ellipsoid's point of that
        // latitude lies in a direction 0.19 degrees (21 km) further south at Bern.
        const double phi = lat * M_PI / 180, lambda = lon * M_PI / 180;
        const glsl::vec3 n(float(std::cos(phi) * std::cos(lambda)), float(std::cos(phi) * std::sin(lambda)),
                           float(std::sin(phi)));
        const glsl::CubeBsplineTaps taps = glsl::cube_bspline_taps(n, float(cover.size));
        const glsl::vec4 sample = glsl::cube_bspline_combine(
            taps, glsl::sample_cube_bilinear(taps.d00, source), glsl::sample_cube_bilinear(taps.d10, source),
            glsl::sample_cube_bilinear(taps.d01, source), glsl::sample_cube_bilinear(taps.d11, source));
        const float c = std::clamp(sample.x, 0.0f, 1.0f);
        if (c <= 0.0f) continue;
        const float latitude = std::asin(std::clamp(n.z, -1.0f, 1.0f));
        const float t = tau != nullptr ? sample.y / sample.x
                                       : glsl::optical_thickness_from_cover(c, cover.tau_median, cover.tau_spread);
        const float h = top != nullptr ? sample.z / sample.x : glsl::cloud_top_from_cover(c, latitude);
        // The sub-texel cloud as the orbit view draws it (orbit.comp's cloud_slab), veils uncarved.
        const float carved = glsl::subtexel_cloud(n * radius, c, cover_texel, footprint).cover;
        const float cloudy = c + glsl::subtexel_carving(h, t) * (carved - c);
        const LevelShares shares = level_shares(h, t);
        put(CoverageChannel::low, row, column, cloudy * shares.low);
        put(CoverageChannel::mid, row, column, cloudy * shares.mid);
        put(CoverageChannel::high, row, column, cloudy * shares.high);
      }
  });
  return f;
}

int weather_block(const WeatherField& field) {
  const double texel = 2.0 * field.extent_m / field.size;
  return std::clamp(static_cast<int>(std::lround(weather_block_m / texel)), 1, field.size);
}

double block_mean(const WeatherField& field, CoverageChannel channel, int column0, int row0, int block) {
  double sum = 0;
  for (int row = row0; row < row0 + block; ++row)
    for (int column = column0; column < column0 + block; ++column) sum += field.at(int(channel), column, row);
  return sum / (static_cast<double>(block) * block);
}

WeatherSample sample_from_field(const WeatherField& field, double time) {
  const int block = weather_block(field);
  const int first = field.size / 2 - block / 2;
  WeatherSample s;
  s.time = time;
  s.may_be_fog = false;
  s.cloud_low = block_mean(field, CoverageChannel::low, first, first, block);
  s.cloud_mid = block_mean(field, CoverageChannel::mid, first, first, block);
  s.cloud_high = block_mean(field, CoverageChannel::high, first, first, block);
  s.cloud_cover = 1.0 - (1.0 - s.cloud_low) * (1.0 - s.cloud_mid) * (1.0 - s.cloud_high);
  return s;
}

WeatherSample sample_for_layers(const WeatherField& field, double time) {
  WeatherSample s = sample_from_field(field, time);
  const int block = weather_block(field);
  for (const auto& [channel, value] : {std::pair{CoverageChannel::low, &s.cloud_low},
                                       {CoverageChannel::mid, &s.cloud_mid},
                                       {CoverageChannel::high, &s.cloud_high}}) {
    double sum = 0;
    std::size_t cloudy = 0;
    for (int row = 0; row + block <= field.size; row += block)
      for (int column = 0; column + block <= field.size; column += block) {
        const double v = block_mean(field, channel, column, row, block);
        if (v >= layer_threshold) sum += v, ++cloudy;
      }
    if (cloudy > 0) *value = sum / static_cast<double>(cloudy);
  }
  s.cloud_cover = 1.0 - (1.0 - s.cloud_low) * (1.0 - s.cloud_mid) * (1.0 - s.cloud_high);
  return s;
}

}  // namespace nephele::regional
