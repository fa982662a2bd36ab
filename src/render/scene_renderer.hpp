#pragma once
// A scene from weather (or the global cover) to an image: the passes a scene needs, no more.
#include <memory>
#include <string>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "regional/cloud_layers.hpp"
#include "regional/convection.hpp"
#include "regional/scene.hpp"
#include "render/cloud_renderer.hpp"
#include "render/convective_volumes.hpp"

namespace nephele::render {

struct SceneRender {
  Camera camera;
  std::vector<regional::CloudLayer> layers;
  RenderResult render;
  std::vector<std::string> passes;  // every pass that ran, in order
  std::string weather_source;       // "stations" or "global cover"
  // What the layer rules read: the nearest station's weather, or the cover's at the camera
  // (the rules then read the region's: regional::sample_for_layers).
  regional::WeatherSample weather_at_camera;
  // The towering cumulus and cumulonimbus placed where the weather calls for convection
  // (docs/convection.md), and what called for it at the camera (empty: no convection there).
  std::vector<regional::ConvectiveCloud> convective_clouds;
  std::string convection_reason;
};

// What a scene needs before its march: the camera, the weather field (from the stations or the
// global cover), the layers and the wind. Made once, it can be rendered with any step counts.
struct PreparedScene {
  SceneRender partial;  // camera, layers, weather source and sample, the passes so far
  regional::WeatherField field;
  double time = 0;            // Unix seconds
  glm::dvec2 wind{0.0, 1.0};  // direction the wind blows towards (east, north)
  double wind_speed = 0.0;    // m/s
  // The ground (io::load_terrain from the scene's `terrain`); none: the bare sphere.
  std::shared_ptr<const regional::TerrainGrid> terrain;
  // The convective clouds' density volumes, made by prepare_scene; none without convection.
  std::shared_ptr<const ConvectiveVolumes> convective;
};

// The camera of a scene: its position (`at`, else the viewpoint's summit with the eye 2 m above
// it), heading (given, else the viewpoint's), pitch, field of view and size.
Camera scene_camera(const regional::Scene& scene);

// The global cover a scene without weather reads: six faces in GL order, size^2 texels each,
// rows from t = 0 (the layout of cover_field() and of io::read_cover_faces).
struct GlobalCoverFaces {
  int size = 0;
  std::vector<float> texels;
  std::vector<float> optical_thickness, cloud_top;  // the cover's other fields (cloud_properties.glsl)
};
// Runs the cover passes with `parameters` and reads the cover back (current GL context).
GlobalCoverFaces make_global_cover(const cover::CoverParameters& parameters);
// The cover a view makes when it names no weather: `size` texels per face, the seed, and the
// flow ("steady" or "moving", the table's words) at the view's ISO 8601 `time`, so that a
// moving cover is that of the moment the sun lights, and the land/ocean mask `surface` (the
// view's --surface as io::surface_from_option loads it; null: none); the rest defaults.
// render, its orbit view and nephele view all make their cover here.
cover::CoverParameters view_cover_parameters(int size, std::uint32_t seed, const std::string& flow,
                                             const std::string& time,
                                             std::shared_ptr<const cover::SurfaceMask> surface);
// The same for a scene: its cover_size, seed, cover_flow and time, and the mask of its
// cover_surface.
cover::CoverParameters scene_cover_parameters(const regional::Scene& scene,
                                              std::shared_ptr<const cover::SurfaceMask> surface);

// Need a current OpenGL 4.5 context. Throw regional::WeatherError / SceneError for bad input.
// `stations`: the weather of the scene's files (io::read_scene_weather), one per file in its
// order; empty when the scene names none (the global cover, with the land/ocean mask
// `surface` of the scene's cover_surface, is then the weather).
PreparedScene prepare_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& stations,
                            std::shared_ptr<const cover::SurfaceMask> surface);
// The same with a cover made before (the viewer keeps one while the camera moves); it is read
// only when `stations` is empty. The seed of the layers' rotations is the scene's.
PreparedScene prepare_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& stations,
                            const GlobalCoverFaces& cover);
// The march of a prepared scene with the scene's step counts and seed (its camera and weather
// come from `prepared`); `noise` as in render_clouds.
RenderSettings render_settings(const regional::Scene& scene);
SceneRender render_prepared(const PreparedScene& prepared, const regional::Scene& scene,
                            const NoiseVolume* noise = nullptr);
// The same with settings of its own (the viewer's bands of rows).
SceneRender render_prepared(const PreparedScene& prepared, const RenderSettings& settings,
                            const NoiseVolume* noise = nullptr);
// prepare_scene and render_prepared in one.
SceneRender render_scene(const regional::Scene& scene, const std::vector<regional::WeatherSeries>& stations,
                         std::shared_ptr<const cover::SurfaceMask> surface);

}  // namespace nephele::render
