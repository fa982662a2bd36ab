// 3D Worley (cellular) noise F1 with its analytic gradient, optionally periodic.
// One feature point per unit cell, uniformly jittered by three independent hashed offsets.
#ifndef NEPHELE_WORLEY_GLSL
#define NEPHELE_WORLEY_GLSL
#include "prelude.glsl"
#include "hash.glsl"

// c - period * quotient, moved into [0, period) when the quotient is off by one: GLSL's float
// division may be 2.5 ulp off (NVIDIA's is; 21.0 / 7.0 can floor to 2), so the floored quotient
// of wrap_axis can miss by one either way. Exact for |c| < 2^23 and any quotient within one.
int wrap_remainder(int c, int period, int quotient) {
  int r = c - period * quotient;
  return r < 0 ? r + period : (r >= period ? r - period : r);
}

// Wraps one lattice index into [0, period); period 0 leaves it unbounded. Floor division, so
// that negative indices wrap correctly (GLSL % is undefined for negative operands), with the
// remainder corrected: exact on every driver for |c| < 2^23.
int wrap_axis(int c, int period) {
  return period > 0 ? wrap_remainder(c, period, int(floor(float(c) / float(period)))) : c;
}

// The same for each axis of a cell index.
ivec3 wrap_cell(ivec3 cell, ivec3 period) {
  return ivec3(wrap_axis(cell.x, period.x), wrap_axis(cell.y, period.y), wrap_axis(cell.z, period.z));
}

// wrap_axis(c + step) from wrapped = wrap_axis(c), for |step| <= 1: the same integer without a
// division. The 27-cell searches wrap three indices per axis this way instead of dividing for
// each cell's three (12 % of the density pass on llvmpipe).
int wrap_step(int wrapped, int step, int period) {
  int c = wrapped + step;
  return period > 0 ? (c < 0 ? c + period : (c >= period ? c - period : c)) : c;
}

// The wrapped indices of c - 1, c and c + 1, with one division for the three.
ivec3 wrapped_neighbours(int c, int period) {
  int wrapped = wrap_axis(c, period);
  return ivec3(wrap_step(wrapped, -1, period), wrapped, wrap_step(wrapped, 1, period));
}

// Feature point of an already wrapped cell, as an offset in [0, 1)^3 from its lower corner.
vec3 wrapped_feature_offset(ivec3 wrapped, uvec3 key) {
  return hash_to_unit3(pcg3d(uvec3(wrapped) ^ key));
}

// Feature point of a cell, as an offset in [0, 1)^3 from the cell's lower corner.
vec3 feature_offset(ivec3 cell, ivec3 period, uvec3 key) {
  return wrapped_feature_offset(wrap_cell(cell, period), key);
}

// Squared distance from local position f (in [0,1)^3 of the cell) to `feature`, the point of
// the neighbour cell `offset` away, updating the best candidate.
void worley_nearer(vec3 feature, ivec3 offset, vec3 f, INOUT(float) best, INOUT(vec3) best_delta) {
  vec3 delta = f - (vec3(offset) + feature);
  float d2 = dot(delta, delta);
  if (d2 < best) {
    best = d2;
    best_delta = delta;
  }
}

// The same for the point of the neighbour cell `cell + offset`, wrapped here.
void worley_candidate(ivec3 cell, ivec3 offset, vec3 f, ivec3 period, uvec3 key,
                      INOUT(float) best, INOUT(vec3) best_delta) {
  worley_nearer(feature_offset(cell + offset, period, key), offset, f, best, best_delta);
}

// The k-th cell (k in [0, 125)) of the 5x5x5 block around a point's cell, x fastest.
const int WIDER_CELLS = 125;
ivec3 wider_offset(int k) { return ivec3(k % 5 - 2, (k / 5) % 5 - 2, k / 25 - 2); }

// The 5x5x5 block's outer shell around p's cell (p at f within it), which F1 needs where the 27
// cells around it found no point within 1 (rarely: every point outside them is at least 1 away,
// and F1 is at most sqrt(3) < 2). `searched`: WIDER_CELLS, or 0 where the 27 found one
// (SKIPPABLE). A loop over the cells rather than an `if` around them: llvmpipe runs an `if`'s body
// for every group of lanes, which made this rare search a tenth of the 1024 cover's density
// pass; a group that does not enter the loop pays one masked cell.
void worley_wider_search(ivec3 cell, vec3 f, ivec3 period, uvec3 key, int searched, INOUT(float) best,
                         INOUT(vec3) best_delta) {
  for (int k = 0; k < searched; ++k) {
    ivec3 offset = wider_offset(k);
    if (max(max(abs(offset.x), abs(offset.y)), abs(offset.z)) == 2) {
      worley_candidate(cell, offset, f, period, key, best, best_delta);
    }
  }
}

// p's lattice cell, p's place in it, and the wrapped indices of the cells either side on each
// axis (wrapped_neighbours), which the 27-cell searches visit.
struct WorleyCell {
  ivec3 cell;
  vec3 f;
  ivec3 xs;
  ivec3 ys;
  ivec3 zs;
};
WorleyCell worley_cell(vec3 p, ivec3 period) {
  vec3 base = floor(p);
  WorleyCell c;
  c.cell = ivec3(base);
  c.f = p - base;
  c.xs = wrapped_neighbours(c.cell.x, period.x);
  c.ys = wrapped_neighbours(c.cell.y, period.y);
  c.zs = wrapped_neighbours(c.cell.z, period.z);
  return c;
}

// F1 and its gradient from the nearest point's squared distance and the vector from it to p.
vec4 worley_result(float best, vec3 best_delta) {
  float distance = sqrt(best);
  vec3 gradient = distance > 0.0f ? best_delta / distance : vec3(0.0f);
  return vec4(gradient, distance);
}

// F1 (distance to the nearest feature point) at p, in cell units, with dF1/dp.
// Returns vec4(gradient, F1). The gradient is the unit vector from the nearest feature point
// to p; it jumps across Voronoi cell borders and is set to zero exactly on a feature point.
// The 27 neighbour cells are exact whenever F1 <= 1; otherwise the wider search.
vec4 worley_f1(vec3 p, ivec3 period, uvec3 key) {
  WorleyCell c = worley_cell(p, period);
  float best = 1.0e30f;
  vec3 best_delta = vec3(0.0f);
  for (int k = -1; k <= 1; ++k) {
    for (int j = -1; j <= 1; ++j) {
      for (int i = -1; i <= 1; ++i) {
        vec3 feature = wrapped_feature_offset(ivec3(c.xs[i + 1], c.ys[j + 1], c.zs[k + 1]), key);
        worley_nearer(feature, ivec3(i, j, k), c.f, best, best_delta);
      }
    }
  }
  worley_wider_search(c.cell, c.f, period, key, SKIPPABLE(best > 1.0f, WIDER_CELLS), best, best_delta);
  return worley_result(best, best_delta);
}

// The neighbour cells of a Worley search: the 27 around p's cell, the k-th at this offset
// (k in [0, 27), x fastest).
const int NEIGHBOUR_CELLS = 27;
ivec3 neighbour_offset(int k) { return ivec3(k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1); }

// The 8 cells of the 2 x 2 x 2 block nearest to a point at `f` in its cell (each coordinate in
// [0, 1)), the k-th at this offset (k in [0, 8)): its own cell and, along each axis, the neighbour on
// the nearer side. They hold every feature point within half a cell of the point: a point in any
// other cell lies at least half a cell away along some axis.
const int NEAR_CELLS = 8;
ivec3 near_offset(int k, vec3 f) {
  ivec3 side = ivec3(f.x < 0.5f ? -1 : 1, f.y < 0.5f ? -1 : 1, f.z < 0.5f ? -1 : 1);
  return ivec3(k % 2, (k / 2) % 2, k / 4) * side;
}

// worley_f1 with a search a group of SIMD lanes can skip: the first `searched` of the neighbour
// cells, NEIGHBOUR_CELLS, or 0 where the caller needs no F1 (distance 1e15, gradient 0; prelude.glsl,
// SKIPPABLE). The same F1 where all are searched, from one loop of a count the compiler cannot
// know (worley_f1's three nested constant loops, unrolled, are faster where every lane needs F1).
vec4 worley_f1_searched(vec3 p, ivec3 period, uvec3 key, int searched) {
  WorleyCell c = worley_cell(p, period);
  float best = 1.0e30f;
  vec3 best_delta = vec3(0.0f);
  for (int k = 0; k < searched; ++k) {
    ivec3 offset = neighbour_offset(k);
    vec3 feature = wrapped_feature_offset(ivec3(c.xs[offset.x + 1], c.ys[offset.y + 1], c.zs[offset.z + 1]), key);
    worley_nearer(feature, offset, c.f, best, best_delta);
  }
  worley_wider_search(c.cell, c.f, period, key, SKIPPABLE(best > 1.0f && searched > 0, WIDER_CELLS), best,
                      best_delta);
  return worley_result(best, best_delta);
}

// The lattice cell of the feature point nearest to p (worley_f1's result f1 at p): p less the
// vector from that point to p, floored. It names a cell's cloud (weather_systems.glsl) and counts
// cells in tests.
ivec3 nearest_cell(vec3 p, vec4 f1) { return ivec3(floor(p - vec3(f1) * f1.w)); }

// Smooth inverted Worley noise, the flow's potential (docs/numerics.md, "Smooth potential").
// Each feature point carries a bump K(r) = (1 - r^2)^5 for r < 1 cell, 0 beyond; the bumps
// are combined by a smooth maximum (log-sum-exp with exact zeros for absent points),
//   W = lambda ln(1 + sum_i (exp(K_i / lambda) - 1)),
// so W = K_i where only one bump reaches p and W -> max_i K_i as lambda -> 0 (W is a smooth
// minimum of the distances). Every point within 1 cell of p lies in the 27 searched cells and
// K vanishes with its first four derivatives at r = 1, so nothing jumps where a point enters
// or leaves the search: W is C^4, its gradient (the velocity) C^3, enough for order 4.
// `smoothing` is lambda; values below 0.02 count as 0.02, which keeps 27 exp(1 / lambda)
// finite in float (lambda > 0.0118). Returns vec4(dW/dp, W); W lies in [0, 1 + lambda ln 27].
vec4 smooth_worley(vec3 p, ivec3 period, uvec3 key, float smoothing) {
  float lambda = max(smoothing, 0.02f);
  WorleyCell c = worley_cell(p, period);
  float sum = 0.0f;
  vec3 gradient = vec3(0.0f);
  for (int k = -1; k <= 1; ++k) {
    for (int j = -1; j <= 1; ++j) {
      for (int i = -1; i <= 1; ++i) {
        ivec3 offset = ivec3(i, j, k);
        vec3 feature = wrapped_feature_offset(ivec3(c.xs[i + 1], c.ys[j + 1], c.zs[k + 1]), key);
        vec3 delta = c.f - (vec3(offset) + feature);
        float r2 = dot(delta, delta);
        if (r2 < 1.0f) {
          float s = 1.0f - r2;
          float s4 = (s * s) * (s * s);
          float e = exp((s4 * s) / lambda);
          sum += e - 1.0f;
          gradient += (-10.0f * s4 * e) * delta;  // e dK/dp, dK/dp = -10 (1 - r^2)^4 delta
        }
      }
    }
  }
  float total = 1.0f + sum;
  return vec4(gradient / total, lambda * log(total));
}

#endif
