#pragma once
// What the current driver can allocate, asked before any allocation so that a size too large
// is bad input (exit code 2) rather than a failure halfway. Needs a current OpenGL context.
#include <epoxy/gl.h>

#include <functional>

namespace nephele::gpu {

// Whether the driver would allocate one level of `format` at this size: the proxy target asks
// the driver itself, which knows limits no query reports (llvmpipe refuses any texture over
// about 1.5 GiB, a 4096^2 RGBA32F cube map among them).
bool driver_accepts(GLenum proxy, GLenum format, int width, int height);

// The largest n in [0, upper] with fits(n), for fits that hold up to some n and fail above.
int largest_fitting(int upper, const std::function<bool(int)>& fits);

int max_texture_size();
int max_cube_map_size();
int max_3d_texture_size();
// Free GPU memory where the driver reports it (GL_NVX_gpu_memory_info), else 0.
double gpu_memory_available_bytes();

}  // namespace nephele::gpu
