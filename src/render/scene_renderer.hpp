#pragma once
// A scene from weather (or the global cover) to an image: the passes a scene needs, no more.
#include <string>
#include <vector>

#include "regional/cloud_layers.hpp"
#include "regional/scene.hpp"
#include "render/cloud_renderer.hpp"
#include "util/json.hpp"

namespace nephele::render {

struct SceneRender {
  Camera camera;
  std::vector<regional::CloudLayer> layers;
  RenderResult render;
  std::vector<std::string> passes;  // every pass that ran, in order
  std::string weather_source;       // "stations" or "global cover"
  regional::WeatherSample weather_at_camera;  // what the layer rules read
};

// Needs a current OpenGL 4.5 context. Throws regional::WeatherError / SceneError for bad input.
SceneRender render_scene(const regional::Scene& scene);

// Writes each output (.png tone-mapped sRGB, .exr linear radiance with cloud opacity in A) and
// a JSON sidecar next to the first one, all renamed into place together.
void write_scene_outputs(const SceneRender& result, const regional::Scene& scene,
                         const std::vector<std::string>& output_paths);

json::Value scene_sidecar(const SceneRender& result, const regional::Scene& scene);

}  // namespace nephele::render
