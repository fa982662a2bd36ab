#pragma once
// The files of a ground render: images (.png tone-mapped sRGB, .exr linear radiance with the
// cloud opacity in A) and the JSON sidecar that says what was rendered and why.
#include <string>
#include <vector>

#include "core/json.hpp"
#include "regional/scene.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::io {

using render::SceneRender;

// Writes each output (.png tone-mapped sRGB, .exr linear radiance with cloud opacity in A) and
// a JSON sidecar next to the first one, all renamed into place together.
void write_scene_outputs(const SceneRender& result, const regional::Scene& scene,
                         const std::vector<std::string>& output_paths);

json::Value scene_sidecar(const SceneRender& result, const regional::Scene& scene);

}  // namespace nephele::io
