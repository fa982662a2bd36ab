#pragma once
// The coverage profile by latitude (docs/climate.md): the target cloudy fraction as a smooth
// function of latitude, Earth's zonal-mean climatology by default, a user's table, or flat (one
// threshold for the sphere, as before profiles). Turned into one target per latitude band.
#include <string>
#include <vector>

namespace nephele::cover {

// Bands of the per-latitude calibration: 2 degrees each, south pole first.
constexpr int profile_bands = 90;

struct LatitudeProfile {
  enum class Kind { flat, earth, table };
  Kind kind = Kind::earth;
  std::string name = "earth";        // "earth", "flat", or the CSV file as given
  std::vector<double> latitude_deg;  // knots, strictly increasing, within [-90, 90]
  std::vector<double> fraction;      // target fraction at each knot, in [0, 1]
};

// Earth's annual-mean zonal cloud fraction (knots from the climatology in docs/climate.md,
// area-weighted mean 0.67).
LatitudeProfile earth_profile();
LatitudeProfile flat_profile();
// A profile from knots (a CSV's rows, already checked): fractions between knots by the
// monotone cubic, constant beyond the first and last knot.
LatitudeProfile table_profile(std::string name, std::vector<double> latitude_deg, std::vector<double> fraction);

// The profile's fraction at a latitude: Fritsch-Carlson monotone cubic Hermite interpolation
// through the knots (C1, no overshoot: the value stays between neighbouring knots, so within
// [0, 1]); constant beyond the end knots.
double profile_fraction(const LatitudeProfile& profile, double latitude_deg);

// The season's phase in a month (1 = January .. 12; 0 = the annual mean): cos(2 pi (m - 8) / 12),
// 1 in August and -1 in February, and 0 for the annual mean; the profile's shift and the ITCZ's
// monsoons (cover/weather_systems.hpp) follow it.
double seasonal_phase(int month);
// The seasonal shift (degrees, northward > 0) of the profile's features at a latitude in a
// month (1 = January .. 12; 0 = the annual mean, no shift): the ITCZ by up to 5 degrees, the
// storm tracks by up to 3, northernmost in August, tapered to 0 at the poles.
double seasonal_shift_deg(double latitude_deg, int month);
// The flow's storm-track envelope follows the same season: CurlParams::storm_track_shift, the
// s of A(z - s), puts the northern track at 50 degrees + seasonal_shift_deg(50, month) (the
// southern moves north by about as much). 0 for month 0.
double storm_track_shift(int month);

// The target of each of `bands` bands (south pole first): the area-weighted (cos latitude)
// mean of the shifted profile over the band, rescaled so that the area-weighted mean over the
// sphere is `coverage` (docs/climate.md: multiplied by coverage / m when coverage <= m, else
// 1 - (1 - f)(1 - coverage)/(1 - m), m the profile's own mean; both keep [0, 1] and the shape).
std::vector<double> band_targets(const LatitudeProfile& profile, int month, double coverage, int bands = profile_bands);

// Each band's share of the sphere: (sin(top) - sin(bottom)) / 2.
std::vector<double> band_areas(int bands = profile_bands);

}  // namespace nephele::cover
