#include "cover/surface_bias.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

#include <glm/common.hpp>

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

double interior_weight(double latitude_deg) {
  const double u = (std::abs(latitude_deg) - 43.0) / 8.0;
  return std::exp(-u * u);
}

double inland(double ocean_distance_km) { return glm::smoothstep(500.0, 1500.0, ocean_distance_km); }

std::vector<float> ocean_distance_km(const SurfaceMask& grid) {
  const int columns = grid.columns, rows = grid.rows;
  constexpr double radius_km = 6371.0;
  const double dlat = M_PI / rows * radius_km, dlon = 2.0 * M_PI / columns * radius_km;
  // The steps' lengths from row j to row j + dj (dj = -1, 0, 1) and one column east or west, at
  // the mean latitude of the two rows: step[3 j + dj + 1].
  std::vector<double> step(3 * static_cast<size_t>(rows));
  for (int j = 0; j < rows; ++j)
    for (int dj = -1; dj <= 1; ++dj) {
      const int jj = std::clamp(j + dj, 0, rows - 1);
      const double east = dlon * std::cos((latitude_of_row(j, rows) + latitude_of_row(jj, rows)) * 0.5 * M_PI / 180.0);
      step[3 * static_cast<size_t>(j) + dj + 1] = std::sqrt(east * east + (dj != 0 ? dlat * dlat : 0.0));
    }
  std::vector<double> distance(static_cast<size_t>(columns) * rows, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  // Every ocean cell is at 0, but only those beside land start the search: a shortest path to
  // a land cell leaves the ocean from one of them, so the distances are the same as from all
  // (and the queue holds a few thousand cells, not the whole ocean's).
  for (std::size_t k = 0; k < distance.size(); ++k)
    if (grid.land[k] < 0.5f) distance[k] = 0.0;
  for (std::size_t k = 0; k < distance.size(); ++k) {
    if (distance[k] != 0.0) continue;
    const int j = static_cast<int>(k / columns), i = static_cast<int>(k % columns);
    bool beside_land = false;
    for (int dj = -1; dj <= 1 && !beside_land; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const int jj = j + dj;
        if (jj < 0 || jj >= rows) continue;
        if (distance[static_cast<std::size_t>(jj) * columns + (i + di + columns) % columns] != 0.0) beside_land = true;
      }
    if (beside_land) queue.push({0.0, k});
  }
  while (!queue.empty()) {
    const auto [d, k] = queue.top();
    queue.pop();
    if (d > distance[k]) continue;
    const int j = static_cast<int>(k / columns), i = static_cast<int>(k % columns);
    for (int dj = -1; dj <= 1; ++dj) {
      const int jj = j + dj;
      if (jj < 0 || jj >= rows) continue;
      for (int di = -1; di <= 1; ++di) {
        if (di == 0 && dj == 0) continue;
        const std::size_t n = static_cast<std::size_t>(jj) * columns + (i + di + columns) % columns;
        const double through = d + (di == 0 ? dlat : step[3 * static_cast<size_t>(j) + dj + 1]);
        if (through < distance[n]) distance[n] = through, queue.push({through, n});
      }
    }
  }
  return std::vector<float>(distance.begin(), distance.end());
}

std::vector<float> surface_bias(const SurfaceMask& mask) {
  const std::vector<float> terms = surface_terms(mask);
  std::vector<float> bias(terms.size() / 3);
  for (std::size_t k = 0; k < bias.size(); ++k) bias[k] = terms[3 * k] - terms[3 * k + 1];
  return bias;
}

std::vector<float> surface_terms(const SurfaceMask& mask) {
  const int columns = surface_bias_columns, rows = surface_bias_rows;
  const SurfaceMask grid = mask.columns == columns && mask.rows == rows ? mask : resample_surface(mask, columns, rows);
  const int reach = columns * 15 / 360;  // 15 degrees of longitude in cells: the coast to the east
  // The open ocean to the west: W = smoothstep(10, 30 degrees) of its stretch before the first land
  // cell (land 1/2 or more), so that a sea with a coast close to its west (the Bay of Bengal, the
  // Arabian Sea, the Mozambique Channel, the Gulf of Mexico) gets no deck, nor one whose open
  // ocean lies beyond a continent.
  const int fetch_from = columns * 10 / 360, fetch = columns * 30 / 360;
  std::vector<float> decks(static_cast<size_t>(columns) * rows), deserts(decks.size()), seas(decks.size());
  const std::vector<float> distance = ocean_distance_km(grid);
  for (int j = 0; j < rows; ++j) {
    const double latitude = latitude_of_row(j, rows);
    const double subtropics = desert_weight(latitude), interior = interior_weight(latitude),
                 deck = deck_weight(latitude);
    const float* row = &grid.land[static_cast<size_t>(j) * columns];
    for (int i = 0; i < columns; ++i) {
      const double land = row[i];
      double east = 0, west = 0;  // land to the east, nearer counts more; open ocean to the west
      for (int d = 1; d <= reach; ++d) east = std::max(east, row[(i + d) % columns] * (1.0 - double(d) / reach));
      int open = 0;
      while (open < fetch && row[(i - open - 1 + columns) % columns] < 0.5f) ++open;
      west = glm::smoothstep(double(fetch_from), double(fetch), double(open));
      const double desert = std::max(subtropics, interior * inland(distance[static_cast<size_t>(j) * columns + i]));
      decks[static_cast<size_t>(j) * columns + i] = static_cast<float>((1.0 - land) * deck * east * west);
      deserts[static_cast<size_t>(j) * columns + i] = static_cast<float>(land * desert);
      seas[static_cast<size_t>(j) * columns + i] = static_cast<float>(1.0 - land);
    }
  }
  // Three passes of a 9 x 9 box: close to a Gaussian of 4.5 cells (2.2 degrees), so that the
  // bias fades over a few hundred kilometres at the coasts.
  for (int pass = 0; pass < 3; ++pass) {
    decks = box_filter(decks, columns, rows, 4);
    deserts = box_filter(deserts, columns, rows, 4);
    seas = box_filter(seas, columns, rows, 4);
  }
  std::vector<float> terms(3 * decks.size());
  for (std::size_t k = 0; k < decks.size(); ++k)
    terms[3 * k] = decks[k], terms[3 * k + 1] = deserts[k], terms[3 * k + 2] = seas[k];
  return terms;
}

}  // namespace nephele::cover
