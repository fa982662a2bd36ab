#include "model/bricks.hpp"

#include <algorithm>
#include <cmath>

namespace nephele::model {
namespace {

// The shader's distances are float sums and products of values below 4 (a few ulp, < 1e-6);
// a brick is culled only beyond R + I + this, so culled voxels have x >= 1 and a field of
// exactly 0 in the shader too (wyvill1 returns 0 for x >= 1).
constexpr double kMargin = 1e-4;

double clampd(double v, double lo, double hi) { return std::max(lo, std::min(hi, v)); }

}  // namespace

std::vector<int> footprint(const BrickGrid& grid, const Primitive& p) {
  const int n = grid.per_axis();
  const double reach_m = double(p.radius) + double(p.influence) + kMargin;
  const glsl::vec3 to = p.segment ? p.to : p.from;
  // Bricks of the skeleton's box grown by the reach, then a distance test per brick.
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    const double low = std::min(p.from[a], to[a]) - reach_m, high = std::max(p.from[a], to[a]) + reach_m;
    lo[a] = std::max(0, int(std::floor(low * grid.size / brick_edge)));
    hi[a] = std::min(n - 1, int(std::floor(high * grid.size / brick_edge)));
  }
  std::vector<int> bricks;
  const double voxel = 1.0 / grid.size;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) {
        // The box spanned by the brick's voxel centres.
        const int b[3] = {x, y, z};
        double box_lo[3], box_hi[3];
        for (int a = 0; a < 3; ++a) {
          box_lo[a] = (b[a] * brick_edge + 0.5) * voxel;
          box_hi[a] = (std::min(grid.size, (b[a] + 1) * brick_edge) - 0.5) * voxel;
        }
        double d;
        if (!p.segment) {
          double s = 0;
          for (int a = 0; a < 3; ++a) {
            const double e = p.from[a] - clampd(p.from[a], box_lo[a], box_hi[a]);
            s += e * e;
          }
          d = std::sqrt(s);
        } else {
          // Distance from the segment to the box's centre, less the box's half diagonal: a
          // lower bound of the distance to any point of the box.
          double c[3], half = 0, ab2 = 0, t = 0;
          for (int a = 0; a < 3; ++a) {
            c[a] = 0.5 * (box_lo[a] + box_hi[a]);
            half += 0.25 * (box_hi[a] - box_lo[a]) * (box_hi[a] - box_lo[a]);
            const double ab = double(to[a]) - p.from[a];
            ab2 += ab * ab;
            t += (c[a] - p.from[a]) * ab;
          }
          t = ab2 > 0 ? clampd(t / ab2, 0.0, 1.0) : 0.0;
          double s = 0;
          for (int a = 0; a < 3; ++a) {
            const double e = c[a] - (p.from[a] + t * (double(to[a]) - p.from[a]));
            s += e * e;
          }
          d = std::sqrt(s) - std::sqrt(half);
        }
        if (d <= reach_m) bricks.push_back(x + n * (y + n * z));
      }
  return bricks;
}

std::vector<std::vector<std::uint32_t>> brick_lists(const BrickGrid& grid, const CloudModel& m) {
  std::vector<std::vector<std::uint32_t>> lists(static_cast<size_t>(grid.count()));
  for (size_t i = 0; i < m.primitives.size(); ++i)
    for (int b : footprint(grid, m.primitives[i])) lists[static_cast<size_t>(b)].push_back(std::uint32_t(i));
  return lists;
}

}  // namespace nephele::model
