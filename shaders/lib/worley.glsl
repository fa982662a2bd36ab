// 3D Worley (cellular) noise F1 with its analytic gradient, optionally periodic.
// One feature point per unit cell, uniformly jittered by three independent hashed offsets.
#ifndef NEPHELE_WORLEY_GLSL
#define NEPHELE_WORLEY_GLSL
#include "prelude.glsl"
#include "hash.glsl"

// Wraps a cell index into [0, period) per axis; period 0 leaves that axis unbounded.
// Uses floor division so that negative cells wrap correctly (GLSL % is undefined for
// negative operands); exact for |cell| < 2^24.
ivec3 wrap_cell(ivec3 cell, ivec3 period) {
  ivec3 wrapped = cell;
  for (int a = 0; a < 3; ++a) {
    if (period[a] > 0) {
      wrapped[a] = cell[a] - period[a] * int(floor(float(cell[a]) / float(period[a])));
    }
  }
  return wrapped;
}

// Feature point of a cell, as an offset in [0, 1)^3 from the cell's lower corner.
vec3 feature_offset(ivec3 cell, ivec3 period, uvec3 key) {
  return hash_to_unit3(pcg3d(uvec3(wrap_cell(cell, period)) ^ key));
}

// Squared distance from local position f (in [0,1)^3 of the cell) to the feature point of
// the neighbour cell `cell + offset`, updating the best candidate.
void worley_candidate(ivec3 cell, ivec3 offset, vec3 f, ivec3 period, uvec3 key,
                      INOUT(float) best, INOUT(vec3) best_delta) {
  vec3 delta = f - (vec3(offset) + feature_offset(cell + offset, period, key));
  float d2 = dot(delta, delta);
  if (d2 < best) {
    best = d2;
    best_delta = delta;
  }
}

// F1 (distance to the nearest feature point) at p, in cell units, with dF1/dp.
// Returns vec4(gradient, F1). The gradient is the unit vector from the nearest feature point
// to p; it jumps across Voronoi cell borders and is set to zero exactly on a feature point.
// The 27 neighbour cells are exact whenever F1 <= 1 (every point outside them is at least 1
// away); otherwise, rarely, the 5x5x5 block is searched, which is always exact because F1 is
// at most sqrt(3) < 2.
vec4 worley_f1(vec3 p, ivec3 period, uvec3 key) {
  vec3 base = floor(p);
  ivec3 cell = ivec3(base);
  vec3 f = p - base;
  float best = 1.0e30f;
  vec3 best_delta = vec3(0.0f);
  for (int k = -1; k <= 1; ++k) {
    for (int j = -1; j <= 1; ++j) {
      for (int i = -1; i <= 1; ++i) {
        worley_candidate(cell, ivec3(i, j, k), f, period, key, best, best_delta);
      }
    }
  }
  if (best > 1.0f) {
    for (int k = -2; k <= 2; ++k) {
      for (int j = -2; j <= 2; ++j) {
        for (int i = -2; i <= 2; ++i) {
          if (max(max(abs(i), abs(j)), abs(k)) == 2) {
            worley_candidate(cell, ivec3(i, j, k), f, period, key, best, best_delta);
          }
        }
      }
    }
  }
  float distance = sqrt(best);
  vec3 gradient = distance > 0.0f ? best_delta / distance : vec3(0.0f);
  return vec4(gradient, distance);
}

#endif
