// Elementary functions whose precision GLSL leaves to the driver, written out so that every
// driver and the C++ twin agree to float rounding. (Mesa's llvmpipe asin errs by up to 4e-4.)
#ifndef NEPHELE_PORTABLE_MATH_GLSL
#define NEPHELE_PORTABLE_MATH_GLSL
#include "prelude.glsl"

const float PI_F = 3.14159265358979f;

// arcsin by Abramowitz and Stegun, Handbook of Mathematical Functions (1964), 4.4.46:
// asin x = pi/2 - sqrt(1 - x) (a0 + a1 x + ... + a7 x^7) for 0 <= x <= 1, |error| <= 2e-8,
// extended to negative x by oddness. In float the evaluation adds a few ulp.
float portable_asin(float x) {
  float a = min(abs(x), 1.0f);
  float p = -0.0012624911f;
  p = p * a + 0.0066700901f;
  p = p * a - 0.0170881256f;
  p = p * a + 0.0308918810f;
  p = p * a - 0.0501743046f;
  p = p * a + 0.0889789874f;
  p = p * a - 0.2145988016f;
  p = p * a + 1.5707963050f;
  float r = 1.5707963268f - sqrt(1.0f - a) * p;
  return x < 0.0f ? -r : r;
}

#endif
