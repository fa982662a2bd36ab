#include "gpu/egl_context.hpp"
#include "gpu/driver_lifetime.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <cstring>

namespace nephele::gpu {
namespace {

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return "EGL error " + std::to_string(code);
  }
}

bool has_extension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + 1, name)) {
    const bool starts = p == list || p[-1] == ' ';
    const bool ends = p[n] == '\0' || p[n] == ' ';
    if (starts && ends) return true;
  }
  return false;
}

std::string gl_string(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

}  // namespace

bool EglContext::try_display(void* display_ptr, const std::string& platform, std::vector<std::string>& attempts) {
  auto display = static_cast<EGLDisplay>(display_ptr);
  if (display == EGL_NO_DISPLAY) {
    attempts.push_back(platform + ": no display (" + egl_error_name(eglGetError()) + ")");
    return false;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) {
    attempts.push_back(platform + ": eglInitialize failed (" + egl_error_name(eglGetError()) + ")");
    return false;
  }
  keep_drivers_loaded();
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context") ||
      !has_extension(extensions, "EGL_KHR_no_config_context")) {
    attempts.push_back(platform + ": EGL " + std::to_string(major) + "." + std::to_string(minor) +
                       " lacks EGL_KHR_surfaceless_context or EGL_KHR_no_config_context");
    eglTerminate(display);
    return false;
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    attempts.push_back(platform + ": eglBindAPI(EGL_OPENGL_API) failed");
    eglTerminate(display);
    return false;
  }
  const EGLint attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) {
    attempts.push_back(platform + ": no OpenGL 4.5 core context (" + egl_error_name(eglGetError()) + ")");
    eglTerminate(display);
    return false;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    attempts.push_back(platform + ": eglMakeCurrent failed (" + egl_error_name(eglGetError()) + ")");
    eglDestroyContext(display, context);
    eglTerminate(display);
    return false;
  }
  display_ = display;
  context_ = context;
  info_ = {platform, gl_string(GL_VENDOR), gl_string(GL_RENDERER), gl_string(GL_VERSION)};
  return true;
}

EglContext::EglContext() {
  const char* only = std::getenv("NEPHELE_EGL_PLATFORM");
  const std::string restrict_to = only ? only : "";
  if (!restrict_to.empty() && restrict_to != "device" && restrict_to != "surfaceless")
    throw ContextError("NEPHELE_EGL_PLATFORM is '" + restrict_to + "'; allowed values: device, surfaceless");
  std::vector<std::string> attempts;
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);

  // 1. Hardware devices (NVIDIA and others) through EGL_EXT_platform_device.
  if (restrict_to.empty() || restrict_to == "device") {
    if (has_extension(client_extensions, "EGL_EXT_platform_device") &&
        has_extension(client_extensions, "EGL_EXT_device_enumeration")) {
      EGLDeviceEXT devices[16];
      EGLint count = 0;
      eglQueryDevicesEXT(16, devices, &count);
      for (EGLint i = 0; i < count; ++i) {
        const char* device_extensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        // Software devices are better reached through the surfaceless platform below.
        if (has_extension(device_extensions, "EGL_MESA_device_software")) {
          attempts.push_back("device " + std::to_string(i) + ": a software renderer, left to the surfaceless platform");
          continue;
        }
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (try_display(display, "device " + std::to_string(i), attempts)) {
          info_.platform = "device";
          return;
        }
      }
      if (count == 0) attempts.push_back("device: no EGL devices");
    } else {
      attempts.push_back("device: EGL_EXT_platform_device not offered by the EGL client");
    }
  }
  // 2. Mesa's surfaceless platform: llvmpipe on machines without a GPU.
  if (restrict_to.empty() || restrict_to == "surfaceless") {
    if (has_extension(client_extensions, "EGL_MESA_platform_surfaceless")) {
      EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (try_display(display, "surfaceless", attempts)) return;
    } else {
      attempts.push_back("surfaceless: EGL_MESA_platform_surfaceless not offered (install libegl-mesa0)");
    }
  }
  std::string message = "no headless OpenGL 4.5 core context could be made; tried:";
  for (const auto& a : attempts) message += "\n  - " + a;
  throw ContextError(message);
}

EglContext::~EglContext() {
  auto display = static_cast<EGLDisplay>(display_);
  if (display != EGL_NO_DISPLAY && display != nullptr) {
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
  }
}

void EglContext::make_current() {
  auto display = static_cast<EGLDisplay>(display_);
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_)))
    throw ContextError("eglMakeCurrent failed (" + egl_error_name(eglGetError()) + ")");
}

}  // namespace nephele::gpu
