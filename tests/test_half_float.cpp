// Half floats on the CPU (src/core/half_float.cpp): IEEE 754 binary16 rounding, checked against
// bit patterns worked out by hand and against the tests' own decoder (texture_readers.cpp).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "core/half_float.hpp"
#include "texture_readers.hpp"

using namespace nephele;

TEST_CASE("half_from_float rounds to the nearest binary16, ties to even, through subnormals and overflow",
          "[fast][half]") {
  // Exact values and their bit patterns (IEEE 754-2008, binary16).
  CHECK(core::half_from_float(0.0f) == 0x0000);
  CHECK(core::half_from_float(-0.0f) == 0x8000);
  CHECK(core::half_from_float(1.0f) == 0x3C00);
  CHECK(core::half_from_float(0.5f) == 0x3800);
  CHECK(core::half_from_float(65504.0f) == 0x7BFF);               // largest finite half
  CHECK(core::half_from_float(std::ldexp(1.0f, -24)) == 0x0001);  // smallest subnormal
  CHECK(core::half_from_float(std::ldexp(1.0f, -14)) == 0x0400);  // smallest normal
  // Between 1 and the next half (1 + 2^-10): below, at and above the midpoint.
  CHECK(core::half_from_float(1.0f + std::ldexp(1.0f, -12)) == 0x3C00);
  CHECK(core::half_from_float(1.0f + std::ldexp(1.0f, -11)) == 0x3C00);      // tie to even (mantissa 0)
  CHECK(core::half_from_float(1.0f + 3 * std::ldexp(1.0f, -11)) == 0x3C02);  // tie to even (mantissa 2)
  CHECK(core::half_from_float(1.0f + std::ldexp(1.0f, -11) + std::ldexp(1.0f, -20)) == 0x3C01);
  CHECK(core::half_from_float(std::ldexp(1.0f, -25)) == 0x0000);  // half the smallest subnormal: tie to even 0
  CHECK(core::half_from_float(1e6f) == 0x7C00);                   // overflow to infinity
  // Every value the reader decodes maps back to itself.
  for (std::uint32_t h = 0; h < 0x7C00; ++h) {
    if (core::half_from_float(test::float_from_half(std::uint16_t(h))) != h) FAIL("round trip of " << h);
    if (core::float_from_half(std::uint16_t(h)) != test::float_from_half(std::uint16_t(h)))
      FAIL("float_from_half of " << h);
  }
}
