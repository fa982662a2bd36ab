#pragma once
// Solid angles of cube map texels: texels near face corners cover less sky than central ones.
#include <vector>

namespace nephele::cover {

// Solid angle of texel (i, j) of one face, the same on all six faces, row-major (j * size + i).
// Exact: the integral of dOmega = (1 + x^2 + y^2)^(-3/2) dx dy over the texel, whose
// antiderivative is atan(x y / sqrt(1 + x^2 + y^2)). The whole table sums to 4 pi / 6.
std::vector<double> face_texel_solid_angles(int size);

}  // namespace nephele::cover
