#version 450
// Pass 3: the flow map over the flow time T, each texel following its own trajectory.
// Variants (defines from src/numerics/integrators.cpp): WARP_INTEGRATOR, an INTEGRATOR_*
// number of warp_step.glsl; WARP_PROCEDURAL 1 evaluates the curl at the exact point instead
// of sampling the curl cube map, WARP_SPLINE 1 the cubic B-spline of the curl grid (binding 4). The start points come from identity_field, whose size (that
// of warp_field) may differ from the curl field's: the report warps sample points that way.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform readonly image2DArray identity_field;
layout(rgba32f, binding = 2) uniform writeonly image2DArray warp_field;

#ifndef WARP_INTEGRATOR
#define WARP_INTEGRATOR 0
#endif
#ifndef WARP_PROCEDURAL
#define WARP_PROCEDURAL 0
#endif
#ifndef WARP_SPLINE
#define WARP_SPLINE 0
#endif

#include "../lib/curl_flow.glsl"
#include "../lib/cube_sampling.glsl"

// The curl map: the velocity source of curl mode sampled, which reads it anywhere on the sphere
// (so it needs the whole cube map, never a tile); in the other modes only RK4's first velocity
// at the texel itself (u_start_velocity), as the identity and warp maps a whole map or a tile.
#if WARP_PROCEDURAL || WARP_SPLINE
layout(rgba32f, binding = 1) uniform readonly image2DArray curl_field;
#else
layout(rgba32f, binding = 1) uniform readonly imageCube curl_field;
#endif

// The velocity source of warp_step.glsl's stepping rules (WarpField) and the uniform that holds
// it (VELOCITY_SOURCE): the curl evaluated where the stepping rule asks, the curl spline, or
// the curl cube map.
#if WARP_PROCEDURAL
uniform CurlParams u_curl;
uniform vec3 u_noise_offset;
#define WarpField CurlParams
vec3 warp_velocity(vec3 w, IN(CurlParams) curl) { return curl_velocity_shifted(w, curl, u_noise_offset); }
#define VELOCITY_SOURCE u_curl
#elif WARP_SPLINE
layout(rgba32f, binding = 4) uniform readonly image2DArray curl_spline;
#include "../lib/curl_spline.glsl"
#define WarpField SplineImage
#define VELOCITY_SOURCE curl_spline
#else
#define VELOCITY_SOURCE curl_field
#endif
#include "../lib/warp_step.glsl"

uniform int u_steps;        // fixed-step schemes: K, or the steps of this dispatch
// 1: curl_field holds the warp's own velocity at the start points (curl mode spline, the
// starts are the identity field, the first dispatch), which RK4 then takes as its first k1.
uniform int u_start_velocity;
uniform float u_step_size;  // h (adaptive: the first step)
#if WARP_INTEGRATOR == 4
// A long adaptive integration runs over several dispatches (see GlobalCover::dispatch_warp):
// each texel keeps (t, h, attempts, done) here and continues where it stopped; identity_field
// then holds the previous dispatch's points.
layout(rgba32f, binding = 3) uniform image2DArray adaptive_state;
layout(std430, binding = 0) buffer Unfinished { uint unfinished; };
uniform float u_flow_time;  // T
uniform float u_max_step;
uniform float u_tolerance;  // error per step, radians
uniform int u_max_substeps;
uniform int u_chunk;        // attempts per texel in this dispatch
uniform int u_resume;       // 0: the first dispatch
#endif

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  ivec3 extent = imageSize(warp_field);
  if (texel.x >= extent.x || texel.y >= extent.y) return;
  vec3 start = imageLoad(identity_field, texel).xyz;
#if WARP_INTEGRATOR == 4
  vec4 state = u_resume != 0 ? imageLoad(adaptive_state, texel) : vec4(0.0f, min(u_step_size, u_max_step), 0.0f, 0.0f);
  vec3 w = start;
  float t = state.x;
  float h = state.y;
  int attempts = int(state.z);
  bool done = state.w > 0.5f;
  if (!done) {
    done = advance_adaptive(w, t, h, attempts, u_flow_time, u_max_step, u_tolerance,
                            min(u_max_substeps, attempts + u_chunk), VELOCITY_SOURCE);
  }
  imageStore(adaptive_state, texel, vec4(t, h, float(attempts), done ? 1.0f : 0.0f));
  // w: attempted steps, negative while T is not reached (in the end: u_max_substeps ran out).
  imageStore(warp_field, texel, vec4(w, done ? float(attempts) : -float(attempts)));
  if (!done && attempts < u_max_substeps) atomicAdd(unfinished, 1u);
#else
  vec3 start_velocity = imageLoad(curl_field, texel).xyz;
  imageStore(warp_field, texel,
             vec4(integrate_fixed_from(WARP_INTEGRATOR, start, start_velocity, u_start_velocity, u_steps, u_step_size,
                                       VELOCITY_SOURCE), 0.0f));
#endif
}
