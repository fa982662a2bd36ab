#include "model/model_limits.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "model/density_volume.hpp"

namespace nephele::model {
namespace {

// Host bytes of a run: the read-back volume, the atlas, the encoded files and the VDB tree
// (each about one volume), plus the texture itself on a software driver (host memory).
double host_bytes(int size, bool software) {
  return 4.0 * DensityVolume::device_bytes(size) + (software ? DensityVolume::device_bytes(size) : 0.0);
}

}  // namespace

void check_model_fits(int size, const gpu::Context& context, const char* option) {
  const double available = core::host_memory_available_bytes();
  const double needed = host_bytes(size, context.is_software());
  if (available > 0 && needed > available) {
    int largest = size;
    while (largest > 8 && host_bytes(largest, context.is_software()) > available) largest = largest * 7 / 8;
    std::ostringstream m;
    m << option << ": " << size << "^3 voxels need about " << std::ceil(needed / 1048576.0) << " MiB but "
      << std::floor(available / 1048576.0) << " MiB of memory are available; allowed up to about " << largest;
    throw core::InputError(m.str());
  }
}

}  // namespace nephele::model
