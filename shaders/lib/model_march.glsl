// The preview of a cloud model's density volume (shaders/model/preview.comp): view rays through
// the volume's box with the regional marcher's light model (cloud_march.glsl): a shadow ray
// towards the sun per sample (quadratically spaced), sun_scattering's multiple-scattering
// octaves, the sky's ambient light from above and the ground's from below, albedo 0.99.
// docs/model.md, "Preview". The density volume is the parameter `density` (DensityVolume:
// sampled at uvw in [0, 1]^3, trilinear, clamped to the edge).
#ifndef NEPHELE_MODEL_MARCH_GLSL
#define NEPHELE_MODEL_MARCH_GLSL
#include "prelude.glsl"
#include "atmosphere.glsl"
#include "cloud_density.glsl"
#include "hash.glsl"

// Camera and light of a preview; lengths in metres in the volume's frame ([0, extent]^3, z up).
struct ModelView {
  vec3 origin;           // the camera
  vec3 forward;          // the view's axes
  vec3 right;
  vec3 up;
  float tan_half_fov;
  vec3 sun;              // unit direction towards the sun
  vec3 sunlight;         // solar irradiance reaching the cloud
  vec3 ambient;          // sky irradiance on a horizontal surface
  vec3 ground_radiance;  // radiance of the ground below the cloud
  vec3 background;       // radiance seen where the cloud lets light through
  float extent;          // the box's edge
  float extinction;      // 1/m at density 1
  int view_steps;        // samples across the box's edge (a ray gets its share)
  int light_steps;       // samples towards the sun
};

// Entry and exit distances (x, y) of the ray o + t d, t >= 0, through the box [lo, hi]; empty
// when x >= y. Direction components of 0 are replaced by 1e-20 (same sign rules on both sides).
vec2 ray_box(vec3 o, vec3 d, vec3 lo, vec3 hi) {
  vec3 safe = vec3(abs(d.x) > 1e-20f ? d.x : 1e-20f, abs(d.y) > 1e-20f ? d.y : 1e-20f,
                   abs(d.z) > 1e-20f ? d.z : 1e-20f);
  vec3 t0 = (lo - o) / safe;
  vec3 t1 = (hi - o) / safe;
  vec3 near = min(t0, t1);
  vec3 far = max(t0, t1);
  return vec2(max(max(near.x, near.y), max(near.z, 0.0f)), min(min(far.x, far.y), far.z));
}

// Extinction (1/m) at x.
float model_extinction(vec3 x, IN(ModelView) v, IN(DensityVolume) density) {
  return v.extinction * texture(density, x / v.extent).x;
}

// Optical depth from x towards the sun to the box's edge, samples spaced as light_sample says.
float model_light_depth(vec3 x, IN(ModelView) v, IN(DensityVolume) density) {
  float length_to_exit = ray_box(x, v.sun, vec3(0.0f), vec3(v.extent)).y;
  float tau = 0.0f;
  for (int i = 0; i < v.light_steps; ++i) {
    vec2 s = light_sample(i, v.light_steps, length_to_exit);  // (distance, step), quadratic
    tau += model_extinction(x + s.x * v.sun, v, density) * s.y;
  }
  return tau;
}

// Radiance the cloud sends along the unit view direction d (xyz) and the transmittance through
// it (w). jitter in [0, 1): the samples' offset within their steps.
vec4 model_march(vec3 d, float jitter, IN(ModelView) v, IN(DensityVolume) density) {
  vec2 interval = ray_box(v.origin, d, vec3(0.0f), vec3(v.extent));
  vec3 radiance = vec3(0.0f);
  float transmittance = 1.0f;
  if (interval.x >= interval.y) return vec4(radiance, transmittance);
  int steps = max(1, int(ceil(float(v.view_steps) * (interval.y - interval.x) / v.extent)));
  float ds = (interval.y - interval.x) / float(steps);
  float nu = dot(d, v.sun);
  for (int i = 0; i < steps && transmittance > 0.01f; ++i) {
    vec3 x = v.origin + (interval.x + (float(i) + jitter) * ds) * d;
    float sigma = model_extinction(x, v, density);
    if (sigma <= 0.0f) continue;
    float tau = v.light_steps > 0 ? model_light_depth(x, v, density) : 0.0f;
    // As cloud_march.glsl: the sky's radiance E/pi over the upper half (dimmer towards the base),
    // the ground's over the lower half, isotropic scattering.
    float h = clamp(x.z / v.extent, 0.0f, 1.0f);
    vec3 ambient = 0.5f * (v.ambient * ((0.4f + 0.6f * h) / PI_F) + v.ground_radiance);
    vec3 source = 0.99f * sigma * (v.sunlight * sun_scattering(tau, nu) + ambient);
    float step_transmittance = exp(-sigma * ds);
    radiance += transmittance * source * (1.0f - step_transmittance) / sigma;
    transmittance *= step_transmittance;
  }
  return vec4(radiance, transmittance);
}

// The unit view direction through `position`, in pixels of an image of `size` from its top-left
// corner (a pixel's centre is its index + 0.5); tan_half_fov spans the width. The preview's
// pixels and nephele view's picking (a cursor position) share it.
vec3 model_ray(vec2 position, ivec2 size, IN(ModelView) v) {
  vec2 uv = position / vec2(size);
  float aspect = float(size.y) / float(size.x);
  vec2 xy = vec2(2.0f * uv.x - 1.0f, (1.0f - 2.0f * uv.y) * aspect) * v.tan_half_fov;
  return normalize(v.forward + xy.x * v.right + xy.y * v.up);
}

// The pixel's radiance (RGB) over the background and the cloud's opacity (A).
vec4 model_pixel(ivec2 pixel, ivec2 size, IN(ModelView) v, IN(DensityVolume) density) {
  vec3 d = model_ray(vec2(pixel) + 0.5f, size, v);
  float jitter = hash_to_unit3(pcg3d(uvec3(uvec2(pixel), 7u))).x;
  vec4 cloud = model_march(d, jitter, v, density);
  return vec4(vec3(cloud) + cloud.w * v.background, 1.0f - cloud.w);
}

#endif
