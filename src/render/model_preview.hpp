#pragma once
// A preview image of a cloud model's density volume (shaders/model/preview.comp on
// shaders/lib/model_march.glsl): the camera south of the box looking north, the regional
// marcher's light model with a shadow ray per sample, sky and ground light from
// render::sky_irradiance. docs/model.md, "Preview".
#include <vector>

#include "core/image.hpp"
#include "model/density_volume.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {

struct PreviewSettings {
  int width = 384, height = 384;
  int view_steps = 128;             // samples across the box's edge
  int light_steps = 8;              // samples towards the sun
  double sun_elevation_deg = 35;
  double sun_azimuth_deg = 225;     // clockwise from north (+y): the south-west, behind the camera's left
  double fov_deg = 50;
};

// The view of `model` (its extent and extinction) with `settings`.
glsl::ModelView preview_view(const model::CloudModel& model, const PreviewSettings& settings);

// Linear radiance (RGB) and cloud opacity (A). Needs a current OpenGL 4.5 context.
core::ImageData render_preview(const model::DensityVolume& volume, const PreviewSettings& settings);

// The same on the CPU from the volume's values (tests).
core::ImageData render_preview_cpu(const std::vector<float>& values, int size, const model::CloudModel& model,
                                   const PreviewSettings& settings);

}  // namespace nephele::render
