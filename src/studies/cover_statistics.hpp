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
// (cut off there). Area: pixels; perimeter: pixel edges between the object and clear pixels.
struct CloudObject {
  long area = 0, perimeter = 0;
};
std::vector<CloudObject> cloud_objects(const Equirect& map, double max_latitude_deg);

// The perimeter-area dimension: P ~ A^(D/2) fitted over the objects of at least `min_area`
// pixels (log P against log A, least squares): D = 2 slope.
struct PerimeterDimension {
  double dimension = 0.0;
  int objects = 0;
  long min_area = 0, max_area = 0;
};
PerimeterDimension perimeter_dimension(const std::vector<CloudObject>& objects, long min_area);

// Everything `nephele stats` reports on a cover directory.
struct CoverStatistics {
  std::string coverage_source;  // "faces" or "equirect"
  std::vector<double> coverage_2deg, coverage_10deg;
  std::vector<double> target_2deg, target_10deg;  // from cover.json (empty without a profile)
  std::vector<double> spectrum;                   // k = 1 .. W/2 (empty without an equirect)
  PowerLaw spectrum_fit;
  double fit_k_low = 0, fit_k_high = 0;
  PerimeterDimension perimeter;
  std::vector<double> histogram;  // [0] clear (cover 0), then 20 bins over (0, 1]
  json::Value sidecar;            // cover.json
};

// Reads COVER_DIR (cover.json, the faces and/or the equirect EXR) and computes the statistics.
// Throws core::InputError naming the file for a missing directory, a malformed cover.json or
// images of the wrong size.
CoverStatistics cover_statistics(const std::filesystem::path& cover_dir);

json::Value statistics_json(const CoverStatistics& stats);
// stats.json and stats.png (coverage by latitude against the target; the spectrum with its fit).
void write_statistics(files::OutputSet& outputs, const CoverStatistics& stats);

}  // namespace nephele::studies
