#pragma once
// The files of a ground render: images (.png tone-mapped sRGB, .exr linear radiance with the
// cloud opacity in A) and the JSON sidecar that says what was rendered and why.
#include <string>
#include <vector>

#include "core/json.hpp"
#include "files/atomic_output.hpp"
#include "regional/scene.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::io {

using render::SceneRender;

// Writes each output `names` (relative to `directory`: .png tone-mapped sRGB, .exr linear
// radiance with cloud opacity in A) and a JSON sidecar next to the first one, as one output set.
void write_scene_outputs(const SceneRender& result, const regional::Scene& scene,
                         const std::filesystem::path& directory, const std::vector<std::string>& names,
                         files::OutputSet::Scope scope);

json::Value scene_sidecar(const SceneRender& result, const regional::Scene& scene);

}  // namespace nephele::io
