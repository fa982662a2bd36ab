#include "gpu/limits.hpp"

namespace nephele::gpu {

bool driver_accepts(GLenum proxy, GLenum format, int width, int height) {
  glTexImage2D(proxy, 0, static_cast<GLint>(format), width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
  GLint accepted = 0;
  glGetTexLevelParameteriv(proxy, 0, GL_TEXTURE_WIDTH, &accepted);
  while (glGetError() != GL_NO_ERROR) {
  }
  return accepted == width;
}

int largest_fitting(int upper, const std::function<bool(int)>& fits) {
  int lo = 0, hi = upper;
  while (lo < hi) {
    const int mid = lo + (hi - lo + 1) / 2;
    if (fits(mid))
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}

namespace {
int integer_limit(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}
}  // namespace

int max_texture_size() { return integer_limit(GL_MAX_TEXTURE_SIZE); }
int max_cube_map_size() { return integer_limit(GL_MAX_CUBE_MAP_TEXTURE_SIZE); }
int max_3d_texture_size() { return integer_limit(GL_MAX_3D_TEXTURE_SIZE); }

double gpu_memory_available_bytes() {
  if (!epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) return 0.0;
  GLint available_kb = 0;
  glGetIntegerv(0x9049 /* GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX */, &available_kb);
  return available_kb * 1024.0;
}

}  // namespace nephele::gpu
