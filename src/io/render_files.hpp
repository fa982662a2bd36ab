#pragma once
// The files of a render, ground or orbit: images (.png tone-mapped sRGB, .exr linear radiance
// with the cloud opacity in A) and the JSON sidecar that says what was rendered and why.
#include <string>
#include <vector>

#include "core/json.hpp"
#include "files/atomic_output.hpp"
#include "regional/scene.hpp"
#include "core/image.hpp"
#include "render/orbit_renderer.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::io {

using render::SceneRender;

// Writes each output `names` (relative to `directory`: .png tone-mapped sRGB, .exr linear
// radiance with cloud opacity in A) and a JSON sidecar next to the first one, as one output set.
void write_scene_outputs(const SceneRender& result, const regional::Scene& scene,
                         const std::filesystem::path& directory, const std::vector<std::string>& names,
                         files::OutputSet::Scope scope);

json::Value scene_sidecar(const SceneRender& result, const regional::Scene& scene);

// One render's image as `name`'s extension says: .png tone-mapped at `exposure` (sRGB, 8 bits),
// else .exr of the linear radiance with the cloud opacity in A.
std::vector<unsigned char> encode_render_image(const core::ImageData& radiance, double exposure,
                                               const std::string& name);

// What an orbit render's sidecar records beside its camera and settings.
struct OrbitRecord {
  render::OrbitCamera camera;
  render::OrbitSettings settings;
  std::string time;
  std::string earth_texture, night_texture, cover;  // where each came from
  std::string water = "none";                       // the sun glint's water mask: ETOPO5's file, "procedural" or "none"
  std::string relief = "none";                      // the ground's relief: ETOPO5's file or "none"
  double exposure = 1;
  // How the exposure was chosen: "given" (--exposure) or "highlights" (render::highlight_exposure).
  std::string metering = "given";
};
json::Value orbit_sidecar(const render::RenderResult& result, const OrbitRecord& record);

// Writes the orbit render's image to `out` (.png or .exr) and its sidecar beside it
// (out's stem + .json), as one output set.
void write_orbit_outputs(const render::RenderResult& result, const OrbitRecord& record,
                         const std::filesystem::path& out);

}  // namespace nephele::io
