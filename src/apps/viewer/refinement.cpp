#include "apps/viewer/refinement.hpp"

#include <algorithm>
#include <chrono>

namespace nephele::viewer {
namespace {

// `image` at width x height by the nearest pixel: the rows that the bands have not reached yet.
core::ImageData upsampled(const core::ImageData& image, int width, int height) {
  core::ImageData out{width, height, image.channels, std::vector<float>(std::size_t(width) * height * image.channels)};
  if (image.width == 0 || image.height == 0) return out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(image.width - 1, x * image.width / width),
                sy = std::min(image.height - 1, y * image.height / height);
      std::copy_n(&image.pixels[(std::size_t(sy) * image.width + sx) * image.channels], image.channels,
                  &out.pixels[(std::size_t(y) * width + x) * image.channels]);
    }
  return out;
}

}  // namespace

const std::vector<RefinementLevel>& refinement_levels() {
  // Eight bands: the rows of sky and cloud cost most (the ground's rays end at once), so the
  // bands of the upper half take most of the time; eight keep each under about a quarter of a
  // whole full-size render (docs/viewer.md).
  static const std::vector<RefinementLevel> levels = [] {
    std::vector<RefinementLevel> out = {{4, 0, 1}, {2, 0, 1}};
    for (int band = 0; band < 8; ++band) out.push_back({1, band, 8});
    return out;
  }();
  return levels;
}

void Refinement::restart(const std::string& key, const std::string& scene_key, int width, int height) {
  const bool resized = width != target_width_ || height != target_height_;
  camera_moving_ = !resized && scene_key == shown_scene_key_;
  if (!camera_moving_) preview_history_ = {};
  shown_key_ = key;
  shown_scene_key_ = scene_key;
  target_width_ = width;
  target_height_ = height;
  next_level_ = 0;
}

bool Refinement::step(ViewSource& source, const ViewState& state) {
  const int width = target_width_, height = target_height_;
  if (next_level_ < refinement_levels().size()) {
    const RefinementLevel level = refinement_levels()[next_level_];
    // Sizes round up, so that the preview is never empty.
    const int w = (width + level.divisor - 1) / level.divisor, h = (height + level.divisor - 1) / level.divisor;
    const int rows = (h + level.bands - 1) / level.bands, first = std::min(h, level.band * rows);
    render::Camera camera = state.camera;
    camera.width = w;
    camera.height = h;
    // A moving camera's preview: a quarter of the pixels marched, the rest reprojected.
    const bool reduced = next_level_ == 0 && camera_moving_ && !camera.panorama && !state.modeller &&
                         preview_history_.radiance.width == w && preview_history_.radiance.height == h;
    const glm::ivec2 phase = render::march_phase(moving_frames_, preview_march_stride);
    if (reduced) source.set_march_lattice(preview_march_stride, phase);
    // The reduced sizes are previews the full size replaces: the source may march fewer steps.
    last_render_ =
        source.render(state, w, h, first, level.bands > 1 ? std::min(rows, h - first) : 0, level.divisor > 1);
    source.set_march_lattice(1, {0, 0});
    if (last_render_.march_stride > 1) {
      ++moving_frames_;
      const auto start = std::chrono::steady_clock::now();
      const long reprojected = render::fill_unmarched(last_render_.radiance, camera, last_render_.march_stride,
                                                      last_render_.march_phase, &preview_history_);
      last_render_.timings_ms.emplace_back(
          "reproject", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      last_render_.passes.push_back("reproject " + std::to_string(reprojected) + " pixels");
    }
    if (next_level_ == 0) preview_history_ = {last_render_.radiance, camera};
    ++renders_;
    ++next_level_;
    if (level.bands == 1) {
      shown_ = last_render_.radiance;
    } else {
      if (level.band == 0) shown_ = upsampled(shown_, w, h);
      const std::size_t row = std::size_t(w) * shown_.channels;
      std::copy(last_render_.radiance.pixels.begin() + first * row,
                last_render_.radiance.pixels.begin() + std::min(h, first + rows) * row,
                shown_.pixels.begin() + first * row);
    }
    return true;
  }
  return false;
}

}  // namespace nephele::viewer
