#include "noise/noise_limits.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "gpu/limits.hpp"
#include "noise/noise_texture.hpp"

namespace nephele::noise {

void check_noise_fits(const TextureSpec& spec, const gpu::Context& context, const char* size_option) {
  const int max_3d = gpu::max_3d_texture_size();
  const std::pair<const char*, int> sizes[] = {{size_option ? size_option : "--width", spec.width},
                                               {size_option ? size_option : "--height", spec.height},
                                               {size_option ? size_option : "--depth", spec.depth}};
  for (const auto& [option, value] : sizes)
    if (value > max_3d)
      throw core::InputError(std::string(option) + ": " + std::to_string(value) +
                             " exceeds this driver's 3D texture limit (" + context.info().renderer +
                             "); allowed range 1 to " + std::to_string(max_3d));
  const double available = core::host_memory_available_bytes();
  const double needed = host_bytes(spec);
  if (available > 0 && needed > available) {
    std::ostringstream m;
    m << "--width, --height, --depth: " << spec.width << " x " << spec.height << " x " << spec.depth << " with "
      << spec.channels.size() << " channels needs about " << std::ceil(needed / 1048576.0) << " MiB but "
      << std::floor(available / 1048576.0) << " MiB of memory are available; allowed at most about "
      << std::floor((available - static_cast<double>(TextureGenerator::slab_budget_bytes)) / 12.0 /
                    static_cast<double>(spec.channels.size()))
      << " texels in all";
    throw core::InputError(m.str());
  }
}

}  // namespace nephele::noise
