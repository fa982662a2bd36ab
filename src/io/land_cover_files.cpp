#include "io/land_cover_files.hpp"

#include <cmath>
#include <filesystem>
#include <map>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/json.hpp"
#include "io/river_files.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::io {
namespace {

// swiss-maps' lakes.dbf: the Federal Statistical Office's lake numbers and names; the mean
// surface elevations (m above sea level) are the lakes' usual figures (docs/terrain.md).
struct Lake {
  const char* name;
  double surface_m;
};
const std::map<int, Lake>& lakes() {
  static const std::map<int, Lake> table = {
      {9040, {"Greifensee", 435}},          {9050, {"Zuerichsee", 406}},
      {9073, {"Thunersee", 558}},           {9089, {"Brienzersee", 564}},
      {9148, {"Bielersee", 429}},           {9151, {"Lac de Neuchatel", 429}},
      {9157, {"Baldeggersee", 463}},        {9163, {"Sempachersee", 504}},
      {9172, {"Hallwilersee", 449}},        {9175, {"Zugersee", 413}},
      {9179, {"Vierwaldstaettersee", 434}}, {9216, {"Sihlsee", 889}},
      {9239, {"Sarnersee", 469}},           {9267, {"Walensee", 419}},
      {9270, {"Aegerisee", 724}},           {9276, {"Lac de la Gruyere", 677}},
      {9294, {"Murtensee", 429}},           {9326, {"Bodensee", 395}},
      {9709, {"Lago di Lugano", 271}},      {9712, {"Lago Maggiore", 193}},
      {9751, {"Lac de Joux", 1004}},        {9757, {"Lac Leman", 372}},
  };
  return table;
}

struct Topology {
  std::vector<std::vector<regional::GeoPoint>> arcs;  // decoded, in degrees

  // A ring from arc indices: ~k (negative) is arc k reversed; consecutive arcs share their
  // end points, so each arc after the first drops its first point.
  std::vector<regional::GeoPoint> ring(const json::Value& indices) const {
    std::vector<regional::GeoPoint> out;
    for (const json::Value& value : indices.as_array()) {
      const long k = static_cast<long>(value.as_number());
      const long arc = k >= 0 ? k : ~k;
      if (arc < 0 || arc >= static_cast<long>(arcs.size())) throw std::out_of_range("arc index " + std::to_string(k));
      std::vector<regional::GeoPoint> points = arcs[static_cast<size_t>(arc)];
      if (k < 0) std::reverse(points.begin(), points.end());
      out.insert(out.end(), points.begin() + (out.empty() ? 0 : 1), points.end());
    }
    return out;
  }

  // A Polygon's or MultiPolygon's rings, all together (the even-odd rule needs no nesting).
  std::vector<std::vector<regional::GeoPoint>> rings(const json::Value& geometry) const {
    std::vector<std::vector<regional::GeoPoint>> out;
    const std::string& type = geometry.at("type").as_string();
    const json::Value& arcs_of = geometry.at("arcs");
    if (type == "Polygon") {
      for (const json::Value& r : arcs_of.as_array()) out.push_back(ring(r));
    } else if (type == "MultiPolygon") {
      for (const json::Value& polygon : arcs_of.as_array())
        for (const json::Value& r : polygon.as_array()) out.push_back(ring(r));
    } else {
      throw std::out_of_range("geometry type " + type + " (allowed: Polygon, MultiPolygon)");
    }
    return out;
  }
};

Topology decode_arcs(const json::Value& root) {
  Topology topology;
  const json::Value& transform = root.at("transform");
  const auto& scale = transform.at("scale").as_array();
  const auto& translate = transform.at("translate").as_array();
  const double sx = scale.at(0).as_number(), sy = scale.at(1).as_number();
  const double tx = translate.at(0).as_number(), ty = translate.at(1).as_number();
  for (const json::Value& arc : root.at("arcs").as_array()) {
    // Quantised positions, each a delta from the one before (TopoJSON specification 2.1.2).
    std::vector<regional::GeoPoint> points;
    double qx = 0, qy = 0;
    for (const json::Value& position : arc.as_array()) {
      qx += position.as_array().at(0).as_number();
      qy += position.as_array().at(1).as_number();
      points.push_back({qy * sy + ty, qx * sx + tx});
    }
    topology.arcs.push_back(std::move(points));
  }
  return topology;
}

// Half the width (m) drawn for a river of a World Data Bank II class (river_files.hpp); 0: not
// drawn (river-lake banks, which the lakes draw, intermittent rivers and irrigation canals).
// Chosen for the rivers of the Plateau: the Aare (class 3) is 40 to 80 m wide through Bern.
double river_half_width_m(int level) {
  switch (level) {
    case 1: return 60.0;
    case 2: return 40.0;
    case 3: return 25.0;
    case 4: return 8.0;
    case 8: return 20.0;
    case 9: return 10.0;
    default: return 0.0;
  }
}

}  // namespace

std::vector<regional::GeoLine> read_rivers(const std::string& path, double latitude_deg, double longitude_deg,
                                           double radius_m) {
  const double reach_lat = radius_m / 111000.0;
  const double reach_lon = reach_lat / std::max(std::cos(latitude_deg * M_PI / 180.0), 0.1);
  std::vector<regional::GeoLine> rivers;
  for (const RiverLine& line : read_gshhg_rivers(path, latitude_deg - reach_lat, latitude_deg + reach_lat,
                                                 longitude_deg - reach_lon, longitude_deg + reach_lon, 9)) {
    const double half_width = river_half_width_m(line.level);
    if (half_width <= 0) continue;
    regional::GeoLine river{"river class " + std::to_string(line.level), half_width, {}};
    for (const auto& [lat, lon] : line.points) river.points.push_back({lat, lon});
    rivers.push_back(std::move(river));
  }
  return rivers;
}

regional::LandFeatures read_swiss_maps(const std::string& path, const std::string& field) {
  const std::string text = core::read_input_file(path);
  regional::LandFeatures features;
  features.source = "swiss-maps (" + std::filesystem::path(path).filename().string() + ")";
  try {
    const json::Value root = json::parse(text);
    if (root.at("type").as_string() != "Topology") throw std::out_of_range("type is not Topology");
    const Topology topology = decode_arcs(root);
    const json::Value& objects = root.at("objects");
    for (const json::Value& lake : objects.at("lakes").at("geometries").as_array()) {
      const int id = static_cast<int>(lake.at("id").as_number());
      const auto known = lakes().find(id);
      // A lake the table does not know keeps the relief under it (no surface to carve to).
      if (known == lakes().end()) continue;
      features.lakes.push_back({known->second.name, topology.rings(lake), known->second.surface_m});
    }
    std::vector<regional::GeoPolygon> municipalities;
    for (const json::Value& m : objects.at("municipalities").at("geometries").as_array())
      municipalities.push_back(
          {"municipality " + std::to_string(static_cast<long>(m.at("id").as_number())), topology.rings(m)});
    for (const regional::Town& town : regional::towns())
      for (const regional::GeoPolygon& m : municipalities)
        if (regional::contains(m, town.centre)) {
          features.settlements.push_back({town, m});
          break;
        }
  } catch (const json::ParseError& e) {
    throw core::InputError(field, path, "a swiss-maps TopoJSON (ch-combined.json)",
                           "is not JSON (line " + std::to_string(e.line) + ": " + e.what() + ")");
  } catch (const std::exception& e) {
    // std::bad_variant_access (a member of the wrong type) and std::out_of_range (one missing).
    throw core::InputError(field, path, "a swiss-maps TopoJSON (ch-combined.json)",
                           std::string("is not one (") + e.what() + ")");
  }
  if (features.lakes.empty())
    throw core::InputError(field, path, "a swiss-maps TopoJSON (ch-combined.json)", "has no lakes");
  return features;
}

std::shared_ptr<const regional::LandCoverGrid> load_land_cover(const std::string& setting, double latitude_deg,
                                                               double longitude_deg, double height_m,
                                                               std::string* warning, const std::string& field) {
  if (setting == "none") return nullptr;
  std::string path = setting;
  if (setting == "swiss-maps") {
    path = swiss_maps_default_path;
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
      if (warning)
        *warning =
            "no land cover at " + path + " (run scripts/install-data.sh): no lakes, rivers or towns on the ground";
      return nullptr;
    }
  }
  regional::LandFeatures features = read_swiss_maps(path, field);
  std::error_code error;
  if (std::filesystem::exists(gshhg_rivers_default_path, error)) {
    try {
      // The far level's corners lie its half-size times sqrt(2) away.
      features.rivers =
          read_rivers(gshhg_rivers_default_path, latitude_deg, longitude_deg, 1.5 * land_cover_far_extent_m);
      features.source += " + GSHHG rivers";
    } catch (const std::runtime_error& e) {
      if (warning) *warning = std::string("no rivers: ") + e.what();
    }
  } else if (warning) {
    *warning = std::string("no rivers at ") + gshhg_rivers_default_path + " (install gmt-gshhg-full)";
  }
  return std::make_shared<const regional::LandCoverGrid>(
      regional::land_cover_grid(latitude_deg, longitude_deg, height_m, render::osculating_earth_radius(latitude_deg),
                                features, land_cover_size, land_cover_near_extent_m, land_cover_far_extent_m));
}

}  // namespace nephele::io
