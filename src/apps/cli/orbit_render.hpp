#pragma once
// nephele render --view orbit: the planet, its cloud shell and atmosphere from anywhere between
// 1 m and 40000 km (src/render/orbit_renderer.hpp, docs/orbit_view.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "apps/cli/options.hpp"
#include "params/table.hpp"

namespace nephele::cli {

// The orbit view's usual exposure: the metering's centre (render::highlight_exposure keeps
// within a factor 4 of it), and the viewer's.
constexpr double orbit_default_exposure = 2.5;

struct OrbitOptions {
  double lat = 0, lon = 0, altitude_km = 0;  // from the table's defaults (bind_orbit_options)
  std::string cover, earth_texture, night_texture;
  double planet_radius_km = 0, cloud_base_km = 0, cloud_thickness_km = 0, cloud_detail = 1,
         cloud_tau_spread = 0;  // bind_orbit_options sets the table's defaults
  // Shared with the ground views (set by run_render).
  std::string time, size, out;
  std::optional<double> heading, pitch, fov;
  std::uint32_t seed = 1;
  std::string flow{params::cover::flow.default_text};        // the generated cover's (without --cover)
  std::string surface{params::cover::surface.default_text};  // its land/ocean mask
  std::optional<double> exposure;  // --exposure; without it metered (render::highlight_exposure)
  bool verbose = false, quiet = false;
  bool no_cache = false;  // --no-cache: the generated cover neither read from nor written to the cache
};

void bind_orbit_options(Options& options, OrbitOptions& orbit);
// The table's parameters only the orbit view takes.
const std::vector<const params::Parameter*>& orbit_only_parameters();
int run_orbit_render(const OrbitOptions& orbit);
// nephele bench orbit: median milliseconds per frame at 640x360 and 1280x720 (the default
// textures and a generated cover, 2000 km above Bern, looking at the centre).
int bench_orbit(const std::vector<std::string>& arguments);

}  // namespace nephele::cli
