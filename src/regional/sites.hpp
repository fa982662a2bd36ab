#pragma once
// Named places: the viewpoints near Bern and the cities their views run towards.
#include <optional>
#include <string>
#include <vector>

namespace nephele::regional {

struct Site {
  std::string name;
  double latitude_deg, longitude_deg;  // WGS84
  double elevation_m;                  // above sea level (treated as above the ellipsoid)
};

struct Viewpoint {
  std::string name;
  Site site;
  std::string towards;  // the city the default view looks at
  double heading_deg;   // default view heading, clockwise from north
};

// Coordinates from Wikipedia (see docs/layers.md for the sources): Gurten 46.91722 N 7.44361 E
// 858 m; Bantiger summit 46.97916 N 7.52917 E 947 m (from LV03 606888/203126); Bern 46.94806 N
// 7.44750 E 540 m; Solothurn 47.20833 N 7.53722 E 432 m; Fribourg 46.800 N 7.150 E 610 m.
const std::vector<Site>& known_cities();
std::optional<Site> find_city(const std::string& name);
std::optional<Viewpoint> find_viewpoint(const std::string& name);  // "gurten", "bantiger"
std::vector<std::string> viewpoint_names();

// Initial geodesic azimuth (deg clockwise from north) and distance (m) between two sites on
// the WGS84 ellipsoid (GeographicLib::Geodesic).
double geodesic_azimuth_deg(const Site& from, const Site& to);
double geodesic_distance_m(double lat1, double lon1, double lat2, double lon2);

}  // namespace nephele::regional
