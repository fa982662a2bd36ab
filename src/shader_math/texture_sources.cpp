// Host-side texture filtering for the library's texture hooks (hooks.hpp), written to the
// OpenGL 4.5 rules (section 8.14) in the order llvmpipe evaluates them: texel coordinate
// u = s * size - 1/2, i = floor(u), weight u - i, lerps a + w (b - a) along x, then y, then z,
// then between mip levels.
#include <algorithm>
#include <cmath>

#include "shader_math/hooks.hpp"

namespace nephele::glsl {
namespace {

struct Taps {
  int i0, i1;
  float weight;
};

Taps repeat_taps(float s, int size) {
  const float u = s * float(size) - 0.5f;
  const float i = std::floor(u);
  const int i0 = static_cast<int>(i);
  // Wrapping of the integer coordinate, also for negative ones.
  const int w0 = ((i0 % size) + size) % size;
  return {w0, (w0 + 1) % size, u - i};
}

Taps clamp_taps(float s, int size) {
  const float u = s * float(size) - 0.5f;
  const float i = std::floor(u);
  const int i0 = static_cast<int>(i);
  return {std::clamp(i0, 0, size - 1), std::clamp(i0 + 1, 0, size - 1), u - i};
}

template <class T>
T lerp(const T& a, const T& b, float w) {
  return a + w * (b - a);
}

// Trilinear interpolation of at(i, j, k) between the taps of each axis: along x, then y, then
// z, in the order GL_LINEAR weights them.
template <class At>
auto trilinear(const At& at, const Taps& tx, const Taps& ty, const Taps& tz) {
  auto plane = [&](int k) {
    return lerp(lerp(at(tx.i0, ty.i0, k), at(tx.i1, ty.i0, k), tx.weight),
                lerp(at(tx.i0, ty.i1, k), at(tx.i1, ty.i1, k), tx.weight), ty.weight);
  };
  return lerp(plane(tz.i0), plane(tz.i1), tz.weight);
}

vec4 sample_level(const std::vector<vec4>& texels, int size, vec3 x) {
  auto at = [&](int i, int j, int k) { return texels[(static_cast<size_t>(k) * size + j) * size + i]; };
  return trilinear(at, repeat_taps(x.x, size), repeat_taps(x.y, size), repeat_taps(x.z, size));
}

}  // namespace

vec4 VolumeSource::sample_lod(vec3 x, float lod) const {
  const int top = static_cast<int>(levels.size()) - 1;
  // lod <= 0 magnifies (GL_LINEAR at the base level, the same filter); beyond the last level
  // that level alone.
  const float clamped = std::clamp(lod, 0.0f, float(top));
  const int level = static_cast<int>(std::floor(clamped));
  const float fraction = clamped - float(level);
  const vec4 v0 = sample_level(levels[level], std::max(size >> level, 1), x);
  if (level >= top || fraction == 0.0f) return v0;
  const vec4 v1 = sample_level(levels[level + 1], std::max(size >> (level + 1), 1), x);
  return lerp(v0, v1, fraction);
}

float LayeredSource::sample(vec2 uv, int layer) const {
  const Taps tx = clamp_taps(uv.x, size), ty = clamp_taps(uv.y, size);
  const float* plane = values + static_cast<size_t>(std::clamp(layer, 0, layers - 1)) * size * size;
  auto at = [&](int i, int j) { return plane[static_cast<size_t>(j) * size + i]; };
  return lerp(lerp(at(tx.i0, ty.i0), at(tx.i1, ty.i0), tx.weight), lerp(at(tx.i0, ty.i1), at(tx.i1, ty.i1), tx.weight),
              ty.weight);
}

vec4 TableSource::sample(vec2 uv) const {
  const Taps tx = clamp_taps(uv.x, width), ty = clamp_taps(uv.y, height);
  auto at = [&](int i, int j) { return texels[static_cast<size_t>(j) * width + i]; };
  return lerp(lerp(at(tx.i0, ty.i0), at(tx.i1, ty.i0), tx.weight), lerp(at(tx.i0, ty.i1), at(tx.i1, ty.i1), tx.weight),
              ty.weight);
}

float DensitySource::sample(vec3 uvw) const {
  auto at = [&](int i, int j, int k) { return values[(static_cast<size_t>(k) * size + j) * size + i]; };
  return trilinear(at, clamp_taps(uvw.x, size), clamp_taps(uvw.y, size), clamp_taps(uvw.z, size));
}

float ConvectiveSource::sample(vec3 stack) const {
  const int depth = size * count;
  auto at = [&](int i, int j, int k) { return values[(static_cast<size_t>(k) * size + j) * size + i]; };
  return trilinear(at, clamp_taps(stack.x, size), clamp_taps(stack.y, size), clamp_taps(stack.z, depth));
}

}  // namespace nephele::glsl
