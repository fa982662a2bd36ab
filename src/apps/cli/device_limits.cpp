#include "apps/cli/device_limits.hpp"

#include <epoxy/gl.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "apps/cli/options.hpp"
#include "cover/global_cover.hpp"

namespace nephele::cli {
namespace {

// MemAvailable from /proc/meminfo in bytes; 0 when unknown.
double host_memory_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024.0;
  return 0.0;
}

// Host copies made while exporting: readbacks, per-face images and the equirect map.
double host_bytes(int size) {
  const double n2 = static_cast<double>(size) * size;
  return 6.0 * n2 * 16.0 + 8.0 * n2 * 12.0;
}

int largest_fitting(double budget, double (*bytes)(int), int upper) {
  int lo = 0, hi = upper;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (bytes(mid) <= budget) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

}  // namespace

void check_cover_fits(const gpu::EglContext& context, int size) {
  GLint max_cube = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &max_cube);
  if (size > max_cube)
    throw UsageError("--size: " + std::to_string(size) + " exceeds this driver's cube map limit (" +
                     context.info().renderer + "); allowed range 1 to " + std::to_string(max_cube));

  const double host_available = host_memory_available();
  if (context.is_software()) {
    // A software rasteriser keeps its textures in host memory too.
    auto total = [](int s) { return cover::cover_gpu_bytes(s) + host_bytes(s); };
    if (host_available > 0 && total(size) > host_available) {
      std::ostringstream m;
      m << "--size: " << size << " needs about " << std::ceil(total(size) / 1048576.0)
        << " MiB but " << std::floor(host_available / 1048576.0) << " MiB are available; allowed range 1 to "
        << largest_fitting(host_available, +[](int s) { return cover::cover_gpu_bytes(s) + host_bytes(s); }, max_cube);
      throw UsageError(m.str());
    }
    return;
  }
  if (host_available > 0 && host_bytes(size) > host_available) {
    std::ostringstream m;
    m << "--size: " << size << " needs about " << std::ceil(host_bytes(size) / 1048576.0)
      << " MiB of host memory but " << std::floor(host_available / 1048576.0)
      << " MiB are available; allowed range 1 to " << largest_fitting(host_available, host_bytes, max_cube);
    throw UsageError(m.str());
  }
  if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
    GLint available_kb = 0;
    glGetIntegerv(0x9049 /* GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX */, &available_kb);
    const double gpu_available = available_kb * 1024.0;
    if (gpu_available > 0 && cover::cover_gpu_bytes(size) > gpu_available) {
      std::ostringstream m;
      m << "--size: " << size << " needs about " << std::ceil(cover::cover_gpu_bytes(size) / 1048576.0)
        << " MiB of GPU memory but " << std::floor(gpu_available / 1048576.0)
        << " MiB are available; allowed range 1 to "
        << largest_fitting(gpu_available, cover::cover_gpu_bytes, max_cube);
      throw UsageError(m.str());
    }
  }
}

}  // namespace nephele::cli
