#pragma once
// IEEE 754 binary16 ("half") from and to float on the CPU: the KTX2 and DDS containers' R16F
// texels, and the orbit view's half-float textures, converted on every core before the upload
// rather than by the driver (docs/orbit_view.md, "Cost").
#include <cstdint>

namespace nephele::core {

// The binary16 nearest `value`, ties to even (as the F16C instruction rounds by default; Mesa's
// llvmpipe truncates instead when it converts GL_FLOAT data); overflow gives infinity, NaN stays NaN.
std::uint16_t half_from_float(float value);
// The float a finite binary16 holds (exact: every binary16 is a float).
float float_from_half(std::uint16_t h);

}  // namespace nephele::core
