#include "apps/cli/device_limits.hpp"

#include <epoxy/gl.h>

#include <cmath>
#include <sstream>
#include <string>

#include "apps/cli/options.hpp"
#include "core/memory.hpp"
#include "cover/global_cover.hpp"

namespace nephele::cli {
namespace {

// Host copies made while exporting: readbacks, per-face images and the equirect map.
double host_bytes(int size) {
  const double n2 = static_cast<double>(size) * size;
  return 6.0 * n2 * 16.0 + 8.0 * n2 * 12.0;
}

// Whether the driver would allocate one level of `format` at this size: the proxy target asks
// the driver itself, which knows limits no query reports (llvmpipe refuses any texture over
// 1 GiB, a 4096^2 RGBA32F cube map among them).
bool driver_accepts(GLenum proxy, GLenum format, int width, int height) {
  glTexImage2D(proxy, 0, static_cast<GLint>(format), width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  GLint accepted = 0;
  glGetTexLevelParameteriv(proxy, 0, GL_TEXTURE_WIDTH, &accepted);
  while (glGetError() != GL_NO_ERROR) {
  }
  return accepted == width;
}

// The largest n in [0, upper] with fits(n), for fits that hold up to some n and fail above.
template <class Fits>
int largest(int upper, Fits fits) {
  int lo = 0, hi = upper;
  while (lo < hi) {
    const int mid = lo + (hi - lo + 1) / 2;
    if (fits(mid)) lo = mid;
    else hi = mid - 1;
  }
  return lo;
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

  // Every pass allocates RGBA32F cube maps of this size.
  auto cube_fits = [](int s) { return driver_accepts(GL_PROXY_TEXTURE_CUBE_MAP, GL_RGBA32F, s, s); };
  if (!cube_fits(size))
    throw UsageError("--size: " + std::to_string(size) + " needs " + std::to_string(size) + "^2 RGBA32F cube maps, " +
                     "which this driver (" + context.info().renderer + ") cannot allocate; allowed range 1 to " +
                     std::to_string(largest(max_cube, cube_fits)));

  const double host_available = core::host_memory_available_bytes();
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

void check_render_fits(const gpu::EglContext& context, int width, int height, const std::string& option) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  if (width > max_side || height > max_side)
    throw UsageError(option + ": " + size + " exceeds this driver's image limit (" + context.info().renderer +
                     "); allowed range 1 to " + std::to_string(max_side) + " on each side");
  // The render target is one RGBA32F image.
  auto fits = [width](int h) { return driver_accepts(GL_PROXY_TEXTURE_2D, GL_RGBA32F, width, h); };
  if (!fits(height))
    throw UsageError(option + ": " + size + " is a larger RGBA32F image than this driver (" + context.info().renderer +
                     ") can allocate; allowed at width " + std::to_string(width) + ": height 1 to " +
                     std::to_string(largest(height, fits)));
  // Host copies: the radiance read back (16 bytes per pixel), the tone-mapped image (12) and
  // the encoders' buffers (at most 16 more); a software rasteriser holds the image (16) too.
  const double pixels = static_cast<double>(width) * height;
  const double bytes = pixels * (44.0 + (context.is_software() ? 16.0 : 0.0));
  const double available = core::host_memory_available_bytes();
  if (available > 0 && bytes > available) {
    std::ostringstream m;
    m << option << ": " << size << " needs about " << std::ceil(bytes / 1048576.0) << " MiB but "
      << std::floor(available / 1048576.0) << " MiB of memory are available; allowed at most about "
      << std::floor(available / (bytes / pixels)) << " pixels";
    throw UsageError(m.str());
  }
}

}  // namespace nephele::cli
