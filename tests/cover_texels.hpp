#pragma once
// A small global cover run on the GPU and read back as (direction, cover) per texel, for tests
// that judge where the clouds are (test_circulation.cpp, test_surface.cpp).
#include <vector>

#include "cover/global_cover.hpp"
#include "gl_support.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::test {

struct CoverTexel {
  glsl::vec3 direction;  // the texel centre's unit vector (ECEF axes, z north)
  float cover;           // 0 clear, > 0 cloudy
};

// Runs every pass of `p` (size and curl_size as given) and returns its texels.
inline std::vector<CoverTexel> cover_texels(const cover::CoverParameters& p) {
  test_context();
  cover::GlobalCover cover(p);
  cover.run();
  const std::vector<float> identity = cover.identity_field().read(), covered = cover.cover_field().read();
  std::vector<CoverTexel> texels(covered.size());
  for (size_t k = 0; k < covered.size(); ++k)
    texels[k] = {glsl::vec3(identity[4 * k], identity[4 * k + 1], identity[4 * k + 2]), covered[k]};
  return texels;
}

}  // namespace nephele::test
