// Integer hashing: every random number in nephele comes from here.
// Integer arithmetic is exact and identical on every driver and far from the origin,
// unlike the common fract(sin(x) * 43758.5453) hashes.
#ifndef NEPHELE_HASH_GLSL
#define NEPHELE_HASH_GLSL

// pcg3d from Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020:
// three rounds of a linear congruential step with cross-coupled components.
uvec3 pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v = v ^ (v >> 16u);
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// Three independent uniform numbers in [0, 1) with 24 bits each (exact in float).
vec3 hash_to_unit3(uvec3 h) {
  return vec3(h >> 8u) * (1.0f / 16777216.0f);
}

// A key that decorrelates noise layers: one per (seed, layer) pair.
uvec3 noise_key(uint seed, uint layer) {
  return pcg3d(uvec3(seed, layer, 0x9E3779B9u));
}

#endif
