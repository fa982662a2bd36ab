#include "cover/surface_bias.hpp"

#include <algorithm>
#include <cmath>

namespace nephele::cover {

namespace {

double latitude_of_row(int row, int rows) { return 90.0 - (row + 0.5) * 180.0 / rows; }

// A (2 radius + 1)^2 box filter, separable: along rows wrapping in longitude, then along
// columns clamped at the poles.
std::vector<float> box_filter(const std::vector<float>& values, int columns, int rows, int radius) {
  const double width = 2.0 * radius + 1.0;
  std::vector<float> along(values.size()), out(values.size());
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      double sum = 0;
      for (int d = -radius; d <= radius; ++d)
        sum += values[static_cast<size_t>(j) * columns + (i + d + columns) % columns];
      along[static_cast<size_t>(j) * columns + i] = static_cast<float>(sum / width);
    }
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      double sum = 0;
      for (int d = -radius; d <= radius; ++d)
        sum += along[static_cast<size_t>(std::clamp(j + d, 0, rows - 1)) * columns + i];
      out[static_cast<size_t>(j) * columns + i] = static_cast<float>(sum / width);
    }
  return out;
}

}  // namespace

SurfaceMask resample_surface(const SurfaceMask& mask, int columns, int rows) {
  SurfaceMask out{columns, rows, std::vector<float>(static_cast<size_t>(columns) * rows), mask.source};
  for (int j = 0; j < rows; ++j) {
    // The mask rows the output row overlaps (at least one: the nearest where the mask is coarser).
    const int j0 = std::min(mask.rows - 1, j * mask.rows / rows);
    const int j1 = std::max(j0 + 1, std::min(mask.rows, (j + 1) * mask.rows / rows));
    for (int i = 0; i < columns; ++i) {
      const int i0 = std::min(mask.columns - 1, i * mask.columns / columns);
      const int i1 = std::max(i0 + 1, std::min(mask.columns, (i + 1) * mask.columns / columns));
      double sum = 0;
      for (int jj = j0; jj < j1; ++jj)
        for (int ii = i0; ii < i1; ++ii) sum += mask.land[static_cast<size_t>(jj) * mask.columns + ii];
      out.land[static_cast<size_t>(j) * columns + i] = static_cast<float>(sum / ((j1 - j0) * (i1 - i0)));
    }
  }
  return out;
}

double desert_weight(double latitude_deg) {
  const double u = (std::abs(latitude_deg) - 24.0) / 8.0;
  return std::exp(-u * u);
}

double deck_weight(double latitude_deg) {
  const double u = (std::abs(latitude_deg) - 22.0) / 9.0;
  return std::exp(-u * u);
}

std::vector<float> surface_bias(const SurfaceMask& mask) {
  const int columns = surface_bias_columns, rows = surface_bias_rows;
  const SurfaceMask grid = mask.columns == columns && mask.rows == rows ? mask : resample_surface(mask, columns, rows);
  const int reach = columns * 15 / 360;  // 15 degrees of longitude in cells
  std::vector<float> bias(static_cast<size_t>(columns) * rows);
  for (int j = 0; j < rows; ++j) {
    const double latitude = latitude_of_row(j, rows);
    const double desert = desert_weight(latitude), deck = deck_weight(latitude);
    const float* row = &grid.land[static_cast<size_t>(j) * columns];
    for (int i = 0; i < columns; ++i) {
      const double land = row[i];
      double east = 0, west = 0;  // land to the east, nearer counts more; open ocean to the west
      for (int d = 1; d <= reach; ++d) {
        east = std::max(east, row[(i + d) % columns] * (1.0 - double(d) / reach));
        west += (1.0 - row[(i - d + columns) % columns]) / reach;
      }
      bias[static_cast<size_t>(j) * columns + i] =
          static_cast<float>((1.0 - land) * deck * east * west - land * desert);
    }
  }
  // Three passes of a 9 x 9 box: close to a Gaussian of 4.5 cells (2.2 degrees), so that the
  // bias fades over a few hundred kilometres at the coasts.
  for (int pass = 0; pass < 3; ++pass) bias = box_filter(bias, columns, rows, 4);
  return bias;
}

}  // namespace nephele::cover
