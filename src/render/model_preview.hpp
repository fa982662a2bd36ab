#pragma once
// A preview image of a cloud model's density volume (shaders/model/preview.comp on
// shaders/lib/model_march.glsl): the camera south of the box looking north, the regional
// marcher's light model with a shadow ray per sample, sky and ground light from
// render::sky_irradiance. docs/model.md, "Preview".
#include <memory>
#include <vector>

#include "core/image.hpp"
#include "gpu/compute_program.hpp"
#include "model/density_volume.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::render {

struct PreviewSettings {
  int width = 384, height = 384;
  int view_steps = 128;  // samples across the box's edge
  int light_steps = 8;   // samples towards the sun
  double sun_elevation_deg = 35;
  double sun_azimuth_deg = 225;  // clockwise from north (+y): the south-west, behind the camera's left
  double fov_deg = 50;
  // The camera orbits `target` (model units) `distance` extents away, looking at it along
  // `heading_deg` (clockwise from north, +y) and `pitch_deg` (up from level). The defaults
  // are nephele model's preview.png: from the south, 1.3 extents out of the box, at 0.45 of
  // its height. nephele view --model turns the heading and pitch.
  double heading_deg = 0, pitch_deg = 0;
  double distance = 1.8;
  glsl::vec3 target{0.5f, 0.5f, 0.45f};
  // A band of rows of the width x height image (row_count 0: every row); the other rows of the
  // result are left 0 (nephele view refines the full size band by band).
  int first_row = 0, row_count = 0;
};

// The view of `model` (its extent and extinction) with `settings`.
glsl::ModelView preview_view(const model::CloudModel& model, const PreviewSettings& settings);

// The preview pass with its program compiled once (nephele view renders it every frame).
class PreviewRenderer {
 public:
  PreviewRenderer();  // needs a current OpenGL 4.5 context
  ~PreviewRenderer();
  PreviewRenderer(const PreviewRenderer&) = delete;
  PreviewRenderer& operator=(const PreviewRenderer&) = delete;
  // Linear radiance (RGB) and cloud opacity (A).
  core::ImageData render(const model::DensityVolume& volume, const PreviewSettings& settings);

 private:
  std::unique_ptr<gpu::ComputeProgram> program_;
};

// Linear radiance (RGB) and cloud opacity (A), with a program made for this one image. Needs a
// current OpenGL 4.5 context.
core::ImageData render_preview(const model::DensityVolume& volume, const PreviewSettings& settings);

// The same on the CPU from the volume's values (tests).
core::ImageData render_preview_cpu(const std::vector<float>& values, int size, const model::CloudModel& model,
                                   const PreviewSettings& settings);

}  // namespace nephele::render
