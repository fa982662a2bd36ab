#include "cover/solid_angle.hpp"

#include <cmath>

namespace nephele::cover {
namespace {

double area_antiderivative(double x, double y) { return std::atan2(x * y, std::sqrt(1.0 + x * x + y * y)); }

}  // namespace

std::vector<double> face_texel_solid_angles(int size) {
  std::vector<double> edges(static_cast<size_t>(size) + 1);
  for (int k = 0; k <= size; ++k) edges[k] = 2.0 * k / size - 1.0;
  std::vector<double> angles(static_cast<size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      angles[static_cast<size_t>(j) * size + i] =
          area_antiderivative(edges[i + 1], edges[j + 1]) - area_antiderivative(edges[i], edges[j + 1]) -
          area_antiderivative(edges[i + 1], edges[j]) + area_antiderivative(edges[i], edges[j]);
  return angles;
}

}  // namespace nephele::cover
