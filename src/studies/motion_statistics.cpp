#include "studies/motion_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/json.hpp"
#include "core/time.hpp"
#include "cover/cover_parameters.hpp"
#include "cover/moving_flow.hpp"
#include "files/image_files.hpp"
#include "shader_math/shader_math.hpp"
#include "studies/svg_plot.hpp"

namespace nephele::studies {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEarthRadius = 6371000.0;  // m, as flow_hours_per_unit

json::Value read_json(const std::filesystem::path& path, const std::string& what) {
  try {
    return json::parse(core::read_input_file(path.string()));
  } catch (const std::exception& e) {
    throw core::InputError(path.string(), "", what, std::string("cannot be read: ") + e.what());
  }
}

// The cover's parameters from a frame's cover.json: the numeric ones by the table's sidecar
// paths (as io/cover_files.cpp writes them), the flow and its time by name.
cover::CoverParameters parameters_of(const json::Value& sidecar, const std::filesystem::path& path) {
  cover::CoverParameters p;
  const json::Value* parameters = sidecar.find("parameters");
  if (!parameters || !parameters->is_object())
    throw core::InputError(path.string() + ": parameters", "", "an object", "is missing");
  cover::visit_numeric_parameters(p, [&](const params::Parameter& parameter, auto& field) {
    const json::Value* value = parameters;
    std::stringstream keys{std::string(parameter.sidecar_path())};
    for (std::string key; value && std::getline(keys, key, '.');)
      value = value->is_object() ? value->find(key) : nullptr;
    if (value && value->is_number()) field = static_cast<std::decay_t<decltype(field)>>(value->as_number());
  });
  const json::Value* flow = parameters->find("flow");
  const json::Value* time = parameters->find("time");
  if (!flow || !flow->is_string() || flow->as_string() != "moving" || !time || !time->is_string())
    throw core::InputError(path.string() + ": parameters.flow", flow && flow->is_string() ? flow->as_string() : "",
                           "moving, with parameters.time", "is not a moving cover");
  p.flow = cover::Flow::moving;
  p.time = time->as_string();
  return p;
}

// The flow's zonal-mean eastward wind (m/s) at `latitude_deg` and time `hours` (the procedural
// flow: what the frames' splines approximate), over 720 longitudes.
double zonal_wind(const cover::CoverParameters& p, double latitude_deg, double hours) {
  const cover::FrameClock clock = cover::frame_clock(p, hours);
  const glsl::CurlParams curl = cover::curl_params(p);
  const glsl::vec3 offset = cover::potential_offset(p);
  const double lat = latitude_deg * kPi / 180.0;
  double sum = 0;
  const int samples = 720;
  for (int i = 0; i < samples; ++i) {
    const double lon = 2 * kPi * (i + 0.5) / samples;
    const glsl::vec3 n(float(std::cos(lat) * std::cos(lon)), float(std::cos(lat) * std::sin(lon)),
                       float(std::sin(lat)));
    const glsl::vec3 east(float(-std::sin(lon)), float(std::cos(lon)), 0.0f);
    const glsl::vec4 v = glsl::moving_curl_flow(n, curl, offset, clock.motion, clock.time);
    sum += glsl::dot(glsl::vec3(v), east);
  }
  // Radians per flow unit to metres per second.
  return sum / samples * kEarthRadius / (cover::flow_hours_per_unit * 3600.0);
}

// The shift (pixels, eastward, sub-pixel by a parabola through the peak) of `b` against `a`
// along rows [row0, row1) that maximises their circular cross-correlation.
double best_shift(const core::ImageData& a, const core::ImageData& b, int row0, int row1, int max_shift) {
  const int w = a.width;
  std::vector<double> score(2 * max_shift + 1, 0.0);
  for (int row = row0; row < row1; ++row) {
    const float* pa = &a.pixels[size_t(row) * w * a.channels];
    const float* pb = &b.pixels[size_t(row) * w * b.channels];
    double mean_a = 0, mean_b = 0;
    for (int x = 0; x < w; ++x) {
      mean_a += pa[x * a.channels];
      mean_b += pb[x * b.channels];
    }
    mean_a /= w;
    mean_b /= w;
    for (int s = -max_shift; s <= max_shift; ++s) {
      double c = 0;
      for (int x = 0; x < w; ++x)
        c += (pa[x * a.channels] - mean_a) * (pb[((x + s) % w + w) % w * b.channels] - mean_b);
      score[s + max_shift] += c;
    }
  }
  const int best = int(std::max_element(score.begin(), score.end()) - score.begin());
  double shift = best - max_shift;
  if (best > 0 && best < 2 * max_shift) {
    const double l = score[best - 1], c = score[best], r = score[best + 1];
    const double curvature = l - 2 * c + r;
    if (curvature < 0) shift += 0.5 * (l - r) / curvature;
  }
  return shift;
}

// Solid-angle weighted correlation of two equirect maps between 60 S and 60 N; `shift(row)`
// (pixels eastward, fractional: linear between the two nearest) moves b's row back before the
// comparison, so that a pattern carried that far east between a and b is compared with itself.
template <class Shift>
double correlation(const core::ImageData& a, const core::ImageData& b, Shift&& shift) {
  double sw = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
  for (int row = 0; row < a.height; ++row) {
    const double lat = 90.0 - 180.0 * (row + 0.5) / a.height;
    if (std::abs(lat) > 60) continue;
    const double weight = std::cos(lat * kPi / 180.0);
    const double s = shift(row);
    const double whole = std::floor(s), part = s - whole;
    for (int x = 0; x < a.width; ++x) {
      const double u = a.pixels[(size_t(row) * a.width + x) * a.channels];
      const auto at = [&](long column) {
        const long wrapped = ((column % a.width) + a.width) % a.width;
        return double(b.pixels[(size_t(row) * b.width + size_t(wrapped)) * b.channels]);
      };
      const long base = x + long(whole);
      const double v = part == 0.0 ? at(base) : (1.0 - part) * at(base) + part * at(base + 1);
      sw += weight;
      sa += weight * u;
      sb += weight * v;
      saa += weight * u * u;
      sbb += weight * v * v;
      sab += weight * u * v;
    }
  }
  const double ma = sa / sw, mb = sb / sw;
  const double va = saa / sw - ma * ma, vb = sbb / sw - mb * mb;
  return va > 0 && vb > 0 ? (sab / sw - ma * mb) / std::sqrt(va * vb) : 0.0;
}

}  // namespace

MotionStatistics motion_statistics(const std::filesystem::path& sequence_dir) {
  const std::filesystem::path listing_path = sequence_dir / "sequence.json";
  const json::Value listing = read_json(listing_path, "the sequence.json of nephele generate --sequence");
  const json::Value* frames = listing.find("frames");
  const json::Value* interval = listing.find("interval_hours");
  if (!frames || !frames->is_array() || frames->as_array().size() < 2 || !interval || !interval->is_number() ||
      !(interval->as_number() > 0))
    throw core::InputError(listing_path.string() + ": frames", "", "two frames or more and interval_hours > 0",
                           "are missing");
  MotionStatistics m;
  m.frames = int(frames->as_array().size());
  m.interval_hours = interval->as_number();
  std::vector<core::ImageData> maps;
  std::vector<double> fractions;
  cover::CoverParameters first;
  for (int k = 0; k < m.frames; ++k) {
    const json::Value& frame = frames->as_array()[size_t(k)];
    const json::Value* folder = frame.find("folder");
    if (!folder || !folder->is_string())
      throw core::InputError(listing_path.string() + ": frames[" + std::to_string(k) + "].folder", "", "a frame folder",
                             "is missing");
    const std::filesystem::path dir = sequence_dir / folder->as_string();
    if (k == 0) first = parameters_of(read_json(dir / "cover.json", "a frame's cover.json"), dir / "cover.json");
    const std::filesystem::path map = dir / "cover_equirect.exr";
    if (!std::filesystem::exists(map))
      throw core::InputError(map.string(), "", "the frame's equirect map (generate --files with equirect)",
                             "is missing");
    maps.push_back(files::read_image(map));
    if (maps.back().width != maps.front().width || maps.back().height != maps.front().height)
      throw core::InputError(map.string(), "", "the size of the first frame's map", "differs");
    const json::Value* fraction = frame.find("cloud_fraction");
    if (fraction && fraction->is_number()) fractions.push_back(fraction->as_number());
  }
  const core::ImageData& shape = maps.front();
  m.equirect_width = shape.width;
  const double start_hours = cover::hours_since_epoch(first.time);
  const double seconds = m.interval_hours * 3600.0;
  // Shifts up to 60 m/s at the equator between frames, at least 4 pixels.
  const int max_shift = std::max(4, int(std::ceil(60.0 * seconds / (2 * kPi * kEarthRadius) * shape.width)));
  for (int band = 0; band < 12; ++band) {
    const double centre = -55.0 + 10.0 * band;
    const int row0 = int(std::lround((90.0 - (centre + 5.0)) / 180.0 * shape.height));
    const int row1 = int(std::lround((90.0 - (centre - 5.0)) / 180.0 * shape.height));
    double shift = 0;
    for (int k = 0; k + 1 < m.frames; ++k)
      shift += best_shift(maps[size_t(k)], maps[size_t(k) + 1], row0, row1, max_shift);
    shift /= m.frames - 1;
    m.band_centres_deg.push_back(centre);
    m.cloud_speed_ms.push_back(shift * 2 * kPi / shape.width * kEarthRadius * std::cos(centre * kPi / 180.0) / seconds);
    // The flow's wind, averaged over the sequence's first, middle and last frame times.
    double wind = 0;
    for (int k : {0, (m.frames - 1) / 2, m.frames - 1})
      wind += zonal_wind(first, centre, start_hours + k * m.interval_hours);
    m.flow_speed_ms.push_back(wind / 3);
  }
  // The rows' shift per interval: that of the band the row lies in (pixels eastward).
  std::vector<double> shift_per_interval(size_t(shape.height), 0.0);
  for (int row = 0; row < shape.height; ++row) {
    const double lat = 90.0 - 180.0 * (row + 0.5) / shape.height;
    const int band = std::clamp(int(std::floor((lat + 60.0) / 10.0)), 0, 11);
    shift_per_interval[size_t(row)] = m.cloud_speed_ms[size_t(band)] * seconds /
                                      (kEarthRadius * std::cos(lat * kPi / 180.0)) * shape.width / (2 * kPi);
  }
  for (int lag = 0; lag < m.frames; ++lag) {
    double fixed = 0, moving = 0;
    for (int k = 0; k + lag < m.frames; ++k) {
      fixed += correlation(maps[size_t(k)], maps[size_t(k + lag)], [](int) { return 0.0; });
      moving += correlation(maps[size_t(k)], maps[size_t(k + lag)],
                            [&](int row) { return shift_per_interval[size_t(row)] * lag; });
    }
    m.correlation_by_lag.push_back(fixed / (m.frames - lag));
    m.comoving_correlation_by_lag.push_back(moving / (m.frames - lag));
  }
  const auto falls_below = [&](const std::vector<double>& c) {
    const double threshold = std::exp(-1.0);
    for (int lag = 1; lag < m.frames; ++lag)
      if (c[size_t(lag)] < threshold) {
        const double a = c[size_t(lag) - 1], b = c[size_t(lag)];
        return (lag - 1 + (a - threshold) / (a - b)) * m.interval_hours;
      }
    return 0.0;
  };
  m.decorrelation_hours = falls_below(m.correlation_by_lag);
  m.comoving_decorrelation_hours = falls_below(m.comoving_correlation_by_lag);
  if (!fractions.empty()) {
    double sum = 0;
    for (double f : fractions) sum += f;
    m.cloud_fraction_mean = sum / double(fractions.size());
    m.cloud_fraction_range =
        *std::max_element(fractions.begin(), fractions.end()) - *std::min_element(fractions.begin(), fractions.end());
  }
  return m;
}

void write_motion(files::OutputSet& outputs, const MotionStatistics& m) {
  json::Value out;
  out.set("frames", m.frames);
  out.set("interval_hours", m.interval_hours);
  json::Value::Array bands;
  for (size_t b = 0; b < m.band_centres_deg.size(); ++b) {
    json::Value band;
    band.set("latitude_deg", m.band_centres_deg[b]);
    band.set("cloud_speed_ms", m.cloud_speed_ms[b]);
    band.set("flow_speed_ms", m.flow_speed_ms[b]);
    bands.push_back(std::move(band));
  }
  out.set("zonal_speed_by_band", std::move(bands));
  json::Value::Array correlation;
  for (double c : m.correlation_by_lag) correlation.emplace_back(c);
  out.set("correlation_by_lag", std::move(correlation));
  out.set("decorrelation_hours", m.decorrelation_hours);
  json::Value::Array comoving;
  for (double c : m.comoving_correlation_by_lag) comoving.emplace_back(c);
  out.set("comoving_correlation_by_lag", std::move(comoving));
  out.set("comoving_decorrelation_hours", m.comoving_decorrelation_hours);
  out.set("cloud_fraction_mean", m.cloud_fraction_mean);
  out.set("cloud_fraction_range", m.cloud_fraction_range);
  outputs.write("motion.json", json::write(out));

  // Two linear panels: eastward speed by latitude (clouds: dots, flow: line) and correlation by lag.
  std::ostringstream s;
  begin_document(s, 1100, 460, "Motion of the moving cover: zonal speed by band and decorrelation");
  const auto panel = [&](double x0, double xmin, double xmax, double ymin, double ymax, const std::string& xl,
                         const std::string& yl) {
    const double w = 460, h = 340, y0 = 50;
    s << "<rect x='" << x0 << "' y='" << y0 << "' width='" << w << "' height='" << h
      << "' fill='none' stroke='black'/>\n";
    for (int i = 0; i <= 4; ++i) {
      const double xv = xmin + (xmax - xmin) * i / 4, yv = ymin + (ymax - ymin) * i / 4;
      s << "<text x='" << x0 + w * i / 4 << "' y='" << y0 + h + 18 << "' font-size='12' text-anchor='middle'>" << xv
        << "</text>\n<text x='" << x0 - 6 << "' y='" << y0 + h - h * i / 4 + 4 << "' font-size='12' text-anchor='end'>"
        << yv << "</text>\n";
    }
    s << "<text x='" << x0 + w / 2 << "' y='" << y0 + h + 38 << "' font-size='13' text-anchor='middle'>" << escape(xl)
      << "</text>\n<text x='" << x0 - 45 << "' y='" << y0 + h / 2
      << "' font-size='13' text-anchor='middle' transform='rotate(-90 " << x0 - 45 << " " << y0 + h / 2 << ")'>"
      << escape(yl) << "</text>\n";
    return [=](double xv, double yv) {
      return std::make_pair(x0 + w * (xv - xmin) / (xmax - xmin), y0 + h - h * (yv - ymin) / (ymax - ymin));
    };
  };
  double low = -5, high = 5;
  for (size_t b = 0; b < m.band_centres_deg.size(); ++b) {
    low = std::min({low, m.cloud_speed_ms[b], m.flow_speed_ms[b]});
    high = std::max({high, m.cloud_speed_ms[b], m.flow_speed_ms[b]});
  }
  low = std::floor(low / 5) * 5;
  high = std::ceil(high / 5) * 5;
  const auto speed = panel(80, -60, 60, low, high, "latitude (degrees)", "eastward speed (m/s)");
  std::vector<std::pair<double, double>> flow;
  for (size_t b = 0; b < m.band_centres_deg.size(); ++b) {
    flow.push_back(speed(m.band_centres_deg[b], m.flow_speed_ms[b]));
    const auto p = speed(m.band_centres_deg[b], m.cloud_speed_ms[b]);
    marker(s, 0, p.first, p.second, "#c03020");
  }
  polyline(s, flow, "#2060c0");
  legend_line(s, 100, 70, "#2060c0", "the flow's zonal-mean wind");
  marker(s, 0, 108, 90, "#c03020");
  s << "<text x='124' y='94' font-size='12'>clouds (cross-correlation of frames)</text>\n";
  const double max_lag = m.interval_hours * (m.frames - 1);
  const auto corr = panel(620, 0, max_lag, 0, 1, "lag (hours)", "correlation of the cover");
  std::vector<std::pair<double, double>> line;
  for (size_t k = 0; k < m.correlation_by_lag.size(); ++k)
    line.push_back(corr(m.interval_hours * double(k), m.correlation_by_lag[k]));
  polyline(s, line, "#c03020");
  std::vector<std::pair<double, double>> comoving_line;
  for (size_t k = 0; k < m.comoving_correlation_by_lag.size(); ++k)
    comoving_line.push_back(corr(m.interval_hours * double(k), m.comoving_correlation_by_lag[k]));
  polyline(s, comoving_line, "#2060c0");
  polyline(s, {corr(0, std::exp(-1.0)), corr(max_lag, std::exp(-1.0))}, "#808080", true);
  legend_line(s, 840, 70, "#c03020", "at a fixed place");
  legend_line(s, 840, 90, "#2060c0", "moving with the band's clouds");
  end_document(s);
  outputs.write("motion.svg", s.str());
  outputs.commit();
}

}  // namespace nephele::studies
