#pragma once
// Keeps the loaded Mesa drivers (*_dri.so) mapped until exit in AddressSanitizer builds
// (scripts/sanitize.sh); a no-op otherwise. eglTerminate, and glfwTerminate with X, unload the
// driver before LeakSanitizer reports at exit, and leaks inside unloaded code show as
// "<unknown module>", which no suppression can name. Marked RTLD_NODELETE, the drivers stay
// mapped, so that scripts/lsan.supp can name Mesa's own leaks by library. Call it once a
// context exists (the driver is loaded then).
namespace nephele::gpu {

void keep_drivers_loaded();

}  // namespace nephele::gpu
