#pragma once
// Statistics of a generated cover (nephele stats; docs/climate.md): coverage by latitude band
// against the profile's targets, the zonal power spectrum and its slope, the perimeter fractal
// dimension of cloud objects, the histogram of cover values, and the fold figures of cover.json.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/json.hpp"
#include "files/atomic_output.hpp"

namespace nephele::studies {

// A 2:1 equirect cover map: longitude -180 deg at the left, north up, rows at WGS84 geodetic
// latitudes (docs/conventions.md).
struct Equirect {
  int width = 0, height = 0;
  std::vector<float> values;  // row-major from the north
};

// Geocentric latitude (radians) of a point on the WGS84 ellipsoid at geodetic latitude phi:
// tan(phi_c) = (1 - e^2) tan(phi). The cover is indexed by direction from the centre, the
// equirect's rows by geodetic latitude.
double geocentric_latitude(double geodetic);

// Cloudy fraction (cover > 0) of equal latitude bands, south pole first, weighted by solid
// angle; a texel or pixel counts wholly in the band of its centre's geocentric latitude.
std::vector<double> band_coverage_faces(const std::vector<float>& faces, int size, int bands);
std::vector<double> band_coverage_equirect(const Equirect& map, int bands);

// The zonal 1D power spectrum averaged over the rows whose centre lies within `max_latitude_deg`
// of the equator: P(k) = |X_k|^2 / W^2 of each row's discrete Fourier transform after its mean
// is removed, for zonal wavenumbers k = 1 .. W/2 (cycles around the latitude circle).
std::vector<double> zonal_power_spectrum(const Equirect& map, double max_latitude_deg);

// Least-squares slope of log y against log x over the points with x in [x_low, x_high] and
// y > 0; NaN with fewer than two such points.
struct PowerLaw {
  double slope = 0.0, intercept = 0.0;  // log10 y = intercept + slope log10 x
  int points = 0;
};
PowerLaw fit_power_law(const std::vector<double>& x, const std::vector<double>& y, double x_low, double x_high);

// Connected cloud objects (cover > 0, 4-connected, periodic in longitude) of the rows within
// `max_latitude_deg` of the equator, without those that touch the first or last of these rows
// (cut off there) unless `keep_cut`. Area: pixels; perimeter: pixel edges between the object and
// clear pixels; area_km2: its pixels' areas on a sphere of 6371 km; elongation: the square root
// of the ratio of the principal second moments of area (local east and north km), 1 for a disc.
struct CloudObject {
  long area = 0, perimeter = 0;
  bool cut = false;
  double area_km2 = 0.0, elongation = 1.0;
};
std::vector<CloudObject> cloud_objects(const Equirect& map, double max_latitude_deg, bool keep_cut = false);

// The perimeter-area dimension: P ~ A^(D/2) fitted over the objects of at least `min_area`
// pixels (log P against log A, least squares): D = 2 slope.
struct PerimeterDimension {
  double dimension = 0.0;
  int objects = 0;
  long min_area = 0, max_area = 0;
};
PerimeterDimension perimeter_dimension(const std::vector<CloudObject>& objects, long min_area);

// The measures by which satellite cloud fields are told from noise (docs/climate.md, "Cloud
// objects"), over the rows within `max_latitude_deg` of the equator:
// - objects: the uncut objects (cloud_objects); their areas' complementary cumulative
//   distribution N(>= a) on thresholds ten to a decade from 10 equatorial pixels to 1e6 km2, and
//   its power-law exponent alpha (N ~ a^-alpha) fitted where N >= 24 (DeWitt and Garrett 2024's
//   precaution for counts; satellites: alpha close to 1, DeWitt et al. 2024);
// - largest_share: the largest connected system's area over all cloudy area, cut objects included;
// - elongation_median: of the uncut objects of at least 10 pixels;
// - mid_tone_share: the share of the cloudy area with cover in [0.25, 0.75);
// - edge_value over cloudy_mean: the mean cover of the cloudy pixels that border a clear one,
//   over that of all cloudy pixels: near 1 for sharp-edged clouds, small for soft ones.
struct ObjectStatistics {
  int objects = 0;
  std::vector<double> thresholds_km2;
  std::vector<double> count_at_least;
  PowerLaw size_fit;  // log10 N against log10 a
  double size_exponent = 0.0, fit_low_km2 = 0.0, fit_high_km2 = 0.0;
  double largest_share = 0.0, elongation_median = 1.0, mid_tone_share = 0.0;
  double edge_value = 0.0, cloudy_mean = 0.0;
};
// `objects`: cloud_objects(map, max_latitude_deg, keep_cut = true), labelled once for this and
// perimeter_dimension (which leaves the cut ones out).
ObjectStatistics object_statistics(const Equirect& map, const std::vector<CloudObject>& objects,
                                   double max_latitude_deg);

// The cloud's optical thickness and cloud-top height over the cloudy texels of faces with the tau
// and cloud_top channels (docs/climate.md, "Optical thickness and cloud tops"), weighted by solid
// angle: the shares of ISCCP's classes, thin (tau < 3.6), medium and thick (tau >= 23), low
// (tops below 3.2 km, 680 hPa), middle and high (from 6.5 km, 440 hPa), and the log-normal's
// mean and standard deviation of ln tau.
struct CloudPropertyStatistics {
  bool present = false;  // the faces had the channels
  double thin = 0, medium = 0, thick = 0;
  double log_tau_mean = 0, log_tau_sd = 0;
  double low = 0, middle = 0, high = 0;
  double top_mean_km = 0;
};
CloudPropertyStatistics cloud_property_statistics(const std::vector<float>& cover,
                                                  const std::vector<float>& optical_thickness,
                                                  const std::vector<float>& cloud_top, int size);

// Everything `nephele stats` reports on a cover directory.
struct CoverStatistics {
  std::string coverage_source;  // "faces" or "equirect"
  std::vector<double> coverage_2deg, coverage_10deg;
  std::vector<double> target_2deg, target_10deg;  // from cover.json (empty without a profile)
  std::vector<double> spectrum;                   // k = 1 .. W/2 (empty without an equirect)
  PowerLaw spectrum_fit;
  double fit_k_low = 0, fit_k_high = 0;
  PerimeterDimension perimeter;
  ObjectStatistics objects;            // (without an equirect: zero)
  std::vector<double> histogram;       // [0] clear (cover 0), then 20 bins over (0, 1]
  CloudPropertyStatistics properties;  // from the faces' tau and cloud_top channels
  json::Value sidecar;                 // cover.json
};

// Reads COVER_DIR (cover.json, the faces and/or the equirect EXR) and computes the statistics.
// Throws core::InputError naming the file for a missing directory, a malformed cover.json or
// images of the wrong size.
CoverStatistics cover_statistics(const std::filesystem::path& cover_dir);

json::Value statistics_json(const CoverStatistics& stats);
// stats.json and stats.png (coverage by latitude against the target; the spectrum with its fit).
void write_statistics(files::OutputSet& outputs, const CoverStatistics& stats);

}  // namespace nephele::studies
