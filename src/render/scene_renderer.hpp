#pragma once
// A scene from weather (or the global cover) to an image: the passes a scene needs, no more.
#include <string>
#include <vector>

#include "regional/cloud_layers.hpp"
#include "regional/scene.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::render {

struct SceneRender {
  Camera camera;
  std::vector<regional::CloudLayer> layers;
  RenderResult render;
  std::vector<std::string> passes;  // every pass that ran, in order
  std::string weather_source;       // "stations" or "global cover"
  regional::WeatherSample weather_at_camera;  // what the layer rules read
};

// What a scene needs before its march: the camera, the weather field (from the stations or the
// global cover), the layers and the wind. Made once, it can be rendered with any step counts.
struct PreparedScene {
  SceneRender partial;  // camera, layers, weather source and sample, the passes so far
  regional::WeatherField field;
  double time = 0;      // Unix seconds
  glm::dvec2 wind{0.0, 1.0};  // direction the wind blows towards (east, north)
  double wind_speed = 0.0;    // m/s
  // The ground (io::load_terrain from the scene's `terrain`); none: the bare sphere.
  std::shared_ptr<const regional::TerrainGrid> terrain;
};

// Need a current OpenGL 4.5 context. Throw regional::WeatherError / SceneError for bad input.
// `stations`: the weather of the scene's files (io::read_scene_weather), one per file in its
// order; empty when the scene names none (the global cover is then the weather).
PreparedScene prepare_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& stations);
// The march of a prepared scene with the scene's step counts and seed (its camera and weather
// come from `prepared`); `noise` as in render_clouds.
RenderSettings render_settings(const regional::Scene& scene);
SceneRender render_prepared(const PreparedScene& prepared, const regional::Scene& scene,
                            const NoiseVolume* noise = nullptr);
SceneRender render_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& stations);

}  // namespace nephele::render
