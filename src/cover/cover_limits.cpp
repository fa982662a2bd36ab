#include "cover/cover_limits.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "cover/global_cover.hpp"
#include "gpu/limits.hpp"

namespace nephele::cover {
namespace {

// Host copies made while exporting: readbacks, per-face images and the equirect map.
double host_bytes(int size) {
  const double n2 = static_cast<double>(size) * size;
  return 6.0 * n2 * 16.0 + 8.0 * n2 * 12.0;
}

}  // namespace

double default_memory_budget_bytes(const gpu::Context& context) {
  if (context.is_software()) return core::host_memory_available_bytes() / 2.0;
  const double gpu = gpu::gpu_memory_available_bytes();
  const double host = core::host_memory_available_bytes() / 2.0;
  return gpu > 0 && host > 0 ? std::min(gpu, host) : std::max(gpu, host);
}

double whole_cover_bytes(int size, Flow flow) { return cover_gpu_bytes(size, flow) + host_bytes(size); }

double tile_bytes(int size, int rows) {
  const double texels = double(size) * rows;
  // curl, warp, and the steady flow's identity map (its warp's start points) or the moving
  // flow's younger warp, a scratch map and the adaptive state: RGBA32F; density, cover contrast,
  // cover, optical thickness and cloud top: R32F; the densities, cloud tops and cover contrasts
  // read back and copied (TileDensity): 3 x 2 x 4 bytes.
  const double maps = texels * (16.0 * 5 + 4.0 * 5 + 3 * 8.0);
  // The texel weight tables of the calibration and the diagnosis, ((N + 1) / 2)^2 / 2 words
  // each, and the diagnosis's partial records (6 doubles a strip of a column).
  const double half = (size + 1) / 2;
  const double shared = 2.0 * half * (half + 1) / 2 * 4.0 + 48.0 * size * (rows / double(diagnosis_strip(size)) + 1);
  return maps + shared;
}

int tile_count_for_budget(int size, double budget, const std::string& option) {
  // The tile is the largest strip, N / S rows rounded up, and its halo.
  for (long strips = 1; strips <= size; ++strips) {
    const int rows = static_cast<int>((size + strips - 1) / strips) + 2;
    if (tile_bytes(size, std::min(rows, size)) <= budget) return static_cast<int>(6 * strips);
  }
  std::ostringstream m;
  m << option << ": " << std::floor(budget / 1048576.0) << " MiB is too little for tiles of one row of a cover of "
    << size << " per face (" << std::ceil(tile_bytes(size, std::min(size, 3)) / 1048576.0)
    << " MiB); allowed range from that up";
  throw core::InputError(m.str());
}

namespace {
// Every pass of a whole cover allocates RGBA32F cube maps of its size.
bool cube_fits(int size) { return gpu::driver_accepts(GL_PROXY_TEXTURE_CUBE_MAP, GL_RGBA32F, size, size); }
}  // namespace

bool whole_cube_fits_driver(int size) { return size <= gpu::max_cube_map_size() && cube_fits(size); }

bool cover_needs_tiles(int size, Flow flow, double budget) {
  return (budget > 0 && whole_cover_bytes(size, flow) > budget) || !whole_cube_fits_driver(size);
}

void check_cover_fits(const gpu::Context& context, int size, const std::string& option, Flow flow) {
  const int max_cube = gpu::max_cube_map_size();
  if (size > max_cube)
    throw core::InputError(option + ": " + std::to_string(size) + " exceeds this driver's cube map limit (" +
                           context.info().renderer + "); allowed range 1 to " + std::to_string(max_cube));

  if (!cube_fits(size))
    throw core::InputError(option + ": " + std::to_string(size) + " needs " + std::to_string(size) +
                           "^2 RGBA32F cube maps, " + "which this driver (" + context.info().renderer +
                           ") cannot allocate; allowed range 1 to " +
                           std::to_string(gpu::largest_fitting(max_cube, cube_fits)));

  const double host_available = core::host_memory_available_bytes();
  if (context.is_software()) {
    // A software rasteriser keeps its textures in host memory too.
    auto total = [flow](int s) { return cover_gpu_bytes(s, flow) + host_bytes(s); };
    if (host_available > 0 && total(size) > host_available) {
      std::ostringstream m;
      m << option << ": " << size << " needs about " << std::ceil(total(size) / 1048576.0) << " MiB but "
        << std::floor(host_available / 1048576.0) << " MiB are available; allowed range 1 to "
        << gpu::largest_fitting(max_cube, [&](int s) { return total(s) <= host_available; });
      throw core::InputError(m.str());
    }
    return;
  }
  if (host_available > 0 && host_bytes(size) > host_available) {
    std::ostringstream m;
    m << option << ": " << size << " needs about " << std::ceil(host_bytes(size) / 1048576.0)
      << " MiB of host memory but " << std::floor(host_available / 1048576.0)
      << " MiB are available; allowed range 1 to "
      << gpu::largest_fitting(max_cube, [&](int s) { return host_bytes(s) <= host_available; });
    throw core::InputError(m.str());
  }
  const double gpu_available = gpu::gpu_memory_available_bytes();
  if (gpu_available > 0 && cover_gpu_bytes(size, flow) > gpu_available) {
    std::ostringstream m;
    m << option << ": " << size << " needs about " << std::ceil(cover_gpu_bytes(size, flow) / 1048576.0)
      << " MiB of GPU memory but " << std::floor(gpu_available / 1048576.0) << " MiB are available; allowed range 1 to "
      << gpu::largest_fitting(max_cube, [&](int s) { return cover_gpu_bytes(s, flow) <= gpu_available; });
    throw core::InputError(m.str());
  }
}

}  // namespace nephele::cover
