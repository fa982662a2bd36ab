#include "cover/cover_limits.hpp"

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

void check_cover_fits(const gpu::Context& context, int size, const std::string& option, Flow flow) {
  const int max_cube = gpu::max_cube_map_size();
  if (size > max_cube)
    throw core::InputError(option + ": " + std::to_string(size) + " exceeds this driver's cube map limit (" +
                           context.info().renderer + "); allowed range 1 to " + std::to_string(max_cube));

  // Every pass allocates RGBA32F cube maps of this size.
  auto cube_fits = [](int s) { return gpu::driver_accepts(GL_PROXY_TEXTURE_CUBE_MAP, GL_RGBA32F, s, s); };
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
