#pragma once
// The CPU twin of the "spline" pass of curl mode spline (shaders/cover/curl_spline.comp): the
// coefficients that shaders/lib/curl_spline.glsl's spline reads, built from the same library
// functions (curl_spline_node, curl_velocity_shifted, prefilter_cubic_bspline) in the same order.
#include <functional>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

// Nodes per face edge of the coefficient grid and of the sample grid the prefilter reads.
int spline_coefficient_extent(int cells);
int spline_sample_extent(int cells);

// The coefficients of the samples sample(face, i, j) (array indices of the sample grid, whose
// arrays begin SPLINE_MARGIN + 1 nodes before the face's edge), prefiltered along x, then y, as
// the pass does: 6 faces of spline_coefficient_extent(cells)^2 vec4, rows from t = 0, the layout
// of GlobalCover::curl_spline().read() (a glsl::SplineSource with `cells` reads them).
std::vector<glsl::vec4> spline_coefficients(int cells, const std::function<glsl::vec4(int face, int i, int j)>& sample);

// The coefficients of the cover's curl: the procedural curl (curl_velocity_shifted with the
// cover's potential offset) at the nodes of p.curl_size per face edge.
std::vector<glsl::vec4> curl_spline_coefficients(const CoverParameters& p);

}  // namespace nephele::cover
