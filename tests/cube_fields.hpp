#pragma once
// Helpers for tests that read cube-map fields back: texels as vec4, their index, and the
// Lipschitz constant of a velocity field.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "shader_math/shader_math.hpp"

namespace nephele::test {

inline std::vector<glsl::vec4> as_vec4(const std::vector<float>& rgba) {
  std::vector<glsl::vec4> texels(rgba.size() / 4);
  std::memcpy(texels.data(), rgba.data(), rgba.size() * sizeof(float));
  return texels;
}

// Index of texel (i, j) of a face in the face-major layout the passes read back.
inline size_t index(int size, int face, int i, int j) { return (static_cast<size_t>(face) * size + j) * size + i; }

// Largest rate of change of a velocity cube map between neighbouring texel centres (per
// radian): a Lipschitz constant of the field, which bounds how perturbations (rounding errors)
// grow per step.
inline double velocity_lipschitz(const std::vector<glsl::vec4>& curl, int size) {
  double worst = 0;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i)
        for (const glsl::ivec2 step : {glsl::ivec2(1, 0), glsl::ivec2(0, 1)}) {
          const int i2 = i + step.x, j2 = j + step.y;
          if (i2 >= size || j2 >= size) continue;
          const double angle =
              std::acos(std::clamp(static_cast<double>(glsl::dot(glsl::texel_direction(face, i, j, size),
                                                                 glsl::texel_direction(face, i2, j2, size))),
                                   -1.0, 1.0));
          const double change =
              glsl::length(glsl::vec3(curl[index(size, face, i, j)]) - glsl::vec3(curl[index(size, face, i2, j2)]));
          worst = std::max(worst, change / angle);
        }
  return worst;
}

}  // namespace nephele::test
