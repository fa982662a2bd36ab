#include "render/render_limits.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "gpu/limits.hpp"

namespace nephele::render {

void check_render_fits(const gpu::Context& context, int width, int height, const std::string& option) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  const int max_side = gpu::max_texture_size();
  if (width > max_side || height > max_side)
    throw core::InputError(option + ": " + size + " exceeds this driver's image limit (" + context.info().renderer +
                           "); allowed range 1 to " + std::to_string(max_side) + " on each side");
  // The render target is one RGBA32F image.
  auto fits = [width](int h) { return gpu::driver_accepts(GL_PROXY_TEXTURE_2D, GL_RGBA32F, width, h); };
  if (!fits(height))
    throw core::InputError(option + ": " + size + " is a larger RGBA32F image than this driver (" +
                           context.info().renderer + ") can allocate; allowed at width " + std::to_string(width) +
                           ": height 1 to " + std::to_string(gpu::largest_fitting(height, fits)));
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
    throw core::InputError(m.str());
  }
}

}  // namespace nephele::render
