#include "regional/sites.hpp"

#include <GeographicLib/Geodesic.hpp>

namespace nephele::regional {

const std::vector<Site>& known_cities() {
  static const std::vector<Site> cities = {
      {"bern", 46.94806, 7.44750, 540.0},
      {"solothurn", 47.20833, 7.53722, 432.0},
      {"fribourg", 46.800, 7.150, 610.0},
  };
  return cities;
}

std::optional<Site> find_city(const std::string& name) {
  for (const auto& c : known_cities())
    if (c.name == name) return c;
  return std::nullopt;
}

double geodesic_azimuth_deg(const Site& from, const Site& to) {
  double distance = 0, azimuth1 = 0, azimuth2 = 0;
  GeographicLib::Geodesic::WGS84().Inverse(from.latitude_deg, from.longitude_deg, to.latitude_deg, to.longitude_deg,
                                           distance, azimuth1, azimuth2);
  return azimuth1 < 0 ? azimuth1 + 360.0 : azimuth1;
}

double geodesic_distance_m(double lat1, double lon1, double lat2, double lon2) {
  double distance = 0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, distance);
  return distance;
}

std::optional<Viewpoint> find_viewpoint(const std::string& name) {
  // The views run from the summit towards the city: Gurten north-north-east to Solothurn,
  // Bantiger south-west to Fribourg; the heading is the geodesic azimuth.
  if (name == "gurten") {
    const Site site{"gurten", 46.91722, 7.44361, 858.0};
    return Viewpoint{name, site, "solothurn", geodesic_azimuth_deg(site, *find_city("solothurn"))};
  }
  if (name == "bantiger") {
    const Site site{"bantiger", 46.97916, 7.52917, 947.0};
    return Viewpoint{name, site, "fribourg", geodesic_azimuth_deg(site, *find_city("fribourg"))};
  }
  return std::nullopt;
}

std::vector<std::string> viewpoint_names() { return {"gurten", "bantiger"}; }

}  // namespace nephele::regional
