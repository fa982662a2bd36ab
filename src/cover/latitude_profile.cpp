#include "cover/latitude_profile.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/common.hpp>

namespace nephele::cover {
namespace {

constexpr double degree = M_PI / 180.0;

// Fritsch and Carlson (1980), "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal.
// 17(2): slopes from the mean of neighbouring secants, 0 at local extrema, scaled back onto the
// circle of radius 3 where they would overshoot.
std::vector<double> monotone_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const size_t n = x.size();
  std::vector<double> m(n, 0.0);
  if (n < 2) return m;
  std::vector<double> secant(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) secant[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  m[0] = secant[0];
  m[n - 1] = secant[n - 2];
  for (size_t i = 1; i + 1 < n; ++i) m[i] = secant[i - 1] * secant[i] <= 0.0 ? 0.0 : 0.5 * (secant[i - 1] + secant[i]);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (secant[i] == 0.0) {
      m[i] = m[i + 1] = 0.0;
      continue;
    }
    const double a = m[i] / secant[i], b = m[i + 1] / secant[i];
    const double r = a * a + b * b;
    if (r > 9.0) {
      const double t = 3.0 / std::sqrt(r);
      m[i] = t * a * secant[i];
      m[i + 1] = t * b * secant[i];
    }
  }
  return m;
}

}  // namespace

LatitudeProfile earth_profile() {
  // Zonal-mean total cloud fraction, annual mean, read from the ranges of King et al. (2013,
  // MODIS) and Stubenrauch et al. (2013, GEWEX cloud assessment) as docs/climate.md lists them:
  // ITCZ maximum 0.72 at 7 N, subtropical minima 0.55 (22 S) and 0.54 (25 N), storm tracks
  // 0.86 at 60 S and 0.77 at 58 N, poles 0.62-0.63. Area-weighted mean 0.668 (rescaled to
  // --coverage by band_targets).
  LatitudeProfile p;
  p.kind = LatitudeProfile::Kind::earth;
  p.name = "earth";
  p.latitude_deg = {-90, -80, -70, -60, -50, -40, -30, -22, -12, 0, 7, 15, 25, 35, 45, 58, 70, 80, 90};
  p.fraction = {0.62, 0.65, 0.77, 0.86, 0.82, 0.72, 0.60, 0.55, 0.62, 0.66,
                0.72, 0.63, 0.54, 0.60, 0.69, 0.77, 0.73, 0.67, 0.63};
  return p;
}

LatitudeProfile flat_profile() {
  LatitudeProfile p;
  p.kind = LatitudeProfile::Kind::flat;
  p.name = "flat";
  p.latitude_deg = {-90, 90};
  p.fraction = {1, 1};
  return p;
}

LatitudeProfile table_profile(std::string name, std::vector<double> latitude_deg, std::vector<double> fraction) {
  if (latitude_deg.empty() || latitude_deg.size() != fraction.size())
    throw std::invalid_argument("table_profile: no knots, or latitudes and fractions differ in number");
  LatitudeProfile p;
  p.kind = LatitudeProfile::Kind::table;
  p.name = std::move(name);
  p.latitude_deg = std::move(latitude_deg);
  p.fraction = std::move(fraction);
  return p;
}

double profile_fraction(const LatitudeProfile& profile, double latitude_deg) {
  const std::vector<double>& x = profile.latitude_deg;
  const std::vector<double>& y = profile.fraction;
  if (x.size() == 1 || latitude_deg <= x.front()) return y.front();
  if (latitude_deg >= x.back()) return y.back();
  // The slopes are recomputed per call: profiles have a few dozen knots and are evaluated a
  // few thousand times per cover.
  const std::vector<double> m = monotone_slopes(x, y);
  const size_t i = static_cast<size_t>(std::upper_bound(x.begin(), x.end(), latitude_deg) - x.begin()) - 1;
  const double h = x[i + 1] - x[i], t = (latitude_deg - x[i]) / h;
  const double t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * y[i] + (t3 - 2 * t2 + t) * h * m[i] + (-2 * t3 + 3 * t2) * y[i + 1] +
         (t3 - t2) * h * m[i + 1];
}

double seasonal_phase(int month) {
  if (month == 0) return 0.0;
  // Northernmost in August, southernmost in February (mid-month phases; docs/climate.md).
  return std::cos(2.0 * M_PI * (month - 8) / 12.0);
}

double seasonal_shift_deg(double latitude_deg, int month) {
  if (month == 0) return 0.0;
  const double season = seasonal_phase(month);
  const double itcz = 5.0, storm_tracks = 3.0;  // amplitudes in degrees (docs/climate.md)
  const double tropical = std::exp(-(latitude_deg / 20.0) * (latitude_deg / 20.0));
  const double amplitude = storm_tracks + (itcz - storm_tracks) * tropical;
  // 0 at the poles, so that the shifted profile still spans -90..90; the slope of the shift
  // stays below 0.3, so latitude - shift is monotone.
  return season * amplitude * glm::smoothstep(0.0, 20.0, 90.0 - std::abs(latitude_deg));
}

double storm_track_shift(int month) {
  if (month == 0) return 0.0;  // exactly the annual mean's envelope
  const double track = 50.0;   // curl_flow.glsl's storm_track_envelope
  return std::sin((track + seasonal_shift_deg(track, month)) * degree) - std::sin(track * degree);
}

std::vector<double> band_areas(int bands) {
  std::vector<double> areas(static_cast<size_t>(bands));
  for (int b = 0; b < bands; ++b) {
    const double bottom = -90.0 + 180.0 * b / bands, top = -90.0 + 180.0 * (b + 1) / bands;
    areas[b] = 0.5 * (std::sin(top * degree) - std::sin(bottom * degree));
  }
  return areas;
}

std::vector<double> band_targets(const LatitudeProfile& profile, int month, double coverage, int bands) {
  const std::vector<double> areas = band_areas(bands);
  std::vector<double> targets(static_cast<size_t>(bands));
  // Composite Simpson rule on the band (32 intervals) for the integral of f cos(lat); the
  // profile is C1 and piecewise cubic, so the rule errs by far less than 1e-6.
  constexpr int intervals = 32;
  double mean = 0.0;
  for (int b = 0; b < bands; ++b) {
    const double bottom = -90.0 + 180.0 * b / bands, width = 180.0 / bands;
    double sum = 0.0;
    for (int k = 0; k <= intervals; ++k) {
      const double latitude = bottom + width * k / intervals;
      const double weight = (k == 0 || k == intervals) ? 1.0 : (k % 2 ? 4.0 : 2.0);
      sum += weight * profile_fraction(profile, latitude - seasonal_shift_deg(latitude, month)) *
             std::cos(latitude * degree);
    }
    const double integral = sum * (width * degree) / (3.0 * intervals);  // of f cos(lat) d lat
    targets[b] = std::clamp(integral / (2.0 * areas[b]), 0.0, 1.0);
    mean += targets[b] * areas[b];
  }
  for (double& t : targets) {
    if (coverage <= mean)
      t = mean > 0.0 ? t * coverage / mean : coverage;
    else
      t = mean < 1.0 ? 1.0 - (1.0 - t) * (1.0 - coverage) / (1.0 - mean) : coverage;
    t = std::clamp(t, 0.0, 1.0);
  }
  return targets;
}

}  // namespace nephele::cover
