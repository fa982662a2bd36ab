#include "cover/curl_spline.hpp"

#include <cstddef>

namespace nephele::cover {

int spline_coefficient_extent(int cells) { return cells + 2 * glsl::SPLINE_MARGIN; }
int spline_sample_extent(int cells) { return cells + 2 * (glsl::SPLINE_MARGIN + 1); }

std::vector<glsl::vec4> spline_coefficients(int cells,
                                            const std::function<glsl::vec4(int face, int i, int j)>& sample) {
  const int m = spline_sample_extent(cells);
  const int n = spline_coefficient_extent(cells);
  std::vector<glsl::vec4> samples(static_cast<size_t>(6) * m * m);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) samples[(static_cast<size_t>(face) * m + j) * m + i] = sample(face, i, j);
  auto at = [&](int face, int i, int j) { return samples[(static_cast<size_t>(face) * m + j) * m + i]; };
  // curl_spline.comp's prefilter: coefficient (i, j) is sample (i + 1, j + 1), first along x
  // in rows j, j + 1, j + 2, then along y.
  auto row = [&](int face, int i, int j) {
    return glsl::prefilter_cubic_bspline(at(face, i, j), at(face, i + 1, j), at(face, i + 2, j));
  };
  std::vector<glsl::vec4> coefficients(static_cast<size_t>(6) * n * n);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        coefficients[(static_cast<size_t>(face) * n + j) * n + i] =
            glsl::prefilter_cubic_bspline(row(face, i, j), row(face, i, j + 1), row(face, i, j + 2));
  return coefficients;
}

std::vector<glsl::vec4> curl_spline_coefficients(const CoverParameters& p) {
  const glsl::CurlParams curl = curl_params(p);
  const glsl::vec3 offset = potential_offset(p);
  const int cells = p.curl_size;
  return spline_coefficients(cells, [&](int face, int i, int j) {
    const glsl::vec3 n = glsl::curl_spline_node(face, i, j, glsl::SPLINE_MARGIN + 1, cells);
    return glsl::curl_flow_shifted(n, curl, offset);
  });
}

}  // namespace nephele::cover
