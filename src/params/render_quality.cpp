#include "params/render_quality.hpp"

#include <stdexcept>

namespace nephele::params {

const RenderQuality* find_render_quality(std::string_view name) {
  for (const RenderQuality& q : render_qualities)
    if (q.name == name) return &q;
  return nullptr;
}

const RenderQuality& default_render_quality() {
  const RenderQuality* q = find_render_quality("default");
  if (q == nullptr) throw std::logic_error("render_qualities: no 'default'");
  return *q;
}

const RenderQuality& final_render_quality() {
  const RenderQuality* q = find_render_quality("final");
  if (q == nullptr) throw std::logic_error("render_qualities: no 'final'");
  return *q;
}

std::string render_quality_names() {
  std::string names;
  for (const RenderQuality& q : render_qualities) names += (names.empty() ? "" : "|") + std::string(q.name);
  return names;
}

}  // namespace nephele::params
