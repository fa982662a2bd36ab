#version 450
// The curl grid of `curl_mode spline` (shaders/lib/curl_spline.glsl), one 2D array layer per
// cube face, in two dispatches:
//   CURL_SPLINE_PREFILTER 0: the procedural curl (and the cyclonic depth in w) at the nodes of each face's grid, continued
//     SPLINE_MARGIN + 1 nodes past the face's edges (the prefilter reads one node further);
//   CURL_SPLINE_PREFILTER 1: the spline's coefficients, the samples prefiltered along both axes.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
#ifndef CURL_SPLINE_PREFILTER
#define CURL_SPLINE_PREFILTER 0
#endif
uniform int u_cells;  // nodes per face edge inside the face
#include "../lib/curl_flow.glsl"
#include "../lib/curl_spline.glsl"
#include "../lib/moving_flow.glsl"
// CURL_SPLINE_MOVING 1 (--flow moving): the samples of one time node's grid, the flow at
// u_node_time (flow units from u_motion's origin, which the host takes from the node's own time, so
// that a node's grid is the same in every frame that uses it); the prefilter writes a node's
// coefficients into layers u_first_layer .. u_first_layer + 5 of the grids of all nodes.
#ifndef CURL_SPLINE_MOVING
#define CURL_SPLINE_MOVING 0
#endif

#if CURL_SPLINE_PREFILTER == 0
layout(rgba32f, binding = 0) uniform writeonly image2DArray samples;
uniform CurlParams u_curl;
uniform vec3 u_noise_offset;  // reduced modulo the lattice period by the host
#if CURL_SPLINE_MOVING
uniform FlowMotion u_motion;
uniform float u_node_time;
#endif

void main() {
  ivec3 node = ivec3(gl_GlobalInvocationID);
  int extent = imageSize(samples).x;
  if (node.x >= extent || node.y >= extent) return;
  vec3 n = curl_spline_node(node.z, node.x, node.y, SPLINE_MARGIN + 1, u_cells);
#if CURL_SPLINE_MOVING
  imageStore(samples, node, moving_curl_flow(n, u_curl, u_noise_offset, u_motion, u_node_time));
#else
  imageStore(samples, node, curl_flow_shifted(n, u_curl, u_noise_offset));
#endif
}
#else
layout(rgba32f, binding = 0) uniform readonly image2DArray samples;
layout(rgba32f, binding = 1) uniform writeonly image2DArray coefficients;
uniform int u_first_layer;  // CURL_SPLINE_MOVING: the node's first layer among all nodes' (else 0)

vec4 prefiltered_row(ivec3 at) {
  return prefilter_cubic_bspline(imageLoad(samples, at), imageLoad(samples, at + ivec3(1, 0, 0)),
                                 imageLoad(samples, at + ivec3(2, 0, 0)));
}

void main() {
  ivec3 node = ivec3(gl_GlobalInvocationID);
  int extent = imageSize(coefficients).x;
  if (node.x >= extent || node.y >= extent) return;
  // Coefficient (i, j) is sample (i + 1, j + 1): the samples' margin is one node wider.
  imageStore(coefficients, node + ivec3(0, 0, u_first_layer),
             prefilter_cubic_bspline(prefiltered_row(node), prefiltered_row(node + ivec3(0, 1, 0)),
                                     prefiltered_row(node + ivec3(0, 2, 0))));
}
#endif
