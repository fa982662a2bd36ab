#include "render/render_error.hpp"

#include <algorithm>
#include <cmath>

#include "render/scene_renderer.hpp"

namespace nephele::render {

std::vector<RenderErrorRow> render_error_sweep(const regional::Scene& scene, const std::vector<int>& view_steps,
                                               const std::vector<int>& light_steps, int reference_view,
                                               int reference_light) {
  regional::Scene reference_scene = scene;
  reference_scene.view_steps = reference_view;
  reference_scene.light_steps = reference_light;
  const SceneRender reference = render_scene(reference_scene);
  const auto& ref = reference.render.radiance.pixels;
  double mean = 0;
  for (size_t k = 0; k < ref.size(); k += 4) mean += (ref[k] + ref[k + 1] + ref[k + 2]) / 3.0;
  mean /= ref.size() / 4.0;
  std::vector<RenderErrorRow> rows;
  for (int v : view_steps) {
    for (int l : light_steps) {
      regional::Scene s = scene;
      s.view_steps = v;
      s.light_steps = l;
      const SceneRender r = render_scene(s);
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
    }
  }
  return rows;
}

}  // namespace nephele::render
