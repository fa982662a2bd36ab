#include "studies/cover_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "cover/latitude_profile.hpp"
#include "cover/solid_angle.hpp"
#include "io/export_presets.hpp"
#include "files/image_files.hpp"
#include "params/table.hpp"
#include "params/values.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::studies {
namespace {

constexpr double degree = M_PI / 180.0;
constexpr int histogram_bins = 20;  // over (0, 1], after the clear bin
constexpr double stats_max_latitude = 60.0;
constexpr long min_object_area = 10;

// Geodetic latitude (degrees) of row r's centre and edges of an equirect of `height` rows.
double row_latitude_deg(int row, int height, double offset = 0.5) { return 90.0 - (row + offset) * 180.0 / height; }

// Calls visit(row, solid-angle weight of one pixel of the row (fraction of the sphere),
// geocentric latitude of the row's centre) for every row.
template <class Visit>
void for_each_row(const Equirect& map, Visit&& visit) {
  for (int r = 0; r < map.height; ++r) {
    const double top = geocentric_latitude(row_latitude_deg(r, map.height, 0.0) * degree);
    const double bottom = geocentric_latitude(row_latitude_deg(r, map.height, 1.0) * degree);
    const double weight = 0.5 * (std::sin(top) - std::sin(bottom)) / map.width;
    visit(r, weight, geocentric_latitude(row_latitude_deg(r, map.height) * degree));
  }
}

int band_of_latitude(double latitude, int bands) {
  return std::clamp(static_cast<int>(std::floor((latitude / M_PI + 0.5) * bands)), 0, bands - 1);
}

std::vector<double> ratio(const std::vector<double>& cloudy, const std::vector<double>& total) {
  std::vector<double> out(cloudy.size(), 0.0);
  for (size_t b = 0; b < out.size(); ++b) out[b] = total[b] > 0.0 ? cloudy[b] / total[b] : 0.0;
  return out;
}

void fft(std::vector<std::complex<double>>& a) {
  const size_t n = a.size();
  for (size_t i = 1, j = 0; i < n; ++i) {
    size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (size_t length = 2; length <= n; length <<= 1) {
    const std::complex<double> step = std::polar(1.0, -2.0 * M_PI / static_cast<double>(length));
    for (size_t i = 0; i < n; i += length) {
      std::complex<double> w(1.0);
      for (size_t k = 0; k < length / 2; ++k, w *= step) {
        const std::complex<double> u = a[i + k], v = a[i + k + length / 2] * w;
        a[i + k] = u + v;
        a[i + k + length / 2] = u - v;
      }
    }
  }
}

// |X_k|^2 / n^2 for k = 1 .. n/2: the FFT for powers of two, else the direct sum (small maps).
std::vector<double> row_power(const std::vector<double>& row) {
  const size_t n = row.size();
  std::vector<double> power(n / 2, 0.0);
  if ((n & (n - 1)) == 0) {
    std::vector<std::complex<double>> a(row.begin(), row.end());
    fft(a);
    for (size_t k = 1; k <= n / 2; ++k) power[k - 1] = std::norm(a[k]) / (double(n) * n);
    return power;
  }
  for (size_t k = 1; k <= n / 2; ++k) {
    std::complex<double> sum(0.0);
    for (size_t x = 0; x < n; ++x) sum += row[x] * std::polar(1.0, -2.0 * M_PI * double(k * x % n) / double(n));
    power[k - 1] = std::norm(sum) / (double(n) * n);
  }
  return power;
}

// The rows whose centre's geodetic latitude is within max_latitude_deg of the equator.
std::pair<int, int> central_rows(int height, double max_latitude_deg) {
  int first = height, last = -1;
  for (int r = 0; r < height; ++r)
    if (std::abs(row_latitude_deg(r, height)) <= max_latitude_deg) {
      first = std::min(first, r);
      last = std::max(last, r);
    }
  return {first, last};
}

std::vector<double> json_numbers(const json::Value* array) {
  std::vector<double> out;
  if (!array || !array->is_array()) return out;
  for (const json::Value& v : array->as_array())
    if (v.is_number()) out.push_back(v.as_number());
  return out;
}

// Means of consecutive groups of 2-degree values weighted by the bands' areas.
std::vector<double> coarsen(const std::vector<double>& fine, int factor) {
  const std::vector<double> areas = cover::band_areas(static_cast<int>(fine.size()));
  std::vector<double> out;
  for (size_t b = 0; b + factor <= fine.size(); b += factor) {
    double sum = 0.0, area = 0.0;
    for (int k = 0; k < factor; ++k) {
      sum += fine[b + k] * areas[b + k];
      area += areas[b + k];
    }
    out.push_back(sum / area);
  }
  return out;
}

json::Value array_of(const std::vector<double>& values) {
  json::Value::Array a;
  for (double v : values) a.emplace_back(v);
  return a;
}

}  // namespace

double geocentric_latitude(double geodetic) {
  constexpr double e2 = 6.69437999014e-3;  // WGS84 first eccentricity squared
  return std::atan((1.0 - e2) * std::tan(geodetic));
}

std::vector<double> band_coverage_faces(const std::vector<float>& faces, int size, int bands) {
  const std::vector<double> weights = cover::face_texel_solid_angles(size);
  std::vector<double> cloudy(bands, 0.0), total(bands, 0.0);
  const size_t per_face = static_cast<size_t>(size) * size;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        // The band of the texel's centre, as the calibration puts it (latitude_bands.glsl).
        const int band = glsl::band_of(glsl::band_coordinate(glsl::texel_direction(face, i, j, size), bands), bands);
        const size_t k = static_cast<size_t>(j) * size + i;
        total[band] += weights[k];
        if (faces[face * per_face + k] > 0.0f) cloudy[band] += weights[k];
      }
  return ratio(cloudy, total);
}

std::vector<double> band_coverage_equirect(const Equirect& map, int bands) {
  std::vector<double> cloudy(bands, 0.0), total(bands, 0.0);
  for_each_row(map, [&](int r, double weight, double latitude) {
    const int band = band_of_latitude(latitude, bands);
    for (int x = 0; x < map.width; ++x) {
      total[band] += weight;
      if (map.values[static_cast<size_t>(r) * map.width + x] > 0.0f) cloudy[band] += weight;
    }
  });
  return ratio(cloudy, total);
}

std::vector<double> zonal_power_spectrum(const Equirect& map, double max_latitude_deg) {
  const auto [first, last] = central_rows(map.height, max_latitude_deg);
  std::vector<double> mean_power(map.width / 2, 0.0);
  if (last < first) return mean_power;
  std::vector<double> row(map.width);
  for (int r = first; r <= last; ++r) {
    double mean = 0.0;
    for (int x = 0; x < map.width; ++x) mean += row[x] = map.values[static_cast<size_t>(r) * map.width + x];
    mean /= map.width;
    for (double& v : row) v -= mean;
    const std::vector<double> power = row_power(row);
    for (size_t k = 0; k < power.size(); ++k) mean_power[k] += power[k] / (last - first + 1);
  }
  return mean_power;
}

PowerLaw fit_power_law(const std::vector<double>& x, const std::vector<double>& y, double x_low, double x_high) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  PowerLaw fit;
  for (size_t k = 0; k < x.size(); ++k) {
    if (x[k] < x_low || x[k] > x_high || !(y[k] > 0.0) || !(x[k] > 0.0)) continue;
    const double lx = std::log10(x[k]), ly = std::log10(y[k]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    ++fit.points;
  }
  const double n = fit.points, denominator = n * sxx - sx * sx;
  if (fit.points < 2 || denominator <= 0.0) {
    fit.slope = fit.intercept = std::numeric_limits<double>::quiet_NaN();
    return fit;
  }
  fit.slope = (n * sxy - sx * sy) / denominator;
  fit.intercept = (sy - fit.slope * sx) / n;
  return fit;
}

std::vector<CloudObject> cloud_objects(const Equirect& map, double max_latitude_deg, bool keep_cut) {
  const auto rows_range = central_rows(map.height, max_latitude_deg);
  const int first = rows_range.first, last = rows_range.second;  // captured below: no bindings (C++17)
  std::vector<CloudObject> objects;
  if (last < first) return objects;
  const int rows = last - first + 1, w = map.width;
  // Pixel sizes on the mean sphere: a pixel spans 360/W degrees of longitude and 180/H of latitude.
  const double radius_km = 6371.0, step_lon = 2.0 * M_PI / w, step_lat = M_PI / map.height;
  auto cloudy = [&](int r, int x) { return map.values[static_cast<size_t>(first + r) * w + x] > 0.0f; };
  std::vector<char> seen(static_cast<size_t>(rows) * w, 0);
  std::vector<std::pair<int, int>> stack;
  for (int r0 = 0; r0 < rows; ++r0)
    for (int x0 = 0; x0 < w; ++x0) {
      if (seen[static_cast<size_t>(r0) * w + x0] || !cloudy(r0, x0)) continue;
      CloudObject object;
      // Second moments in local km about the seed pixel: east from the longitude difference
      // (unwrapped across the seam) at each row's latitude, north from the row difference.
      double m0 = 0, mx = 0, my = 0, mxx = 0, myy = 0, mxy = 0;
      stack.assign(1, {r0, x0});
      seen[static_cast<size_t>(r0) * w + x0] = 1;
      while (!stack.empty()) {
        const auto [r, x] = stack.back();
        stack.pop_back();
        ++object.area;
        if (r == 0 || r == rows - 1) object.cut = true;
        const double latitude = row_latitude_deg(first + r, map.height) * degree;
        const double a = radius_km * radius_km * std::cos(latitude) * step_lon * step_lat;
        const int dx = ((x - x0) % w + w + w / 2) % w - w / 2;
        const double east = radius_km * std::cos(latitude) * step_lon * dx, north = radius_km * step_lat * (r0 - r);
        m0 += a, mx += a * east, my += a * north, mxx += a * east * east, myy += a * north * north;
        mxy += a * east * north;
        const int neighbours[4][2] = {{r - 1, x}, {r + 1, x}, {r, (x + 1) % w}, {r, (x + w - 1) % w}};
        for (const auto& n : neighbours) {
          if (n[0] < 0 || n[0] >= rows) continue;  // beyond the window: the object is cut anyway
          if (!cloudy(n[0], n[1])) {
            ++object.perimeter;
            continue;
          }
          char& s = seen[static_cast<size_t>(n[0]) * w + n[1]];
          if (!s) {
            s = 1;
            stack.push_back({n[0], n[1]});
          }
        }
      }
      object.area_km2 = m0;
      // Covariance of the area (plus a pixel's own spread, so that a single pixel is round).
      const double cx = mx / m0, cy = my / m0;
      const double pixel_x = radius_km * step_lon, pixel_y = radius_km * step_lat;
      const double sxx = mxx / m0 - cx * cx + pixel_x * pixel_x / 12, syy = myy / m0 - cy * cy + pixel_y * pixel_y / 12;
      const double sxy = mxy / m0 - cx * cy;
      const double mean = 0.5 * (sxx + syy), spread = std::sqrt(0.25 * (sxx - syy) * (sxx - syy) + sxy * sxy);
      object.elongation = mean - spread > 0 ? std::sqrt((mean + spread) / (mean - spread)) : 1.0;
      if (keep_cut || !object.cut) objects.push_back(object);
    }
  return objects;
}

PerimeterDimension perimeter_dimension(const std::vector<CloudObject>& objects, long min_area) {
  std::vector<double> area, perimeter;
  PerimeterDimension d;
  d.min_area = std::numeric_limits<long>::max();
  for (const CloudObject& o : objects) {
    if (o.area < min_area || o.cut) continue;
    area.push_back(static_cast<double>(o.area));
    perimeter.push_back(static_cast<double>(o.perimeter));
    d.min_area = std::min(d.min_area, o.area);
    d.max_area = std::max(d.max_area, o.area);
  }
  if (area.empty()) d.min_area = 0;
  const PowerLaw fit = fit_power_law(area, perimeter, 0.0, std::numeric_limits<double>::infinity());
  d.dimension = 2.0 * fit.slope;
  d.objects = fit.points;
  return d;
}

ObjectStatistics object_statistics(const Equirect& map, const std::vector<CloudObject>& all, double max_latitude_deg) {
  ObjectStatistics o;
  std::vector<double> elongations;
  double total = 0.0, largest = 0.0;
  for (const CloudObject& object : all) {
    total += object.area_km2;
    largest = std::max(largest, object.area_km2);
    if (object.cut) continue;
    ++o.objects;
    if (object.area >= min_object_area) elongations.push_back(object.elongation);
  }
  o.largest_share = total > 0.0 ? largest / total : 0.0;
  if (!elongations.empty()) {
    std::nth_element(elongations.begin(), elongations.begin() + elongations.size() / 2, elongations.end());
    o.elongation_median = elongations[elongations.size() / 2];
  }
  // N(>= a) on thresholds ten to a decade, from 10 pixels at the equator to 1e6 km2.
  const double pixel_km2 = 6371.0 * 6371.0 * (2.0 * M_PI / map.width) * (M_PI / map.height);
  std::vector<double> fit_a, fit_n;
  for (double log_a = std::log10(10.0 * pixel_km2); log_a <= 6.0 + 1e-9; log_a += 0.1) {
    const double a = std::pow(10.0, log_a);
    double n = 0;
    for (const CloudObject& object : all)
      if (!object.cut && object.area_km2 >= a) ++n;
    o.thresholds_km2.push_back(a);
    o.count_at_least.push_back(n);
    if (n >= 24) fit_a.push_back(a), fit_n.push_back(n);
  }
  if (fit_a.size() >= 2) {
    o.size_fit = fit_power_law(fit_a, fit_n, 0.0, std::numeric_limits<double>::infinity());
    o.size_exponent = -o.size_fit.slope;
    o.fit_low_km2 = fit_a.front(), o.fit_high_km2 = fit_a.back();
  }
  // Brightness measures over the window's cloudy pixels, weighted by their areas.
  const auto [first, last] = central_rows(map.height, max_latitude_deg);
  double cloudy = 0, mid = 0, sum = 0, edge_weight = 0, edge_sum = 0;
  const int w = map.width;
  for (int r = first; r <= last; ++r) {
    const double weight = std::cos(row_latitude_deg(r, map.height) * degree);
    for (int x = 0; x < w; ++x) {
      const float c = map.values[static_cast<size_t>(r) * w + x];
      if (!(c > 0.0f)) continue;
      cloudy += weight, sum += weight * c;
      if (c >= 0.25f && c < 0.75f) mid += weight;
      const auto clear = [&](int rr, int xx) {
        return rr >= 0 && rr < map.height && !(map.values[static_cast<size_t>(rr) * w + (xx + w) % w] > 0.0f);
      };
      if (clear(r - 1, x) || clear(r + 1, x) || clear(r, x - 1) || clear(r, x + 1))
        edge_weight += weight, edge_sum += weight * c;
    }
  }
  o.mid_tone_share = cloudy > 0 ? mid / cloudy : 0.0;
  o.cloudy_mean = cloudy > 0 ? sum / cloudy : 0.0;
  o.edge_value = edge_weight > 0 ? edge_sum / edge_weight : 0.0;
  return o;
}

CloudPropertyStatistics cloud_property_statistics(const std::vector<float>& cover,
                                                  const std::vector<float>& optical_thickness,
                                                  const std::vector<float>& cloud_top, int size) {
  CloudPropertyStatistics p;
  if (optical_thickness.size() != cover.size() || cloud_top.size() != cover.size() || cover.empty()) return p;
  p.present = true;
  const std::vector<double> weights = cover::face_texel_solid_angles(size);
  double total = 0, log_sum = 0, log_square = 0, top_sum = 0;
  for (size_t k = 0; k < cover.size(); ++k) {
    if (!(cover[k] > 0.0f)) continue;
    const double w = weights[k % weights.size()];
    const double tau = std::max(1e-6, static_cast<double>(optical_thickness[k]));
    const double top = cloud_top[k];
    total += w;
    (tau < 3.6 ? p.thin : tau < 23.0 ? p.medium : p.thick) += w;
    (top < 3.2 ? p.low : top < 6.5 ? p.middle : p.high) += w;
    log_sum += w * std::log(tau);
    log_square += w * std::log(tau) * std::log(tau);
    top_sum += w * top;
  }
  if (total <= 0) return p;
  for (double* share : {&p.thin, &p.medium, &p.thick, &p.low, &p.middle, &p.high}) *share /= total;
  p.log_tau_mean = log_sum / total;
  p.log_tau_sd = std::sqrt(std::max(0.0, log_square / total - p.log_tau_mean * p.log_tau_mean));
  p.top_mean_km = top_sum / total;
  return p;
}

CoverStatistics cover_statistics(const std::filesystem::path& cover_dir) {
  if (!std::filesystem::is_directory(cover_dir))
    throw core::InputError("COVER_DIR", cover_dir.string(), "a directory written by nephele generate",
                           "is not a directory");
  CoverStatistics stats;
  const std::filesystem::path sidecar_path = cover_dir / "cover.json";
  std::string text;
  try {
    text = core::read_input_file(sidecar_path.string());
    stats.sidecar = json::parse(text);
  } catch (const std::exception& e) {
    throw core::InputError(sidecar_path.string(), "", "the cover.json of nephele generate",
                           std::string("cannot be read: ") + e.what());
  }
  const json::Value* parameters = stats.sidecar.find("parameters");
  const json::Value* size_value = parameters && parameters->is_object() ? parameters->find("size") : nullptr;
  if (!size_value || !size_value->is_number())
    throw core::InputError(sidecar_path.string() + ": parameters.size", "", params::cover::size.range_text(),
                           "is missing or not a number");
  // The table's range before any use: 1e300 would not fit an int, 536870912 would overflow 4 size.
  params::check_number(params::cover::size, size_value->as_number(), sidecar_path.string() + ": parameters.size");
  const int size = static_cast<int>(size_value->as_number());

  const bool has_faces = std::filesystem::exists(cover_dir / "cover_px.exr");
  const std::filesystem::path equirect_path = cover_dir / "cover_equirect.exr";
  std::optional<Equirect> map;
  if (std::filesystem::exists(equirect_path)) {
    core::ImageData image;
    try {
      image = files::read_image(equirect_path);
    } catch (const std::exception& e) {
      throw core::InputError(equirect_path.string(), "", "an OpenEXR equirect map",
                             std::string("cannot be read: ") + e.what());
    }
    if (image.width != 4 * size || image.height != 2 * size)
      throw core::InputError(
          equirect_path.string(), std::to_string(image.width) + " x " + std::to_string(image.height),
          std::to_string(4 * size) + " x " + std::to_string(2 * size) + " (4 size x 2 size of cover.json)",
          "has the wrong size");
    Equirect m{image.width, image.height, {}};
    m.values.resize(static_cast<size_t>(m.width) * m.height);
    for (size_t k = 0; k < m.values.size(); ++k) m.values[k] = image.pixels[k * image.channels];
    map = std::move(m);
  }
  if (!has_faces && !map)
    throw core::InputError("COVER_DIR", cover_dir.string(), "cover_{px,...}.exr faces or cover_equirect.exr",
                           "has no cover images");

  // Histogram bins: clear, then 20 over (0, 1]; weighted by solid angle.
  stats.histogram.assign(histogram_bins + 1, 0.0);
  auto add = [&](float v, double weight) {
    const int bin =
        v > 0.0f ? 1 + std::min(histogram_bins - 1, static_cast<int>(std::ceil(v * histogram_bins)) - 1) : 0;
    stats.histogram[std::max(bin, 0)] += weight;
  };
  if (has_faces) {
    const io::CoverFaces faces = io::read_cover_faces(cover_dir);
    if (faces.size != size)
      throw core::InputError((cover_dir / "cover_px.exr").string(), std::to_string(faces.size),
                             std::to_string(size) + " (parameters.size of cover.json)", "has the wrong face size");
    stats.coverage_source = "faces";
    stats.coverage_2deg = band_coverage_faces(faces.texels, size, 90);
    stats.coverage_10deg = band_coverage_faces(faces.texels, size, 18);
    const std::vector<double> weights = cover::face_texel_solid_angles(size);
    for (size_t k = 0; k < faces.texels.size(); ++k) add(faces.texels[k], weights[k % weights.size()] / (4.0 * M_PI));
    stats.properties = cloud_property_statistics(faces.texels, faces.optical_thickness, faces.cloud_top, size);
  } else {
    stats.coverage_source = "equirect";
    stats.coverage_2deg = band_coverage_equirect(*map, 90);
    stats.coverage_10deg = band_coverage_equirect(*map, 18);
    for_each_row(*map, [&](int r, double weight, double) {
      for (int x = 0; x < map->width; ++x) add(map->values[static_cast<size_t>(r) * map->width + x], weight);
    });
  }
  if (const json::Value* result = stats.sidecar.find("result"))
    if (const json::Value* profile = result->is_object() ? result->find("profile") : nullptr) {
      stats.target_2deg = json_numbers(profile->find("targets"));
      if (stats.target_2deg.size() == 90)
        stats.target_10deg = coarsen(stats.target_2deg, 5);
      else
        stats.target_2deg.clear();
    }
  if (map) {
    stats.spectrum = zonal_power_spectrum(*map, stats_max_latitude);
    std::vector<double> k(stats.spectrum.size());
    for (size_t i = 0; i < k.size(); ++i) k[i] = static_cast<double>(i + 1);
    // Wavenumbers 16 to 512 cycles per circle (2500 to 78 km at the equator): above the
    // largest scales, where the warp's few cells flatten the spectrum, and below the pixel
    // scale of every map from size 512 on (W / 8 where the map is smaller).
    stats.fit_k_low = 16;
    stats.fit_k_high = std::max(32, std::min(512, map->width / 8));
    stats.spectrum_fit = fit_power_law(k, stats.spectrum, stats.fit_k_low, stats.fit_k_high);
    const std::vector<CloudObject> objects = cloud_objects(*map, stats_max_latitude, true);
    stats.perimeter = perimeter_dimension(objects, min_object_area);
    stats.objects = object_statistics(*map, objects, stats_max_latitude);
  }
  return stats;
}

json::Value statistics_json(const CoverStatistics& s) {
  json::Value root;
  root.set("program", "nephele stats");
  json::Value coverage;
  coverage.set("source", s.coverage_source);
  coverage.set("definition",
               "solid-angle fraction of each band where cover > 0; a texel counts in the band of its centre's "
               "geocentric latitude");
  coverage.set("bands_south_to_north", "band b spans -90 + w b to -90 + w (b + 1) degrees");
  json::Value two, ten;
  two.set("width_deg", 2.0);
  two.set("coverage", array_of(s.coverage_2deg));
  ten.set("width_deg", 10.0);
  ten.set("coverage", array_of(s.coverage_10deg));
  if (!s.target_2deg.empty()) {
    two.set("target", array_of(s.target_2deg));
    ten.set("target", array_of(s.target_10deg));
    double worst = 0.0;
    for (size_t b = 0; b < s.target_10deg.size(); ++b)
      worst = std::max(worst, std::abs(s.coverage_10deg[b] - s.target_10deg[b]));
    ten.set("max_abs_error", worst);
  }
  coverage.set("bands_2deg", two);
  coverage.set("bands_10deg", ten);
  root.set("coverage_by_latitude", coverage);
  if (s.properties.present) {
    const CloudPropertyStatistics& p = s.properties;
    json::Value properties;
    properties.set("definition",
                   "over the faces' cloudy texels (cover > 0), weighted by solid angle: shares of ISCCP's optical "
                   "thickness classes (thin tau < 3.6, medium, thick tau >= 23) and cloud-top classes (low below "
                   "3.2 km, middle, high from 6.5 km); mean and standard deviation of ln tau");
    properties.set("thin", p.thin);
    properties.set("medium", p.medium);
    properties.set("thick", p.thick);
    properties.set("log_tau_mean", p.log_tau_mean);
    properties.set("log_tau_sd", p.log_tau_sd);
    properties.set("low", p.low);
    properties.set("middle", p.middle);
    properties.set("high", p.high);
    properties.set("top_mean_km", p.top_mean_km);
    root.set("cloud_properties", properties);
  }
  if (!s.spectrum.empty()) {
    json::Value spectrum;
    spectrum.set("definition",
                 "mean over equirect rows within 60 deg of the equator of |X_k|^2 / W^2 (row mean removed); k: cycles "
                 "around the latitude circle");
    spectrum.set("power", array_of(s.spectrum));
    spectrum.set("fit_k_low", s.fit_k_low);
    spectrum.set("fit_k_high", s.fit_k_high);
    spectrum.set("slope", s.spectrum_fit.slope);
    spectrum.set("fit_points", s.spectrum_fit.points);
    root.set("zonal_spectrum", spectrum);
    json::Value perimeter;
    perimeter.set("definition",
                  "objects: 4-connected cloudy pixels (cover > 0) of the equirect rows within 60 deg of the equator, "
                  "periodic in longitude, not touching the first or last of those rows, at least 10 pixels; P: pixel "
                  "edges to clear pixels; D = 2 x least-squares slope of log P against log A");
    perimeter.set("dimension", s.perimeter.dimension);
    perimeter.set("objects", s.perimeter.objects);
    perimeter.set("min_area_px", static_cast<double>(s.perimeter.min_area));
    perimeter.set("max_area_px", static_cast<double>(s.perimeter.max_area));
    root.set("perimeter_dimension", perimeter);
    const ObjectStatistics& o = s.objects;
    json::Value objects;
    objects.set("definition",
                "cloud objects (cover > 0, 4-connected) within 60 degrees of the equator, those cut by the "
                "window left out of counts and sizes; areas on a sphere of 6371 km");
    objects.set("count", o.objects);
    json::Value sizes;
    sizes.set("thresholds_km2", array_of(o.thresholds_km2));
    sizes.set("count_at_least", array_of(o.count_at_least));
    sizes.set("exponent", o.size_exponent);
    sizes.set("fit_low_km2", o.fit_low_km2);
    sizes.set("fit_high_km2", o.fit_high_km2);
    sizes.set("definition", "N(>= a) ~ a^-exponent, least squares in log-log over thresholds with N >= 24");
    objects.set("size_distribution", sizes);
    objects.set("largest_share", o.largest_share);
    objects.set("elongation_median", o.elongation_median);
    objects.set("mid_tone_share", o.mid_tone_share);
    objects.set("edge_value", o.edge_value);
    objects.set("cloudy_mean", o.cloudy_mean);
    objects.set("edge_contrast", o.cloudy_mean > 0 ? o.edge_value / o.cloudy_mean : 0.0);
    root.set("cloud_objects", objects);
  }
  json::Value histogram;
  histogram.set("definition",
                "solid-angle fraction: [0] cover = 0 (clear), then 20 bins (k/20, (k+1)/20] for k = 0..19");
  histogram.set("fractions", array_of(s.histogram));
  root.set("histogram", histogram);
  // The fold figures of the warp, as generate measured them.
  const json::Value* result = s.sidecar.find("result");
  const json::Value* numerics = result && result->is_object() ? result->find("numerics") : nullptr;
  const json::Value* folding = numerics && numerics->is_object() ? numerics->find("folding") : nullptr;
  root.set("folding", folding ? *folding : json::Value());
  if (const json::Value* fraction = result && result->is_object() ? result->find("cloud_fraction") : nullptr)
    root.set("cloud_fraction", *fraction);
  return root;
}

namespace {

// A small raster plot: lines, markers and frames in an RGB image, labels through files::draw_text.
struct Canvas {
  core::ImageData image;
  Canvas(int width, int height) : image{width, height, 3, std::vector<float>(size_t(width) * height * 3, 1.0f)} {}
  void dot(int x, int y, const float rgb[3]) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    for (int c = 0; c < 3; ++c) image.pixels[(size_t(y) * image.width + x) * 3 + c] = rgb[c];
  }
  void line(double x0, double y0, double x1, double y1, const float rgb[3], int thickness = 1) {
    const int steps = static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))) + 1;
    for (int s = 0; s <= steps; ++s) {
      const double x = x0 + (x1 - x0) * s / steps, y = y0 + (y1 - y0) * s / steps;
      for (int a = 0; a < thickness; ++a)
        for (int b = 0; b < thickness; ++b)
          dot(static_cast<int>(std::lround(x)) + a - thickness / 2,
              static_cast<int>(std::lround(y)) + b - thickness / 2, rgb);
    }
  }
  void square(double x, double y, int half, const float rgb[3]) {
    for (int a = -half; a <= half; ++a)
      for (int b = -half; b <= half; ++b)
        dot(static_cast<int>(std::lround(x)) + a, static_cast<int>(std::lround(y)) + b, rgb);
  }
  void text(double x, double y, const std::string& t, int size = 14) {
    const float black[3] = {0, 0, 0};
    files::draw_text(image, static_cast<int>(x), static_cast<int>(y), t, size, black);
  }
};

// A linear or log10 panel of the canvas: data to pixel coordinates.
struct Panel {
  double left, top, width, height, x0, x1, y0, y1;
  double px(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double py(double y) const { return top + height - (y - y0) / (y1 - y0) * height; }
  void frame(Canvas& c) const {
    const float grey[3] = {0.2f, 0.2f, 0.2f};
    c.line(left, top, left + width, top, grey);
    c.line(left, top + height, left + width, top + height, grey);
    c.line(left, top, left, top + height, grey);
    c.line(left + width, top, left + width, top + height, grey);
  }
  void grid_x(Canvas& c, double x, const std::string& label) const {
    const float light[3] = {0.85f, 0.85f, 0.85f};
    c.line(px(x), top, px(x), top + height, light);
    c.text(px(x) - 10, top + height + 18, label, 13);
  }
  void grid_y(Canvas& c, double y, const std::string& label) const {
    const float light[3] = {0.85f, 0.85f, 0.85f};
    c.line(left, py(y), left + width, py(y), light);
    c.text(left - 44, py(y) + 5, label, 13);
  }
};

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::vector<unsigned char> plot_png(const CoverStatistics& s) {
  Canvas canvas(1200, 520);
  const float blue[3] = {0.12f, 0.47f, 0.71f}, red[3] = {0.84f, 0.15f, 0.16f}, black[3] = {0.1f, 0.1f, 0.1f};
  const Panel cover_panel{70, 50, 480, 380, -90, 90, 0, 1};
  for (int lat = -90; lat <= 90; lat += 30) cover_panel.grid_x(canvas, lat, std::to_string(lat));
  for (int k = 0; k <= 5; ++k) cover_panel.grid_y(canvas, k * 0.2, fixed(k * 0.2, 1));
  cover_panel.frame(canvas);
  auto curve = [&](const Panel& p, const std::vector<double>& values, double band_deg, const float rgb[3]) {
    for (size_t b = 0; b + 1 < values.size(); ++b) {
      const double x = -90.0 + band_deg * (b + 0.5);
      canvas.line(p.px(x), p.py(values[b]), p.px(x + band_deg), p.py(values[b + 1]), rgb, 2);
    }
  };
  if (!s.target_2deg.empty()) curve(cover_panel, s.target_2deg, 2.0, black);
  curve(cover_panel, s.coverage_2deg, 2.0, blue);
  for (size_t b = 0; b < s.coverage_10deg.size(); ++b)
    canvas.square(cover_panel.px(-85.0 + 10.0 * b), cover_panel.py(s.coverage_10deg[b]), 3, red);
  canvas.text(70, 30, "Coverage by latitude (" + s.coverage_source + "): 2-deg bands blue, 10-deg red, target black",
              15);
  canvas.text(250, 472, "geocentric latitude (degrees)", 14);

  if (!s.spectrum.empty()) {
    double low = INFINITY, high = -INFINITY;
    for (double p : s.spectrum)
      if (p > 0.0) low = std::min(low, std::log10(p)), high = std::max(high, std::log10(p));
    if (!(high > low)) low = -1, high = 0;
    const Panel spectrum_panel{
        680, 50, 480, 380, 0.0, std::log10(double(s.spectrum.size())), std::floor(low), std::ceil(high)};
    for (int d = 0; d <= static_cast<int>(spectrum_panel.x1); ++d)
      spectrum_panel.grid_x(canvas, d, "1e" + std::to_string(d));
    for (int d = static_cast<int>(spectrum_panel.y0); d <= static_cast<int>(spectrum_panel.y1); d += 2)
      spectrum_panel.grid_y(canvas, d, "1e" + std::to_string(d));
    spectrum_panel.frame(canvas);
    for (size_t k = 1; k < s.spectrum.size(); ++k)
      if (s.spectrum[k - 1] > 0.0 && s.spectrum[k] > 0.0)
        canvas.line(spectrum_panel.px(std::log10(double(k))), spectrum_panel.py(std::log10(s.spectrum[k - 1])),
                    spectrum_panel.px(std::log10(double(k + 1))), spectrum_panel.py(std::log10(s.spectrum[k])), blue);
    if (std::isfinite(s.spectrum_fit.slope)) {
      // The fit's segment over its range, cut where it leaves the panel.
      double a = std::log10(s.fit_k_low), b = std::log10(s.fit_k_high);
      const auto x_at = [&](double y) { return (y - s.spectrum_fit.intercept) / s.spectrum_fit.slope; };
      if (s.spectrum_fit.slope < 0.0) {
        a = std::max(a, x_at(spectrum_panel.y1));
        b = std::min(b, x_at(spectrum_panel.y0));
      } else if (s.spectrum_fit.slope > 0.0) {
        a = std::max(a, x_at(spectrum_panel.y0));
        b = std::min(b, x_at(spectrum_panel.y1));
      }
      canvas.line(spectrum_panel.px(a), spectrum_panel.py(s.spectrum_fit.intercept + s.spectrum_fit.slope * a),
                  spectrum_panel.px(b), spectrum_panel.py(s.spectrum_fit.intercept + s.spectrum_fit.slope * b), red, 2);
    }
    canvas.text(680, 30,
                "Zonal power spectrum, |lat| <= 60: slope " + fixed(s.spectrum_fit.slope, 2) + " (red fit, k " +
                    fixed(s.fit_k_low, 0) + "-" + fixed(s.fit_k_high, 0) + ")",
                15);
    canvas.text(830, 472, "zonal wavenumber k (cycles per circle)", 14);
    canvas.text(680, 505,
                "perimeter dimension D = " + fixed(s.perimeter.dimension, 3) + " (" +
                    std::to_string(s.perimeter.objects) + " objects >= 10 px)",
                15);
  }
  return files::encode_image(canvas.image, files::png_encoding(8), "stats.png");
}

}  // namespace

void write_statistics(files::OutputSet& outputs, const CoverStatistics& stats) {
  outputs.write("stats.json", json::write(statistics_json(stats)));
  outputs.write("stats.png", plot_png(stats));
  outputs.commit();
}

}  // namespace nephele::studies
