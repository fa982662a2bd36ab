// GLSL side of the shared GLSL/C++ subset (the C++ side is src/shader_math/glsl_cpp.hpp).
// Parameter qualifiers are macros so that C++ can pass by reference.
#ifndef NEPHELE_PRELUDE_GLSL
#define NEPHELE_PRELUDE_GLSL
#define IN(T) in T
#define OUT(T) out T
#define INOUT(T) inout T
#endif
