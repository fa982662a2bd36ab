// Types of the tileable noise textures (tileable_noise.glsl, noise_rows.glsl), kept apart
// from the functions so that C++ gives them external linkage.
#ifndef NEPHELE_NOISE_TYPES_GLSL
#define NEPHELE_NOISE_TYPES_GLSL
#include "parameters.glsl"

// Channel types; every one is normalised to [0, 1] (docs/noise.md, "Value ranges").
const int NOISE_WORLEY = 0;           // F1 / sqrt(3)
const int NOISE_INVERTED_WORLEY = 1;  // 1 - F1 / sqrt(3)
const int NOISE_PERLIN = 2;           // 1/2 + n / (2 PERLIN_BOUND)
const int NOISE_PERLIN_WORLEY = 3;    // Perlin remapped by inverted Worley (Schneider 2015)

// One channel of a texture. Points are in texel units (texel t has its centre at t + 1/2);
// fbm.frequency is cells per texel and fbm.period the cells per texture size, per axis.
struct NoiseChannel {
  int type;          // NOISE_*
  FbmParams fbm;     // the channel's fBm (the Perlin part of perlin-worley)
  FbmParams worley;  // the inverted Worley fBm of perlin-worley; unused by the other types
};

// How the row walk turns a texel's fBm sums into its value (noise_rows.glsl).
struct NoiseFinish {
  int type;           // NOISE_*
  float norm;         // sum of the amplitudes of the channel's fBm
  float worley_norm;  // the same for the Worley part of perlin-worley
};

// Texels of one row that one invocation computes (a row segment).
const int NOISE_SEGMENT = 64;

// The 9 feature points of the cells (x, cy + j, cz + k), j, k in -1..1, seen from one row:
// x offsets in the cell, and the squared y plus z distance to the row (constant along it).
struct WorleySlab {
  float x[9];
  float dyz[9];
};

// What a Perlin row walk shares along the row (y, z): the wrapped lattice rows and slices around
// it, the fractions within the cell, and perlin_yz_weights of them.
struct PerlinRowFrame {
  ivec2 ys;
  ivec2 zs;
  float fy;
  float fz;
  vec4 w;
};

#endif
