#include "studies/render_error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "io/surface_files.hpp"
#include "io/weather_files.hpp"
#include "params/render_quality.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::studies {

using render::NoiseVolume;
using render::PreparedScene;
using render::SceneRender;

std::vector<RenderVariant> RenderSweepOptions::variants() const {
  std::vector<RenderVariant> all;
  for (int v : view_steps)
    for (int l : light_steps) all.push_back({v, l, 1, 1});
  all.insert(all.end(), extra.begin(), extra.end());
  return all;
}

std::string RenderSweepOptions::reference_name() const {
  return std::to_string(reference_view) + " view x " + std::to_string(reference_light) + " light steps over " +
         std::to_string(reference_frames) + " frames";
}

RenderSweepOptions RenderSweepOptions::full() {
  RenderSweepOptions o;
  o.view_steps = {8, 16, 32, 48, 96};
  o.light_steps = {2, 4, 6, 12};
  const regional::Scene d;
  o.extra = {{d.view_steps, d.light_steps, 2, 1},
             {d.view_steps, d.light_steps, 4, 1},
             {d.view_steps, d.light_steps, 1, 2},
             {d.view_steps, d.light_steps, 1, 4},
             {24, 6, 4, 1},
             {d.view_steps, d.light_steps, 4, 2},
             {8, 2, 1, 2},
             {8, 2, 1, 4}};
  o.reference_view = 192;
  o.reference_light = 24;
  o.reference_frames = 4;
  o.width = 160;
  o.height = 90;
  return o;
}

RenderSweepOptions RenderSweepOptions::qualities(bool quick) {
  RenderSweepOptions o;
  for (const params::RenderQuality& q : params::render_qualities)
    o.extra.push_back({q.view_steps, q.light_steps, q.frames, q.resolution_divisor});
  o.reference_view = 96;
  o.reference_light = 12;
  o.reference_frames = 1;
  o.share_shadow_maps = false;
  o.width = quick ? 64 : 1280;
  o.height = quick ? 36 : 720;
  return o;
}

RenderSweepOptions RenderSweepOptions::quick() {
  RenderSweepOptions o;
  o.view_steps = {8, 16, 48};
  o.light_steps = {2, 12};  // the default light steps among them
  const regional::Scene d;
  o.extra = {{d.view_steps, d.light_steps, 2, 1}, {d.view_steps, d.light_steps, 1, 2}};
  o.reference_view = 96;
  o.reference_light = 12;
  o.reference_frames = 2;
  o.width = 32;
  o.height = 18;
  return o;
}

void measure_render_error(const core::ImageData& image, const core::ImageData& reference, double exposure,
                          const std::vector<bool>& excluded, RenderErrorRow& row) {
  if (image.width != reference.width || image.height != reference.height || image.channels != reference.channels ||
      image.channels < 3)
    throw std::invalid_argument("measure_render_error: images of different sizes");
  const auto& p = image.pixels;
  const auto& ref = reference.pixels;
  const size_t pixels = ref.size() / reference.channels;
  const auto kept = [&](size_t pixel) { return excluded.empty() || !excluded[pixel]; };
  size_t n = 0;
  double mean = 0;
  for (size_t i = 0; i < pixels; ++i)
    if (kept(i)) {
      const size_t k = i * reference.channels;
      mean += (ref[k] + ref[k + 1] + ref[k + 2]) / 3.0;
      ++n;
    }
  row.rms_error = row.max_error = row.display_rms = 0.0;
  if (n == 0) return;
  mean /= static_cast<double>(n);
  double sum = 0, worst = 0;
  for (size_t i = 0; i < pixels; ++i)
    if (kept(i))
      for (int c = 0; c < 3; ++c) {
        const size_t k = i * reference.channels + c;
        const double d = std::abs(p[k] - ref[k]);
        sum += d * d;
        worst = std::max(worst, d);
      }
  row.rms_error = mean > 0 ? std::sqrt(sum / (3.0 * n)) / mean : 0.0;
  row.max_error = mean > 0 ? worst / mean : 0.0;
  const core::ImageData shown = render::tone_map(image, exposure);
  const core::ImageData shown_reference = render::tone_map(reference, exposure);
  double display = 0;
  for (size_t i = 0; i < pixels; ++i)
    if (kept(i))
      for (int c = 0; c < 3; ++c) {
        const double d = shown.pixels[i * 3 + c] - shown_reference.pixels[i * 3 + c];
        display += d * d;
      }
  row.display_rms = std::sqrt(display / (3.0 * n));
}

std::vector<RenderErrorRow> render_error_sweep(const regional::Scene& scene, const RenderSweepOptions& options,
                                               const std::function<void(const RenderErrorRow&)>& progress,
                                               ReferenceCheck* reference_check) {
  regional::Scene base = scene;
  base.width = options.width;
  base.height = options.height;
  base.frames = 1;
  // The weather and the noise volume depend neither on the step counts nor on the frame size:
  // made once, shared by every render of the sweep (the camera is made again per size).
  std::string surface_warning;  // the default etopo5 not installed: the sweep's cover has no mask
  const PreparedScene prepared =
      render::prepare_scene(base, io::read_scene_weather(base), io::scene_surface(base, &surface_warning, "surface"));
  const NoiseVolume noise(render::render_settings(base).noise_size, render::render_settings(base).seed);
  const auto shadow_maps = options.share_shadow_maps ? std::make_shared<render::ShadowMapCache>() : nullptr;
  const auto render_variant = [&](const RenderVariant& v, double* time_ms, double* render_ms) {
    regional::Scene s = base;
    s.view_steps = v.view_steps;
    s.light_steps = v.light_steps;
    s.frames = v.frames;
    s.resolution_divisor = v.divisor;  // render_prepared marches fewer pixels and upsamples
    render::RenderSettings settings = render::render_settings(s);
    settings.shadow_cache = shadow_maps;
    const auto start = std::chrono::steady_clock::now();
    const SceneRender r = render::render_prepared(prepared, settings, &noise);
    if (render_ms != nullptr)
      *render_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (time_ms != nullptr)
      for (const auto& [name, ms] : r.render.timings_ms)
        if (name == "clouds") *time_ms = ms;
    return r;
  };
  const SceneRender reference =
      render_variant({options.reference_view, options.reference_light, options.reference_frames, 1}, nullptr, nullptr);
  // llvmpipe cuts a whole SIMD vector of invocations once the loops of one reach the limit, so
  // the pixels of a flagged pixel's workgroup (8 x 8, clouds.comp) go too.
  constexpr int tile = 8;
  std::vector<bool> excluded(static_cast<size_t>(options.width) * options.height, false);
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x)
      if (reference.render.loop_limited(x, y))
        for (int ty = y / tile * tile; ty < std::min(y / tile * tile + tile, options.height); ++ty)
          for (int tx = x / tile * tile; tx < std::min(x / tile * tile + tile, options.width); ++tx)
            excluded[static_cast<size_t>(ty) * options.width + tx] = true;
  if (reference_check != nullptr) {
    reference_check->limited = static_cast<unsigned>(std::count(excluded.begin(), excluded.end(), true));
    const RenderVariant half{std::max(1, options.reference_view / 2), std::max(1, options.reference_light / 2),
                             options.reference_frames, 1};
    RenderErrorRow& row = reference_check->half_steps;
    row = {half.view_steps, half.light_steps, half.frames, 1};
    measure_render_error(render_variant(half, &row.time_ms, &row.render_ms).render.radiance, reference.render.radiance,
                         base.exposure, excluded, row);
  }
  std::vector<RenderErrorRow> rows;
  for (const RenderVariant& v : options.variants()) {
    RenderErrorRow row{v.view_steps, v.light_steps, v.frames, v.divisor};
    const SceneRender r = render_variant(v, &row.time_ms, &row.render_ms);
    const core::ImageData& image = r.render.radiance;
    measure_render_error(image, reference.render.radiance, base.exposure, excluded, row);
    rows.push_back(row);
    if (progress) progress(rows.back());
  }
  return rows;
}

}  // namespace nephele::studies
