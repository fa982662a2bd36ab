#version 450
// Pass 2: the curl vector v = n x grad phi at every texel direction n, and in w the flow's
// cyclonic depth, which the density pass adds (curl_flow.glsl); with CURL_FROM_SPLINE 1
// the velocity the spline warp uses there instead (curl_mode spline: the diagnosis then judges
// the flow that was integrated, and no procedural evaluation is made per texel).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 1) uniform writeonly image2DArray curl_field;
#ifndef CURL_FROM_SPLINE
#define CURL_FROM_SPLINE 0
#endif
// CURL_MOVING 1: the moving flow at the frame's time (--flow moving; moving_flow.glsl).
#ifndef CURL_MOVING
#define CURL_MOVING 0
#endif
// Both variants' libraries come in before the #if: the host expands each file once (the first
// include wins, active or not), so a file first included inside an inactive branch would be
// missing from the other.
#include "../lib/curl_flow.glsl"
#include "../lib/moving_flow.glsl"
#include "../lib/curl_spline.glsl"
#include "cube_tile.glsl"
#if CURL_FROM_SPLINE
// With CURL_MOVING, the moving flow's grids at time nodes (shaders/cover/moving_warp.comp).
layout(rgba32f, binding = 2) uniform readonly image2DArray curl_spline;
#if CURL_MOVING
uniform float u_time;  // flow units from the motion's origin
uniform float u_first_node_time;
uniform float u_node_spacing;
uniform CurlParams u_curl;  // for the drift that turns the grids (curl_spline.glsl)
uniform FlowMotion u_motion;
#endif
#else
uniform CurlParams u_curl;
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host
#if CURL_MOVING
uniform FlowMotion u_motion;
uniform float u_time;  // flow units from u_motion's origin
#endif
#endif

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  ivec3 extent = imageSize(curl_field);
  if (texel.x >= extent.x || texel.y >= extent.y) return;
  vec3 n = image_texel_direction(texel);
#if CURL_FROM_SPLINE && CURL_MOVING
  float node = (u_time - u_first_node_time) / u_node_spacing;
  float turn = u_motion.drift * zonal_drift(clamp(n.z, -1.0f, 1.0f), u_curl).x * u_node_spacing;
  imageStore(curl_field, texel,
             vec4(spline_velocity_in_time(n, curl_spline, node, turn),
                  sample_curl_spline_in_time(n, curl_spline, node, turn).w));
#elif CURL_FROM_SPLINE
  imageStore(curl_field, texel, vec4(spline_velocity(n, curl_spline), sample_curl_spline(n, curl_spline).w));
#elif CURL_MOVING
  imageStore(curl_field, texel, moving_curl_flow(n, u_curl, u_noise_offset, u_motion, u_time));
#else
  imageStore(curl_field, texel, curl_flow_shifted(n, u_curl, u_noise_offset));
#endif
}
