#include "studies/render_error.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "io/weather_files.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::studies {

using render::NoiseVolume;
using render::PreparedScene;
using render::RenderSettings;
using render::SceneRender;

RenderSweepOptions RenderSweepOptions::full() {
  RenderSweepOptions o;
  o.view_steps = {8, 16, 32, 48, 96};
  o.light_steps = {2, 4, 6, 12};
  o.reference_view = 384;
  o.reference_light = 24;
  o.width = 160;
  o.height = 90;
  return o;
}

RenderSweepOptions RenderSweepOptions::quick() {
  RenderSweepOptions o;
  o.view_steps = {8, 16, 48};
  o.light_steps = {2, 12};  // the default light steps among them
  o.reference_view = 96;
  o.reference_light = 12;
  o.width = 32;
  o.height = 18;
  return o;
}

std::vector<RenderErrorRow> render_error_sweep(const regional::Scene& scene, const RenderSweepOptions& options,
                                               const std::function<void(const RenderErrorRow&)>& progress) {
  regional::Scene base = scene;
  base.width = options.width;
  base.height = options.height;
  // The weather and the noise volume do not depend on the step counts: made once, shared by
  // every render of the sweep.
  const PreparedScene prepared = render::prepare_scene(base, io::read_scene_weather(base));
  const RenderSettings settings = render::render_settings(base);
  const NoiseVolume noise(settings.noise_size, settings.seed);
  regional::Scene reference_scene = base;
  reference_scene.view_steps = options.reference_view;
  reference_scene.light_steps = options.reference_light;
  const SceneRender reference = render::render_prepared(prepared, reference_scene, &noise);
  if (reference.render.loop_limited_pixels > 0)
    std::cerr << "warning: the " << options.reference_view << " x " << options.reference_light << " reference has "
              << reference.render.loop_limited_pixels
              << " pixels at 65535 or more shader loop iterations; llvmpipe cuts those short, so the errors "
                 "there are not to be trusted (docs/rendering.md)\n";
  const auto& ref = reference.render.radiance.pixels;
  double mean = 0;
  for (size_t k = 0; k < ref.size(); k += 4) mean += (ref[k] + ref[k + 1] + ref[k + 2]) / 3.0;
  mean /= ref.size() / 4.0;
  std::vector<RenderErrorRow> rows;
  for (int v : options.view_steps) {
    for (int l : options.light_steps) {
      regional::Scene s = base;
      s.view_steps = v;
      s.light_steps = l;
      const SceneRender r = render::render_prepared(prepared, s, &noise);
      double time = 0;
      for (const auto& [name, ms] : r.render.timings_ms)
        if (name == "clouds") time = ms;
      double sum = 0, worst = 0;
      const auto& p = r.render.radiance.pixels;
      for (size_t k = 0; k < p.size(); k += 4)
        for (int c = 0; c < 3; ++c) {
          const double d = std::abs(p[k + c] - ref[k + c]);
          sum += d * d;
          worst = std::max(worst, d);
        }
      rows.push_back({v, l, time, std::sqrt(sum / (3.0 * p.size() / 4.0)) / mean, worst / mean});
      if (progress) progress(rows.back());
    }
  }
  return rows;
}

}  // namespace nephele::studies
