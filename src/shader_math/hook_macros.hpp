// The one macro the GLSL library still needs in C++: warp_step.glsl's stepping rules are
// templates over the velocity source (empty in GLSL, where each variant has one source). Apart
// from hooks.hpp so that a file that includes shader_math.hpp (which #undefs it) can define it
// again for library text of its own (the tests' probes). No include guard on purpose.
#define WARP_TEMPLATE template <class WarpField>
