#pragma once
// Small render scenes shared by the render tests: cheap to march, with the summer stations.
#include <string>

#include "regional/scene.hpp"

namespace nephele::test {

// The default view at width x height with few steps, an 8-texel cover and the Bern and
// Solothurn summer weather of scenes/weather (a summer afternoon with cumulus).
inline regional::Scene small_summer_scene(int width = 16, int height = 8) {
  regional::Scene scene;
  scene.width = width;
  scene.height = height;
  scene.view_steps = 8;
  scene.light_steps = 2;
  scene.sky_steps = 4;
  scene.cover_size = 8;
  scene.shadow_map_size = 64;  // as coarse as the image (the default 512^2 is most of its time)
  scene.time = "2026-06-21T15:00Z";
  scene.weather = {std::string(NEPHELE_SOURCE_DIR) + "/scenes/weather/bern-summer.json",
                   std::string(NEPHELE_SOURCE_DIR) + "/scenes/weather/solothurn-summer.json"};
  return scene;
}

}  // namespace nephele::test
