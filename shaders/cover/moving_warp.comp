#version 450
// Pass 3 of the moving flow (--flow moving): for each texel, where its air was at the two cloud
// layers' ages, by one back-trajectory through the time-dependent flow (moving_flow.glsl). The
// older layer's points go to warp_field (where the steady warp writes its own), the younger's to
// young_warp_field; the density pass blends the noise found at both (docs/algorithm.md, "The
// moving flow"). Variants: MOVING_SPLINE 1 (curl mode spline, the default) reads the flow from
// the splines of its grids at time nodes (binding 4, made by curl_spline.comp's moving variant),
// mixed linearly between nodes; 0 evaluates the flow itself at every stage (curl mode procedural).
// WARP_GRID 1 (covers finer than --warp-grid): the trajectories start at the nodes of the warp
// grid, u_grid_cells per face edge with SPLINE_MARGIN + 1 beyond each edge as the curl's samples
// (curl_spline.glsl), and both outputs are 6-layer arrays of those samples; the curl spline's
// prefilter and warp_from_grid.comp then bring them to the texels, with the noise grid in their w:
// octaves [0, u_grid_octaves) of each layer's cover noise at its point (docs/numerics.md, "The
// noise grid"; 0 where the grid carries none).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 2) uniform writeonly image2DArray warp_field;
layout(rgba32f, binding = 3) uniform writeonly image2DArray young_warp_field;
#ifndef MOVING_SPLINE
#define MOVING_SPLINE 1
#endif
#ifndef WARP_GRID
#define WARP_GRID 0
#endif

// Both variants' libraries before the #if: the host expands each file once (the first include
// wins, active or not), so a file first included in an inactive branch would be missing.
#include "../lib/prelude.glsl"
#include "../lib/parameters.glsl"
#include "../lib/curl_spline.glsl"
#include "../lib/worley_fbm.glsl"
#include "cube_tile.glsl"
uniform CurlParams u_curl;
uniform FlowMotion u_motion;
#if MOVING_SPLINE
layout(rgba32f, binding = 4) uniform readonly image2DArray flow_splines;
uniform float u_first_node_time;  // flow units from the motion's origin, as u_time
uniform float u_node_spacing;
#define WarpField SplineImage
vec2 zonal_drift(float z, CurlParams params);  // moving_flow.glsl, included below
// The grids turned with the drift between their time and t (curl_spline.glsl).
vec3 moving_velocity(vec3 w, float t, SplineImage splines) {
  float turn = u_motion.drift * zonal_drift(clamp(w.z, -1.0f, 1.0f), u_curl).x * u_node_spacing;
  return spline_velocity_in_time(w, splines, (t - u_first_node_time) / u_node_spacing, turn);
}
#define FLOW_SOURCE flow_splines
#endif
#include "../lib/moving_flow.glsl"

uniform float u_time;     // the frame's time, flow units from the motion's origin
uniform float u_old_age;  // the older layer's age (flow units)
uniform float u_young_age;
uniform int u_young_steps;  // RK4 steps back to the younger layer's age
uniform int u_older_steps;  // and on from there to the older layer's
#if WARP_GRID
uniform int u_grid_cells;  // the warp grid's nodes per face edge inside the face
uniform int u_grid_octaves;  // the cover noise's octaves that the grid carries
uniform FbmParams u_cover;   // the older layer's noise (the density pass's u_cover)
uniform FbmParams u_young_cover;
uniform vec3 u_density_offset;  // the density pass's u_noise_offset
#endif
#if !MOVING_SPLINE
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host
#define FLOW_SOURCE MovingCurl(u_curl, u_noise_offset, u_motion)
#endif

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  ivec3 extent = imageSize(warp_field);
  if (texel.x >= extent.x || texel.y >= extent.y) return;
#if WARP_GRID
  vec3 x = curl_spline_node(texel.z, texel.x, texel.y, SPLINE_MARGIN + 1, u_grid_cells);
#else
  vec3 x = image_texel_direction(texel);
#endif
  // One trajectory: back to the younger layer's birth, then on to the older layer's.
  vec3 young = back_trajectory(x, u_time, u_young_age, u_young_steps, FLOW_SOURCE);
  vec3 old = back_trajectory(young, u_time - u_young_age, u_old_age - u_young_age, u_older_steps, FLOW_SOURCE);
#if WARP_GRID
  float young_sum = inverted_worley_octaves(normalize(young) + u_density_offset, u_young_cover, 0, u_grid_octaves);
  float old_sum = inverted_worley_octaves(normalize(old) + u_density_offset, u_cover, 0, u_grid_octaves);
#else
  float young_sum = 0.0f, old_sum = 0.0f;
#endif
  imageStore(young_warp_field, texel, vec4(young, young_sum));
  imageStore(warp_field, texel, vec4(old, old_sum));
}
