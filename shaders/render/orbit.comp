#version 450
// The orbit view (docs/orbit_view.md): a textured planet, a volumetric cloud shell whose density
// follows the global cover (a cube map), cloud shadows on the ground, city lights on the night
// side and the single-scattering atmosphere of shaders/lib/atmosphere.glsl in front of both.
// One invocation per pixel. Positions are relative to the camera: the host computes the camera
// and planet in double and hands over the planet's centre relative to the camera as float, and
// for each sphere q = |camera - centre|^2 - r^2 (exact in double; in float it would cancel
// catastrophically near the ground). Axes are Earth-centred, Earth-fixed (+Z north, +X latitude
// 0 longitude 0), as the cover's cube map is.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D radiance_image;
layout(binding = 1) uniform sampler2D day_texture;    // equirect, linear RGB, row 0 = north
layout(binding = 2) uniform sampler2D night_texture;  // equirect, linear RGB (city lights)
layout(binding = 3) uniform samplerCube cover_map;    // coverage in [0, 1], GL face convention
layout(binding = 4) uniform sampler3D detail_noise;   // 32^3 value noise in [0, 1], repeating
layout(binding = 5) uniform sampler2D water_texture;  // equirect, fraction of open water (sun glint)

#include "../lib/atmosphere.glsl"
#include "../lib/cube_bspline.glsl"
#include "../lib/equirect_mapping.glsl"
#include "../lib/hash.glsl"
#include "../lib/sun_glint.glsl"

uniform vec3 u_centre;         // planet centre relative to the camera, m
uniform float u_q_ground;      // |camera - centre|^2 - r^2 for the ground, cloud base, cloud top
uniform float u_q_base;        // and atmosphere top spheres (double on the host), m^2
uniform float u_q_top;
uniform float u_q_atmosphere;
uniform float u_radius;        // planet radius, m
uniform float u_cloud_base;    // altitude of the shell's bottom, m
uniform float u_cloud_top;     // altitude of the shell's top, m
uniform float u_extinction;    // cloud extinction at density 1, 1/m
uniform vec3 u_forward;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_tan_half_fov;
uniform float u_pixel_angle;   // radians per pixel
uniform vec3 u_sun;            // unit direction towards the sun
uniform float u_night_lights;  // radiance of a city-light texel of value 1
uniform float u_sea_wind;      // wind over the sea, m/s (the glint's facet slopes)
uniform float u_cover_texel;   // arc length of one cover texel on the ground, m
uniform float u_cover_size;    // cover texels along a face edge
uniform float u_day_texel;     // arc length of one day-texture texel, m
uniform int u_cloud_steps;
uniform int u_shadow_steps;
uniform int u_sky_steps;

const float CLOUD_ALBEDO = 0.95f;

// (near, far) distances to a sphere along unit d, from b = dot(camera - centre, d) and q; near >
// far when the ray misses. The root of larger magnitude first, the other as q / root (Vieta):
// no cancellation for a camera 1 m above the ground.
vec2 sphere_hits(float b, float q) {
  float disc = b * b - q;
  if (disc < 0.0f) return vec2(1.0f, -1.0f);
  float s = sqrt(disc);
  float big = b >= 0.0f ? -b - s : -b + s;
  if (abs(big) < 1.0e-30f) return vec2(-b - s, -b + s);
  float other = q / big;
  return vec2(min(big, other), max(big, other));
}

// Parts of [0, limit] between the spheres of q_in and q_out (as ray_shell).
vec4 shell_intervals(float b, float q_in, float q_out, float limit) {
  vec2 outer = sphere_hits(b, q_out);
  if (outer.x > outer.y) return vec4(0.0f);
  float a = max(outer.x, 0.0f);
  float e = min(outer.y, limit);
  if (a >= e) return vec4(0.0f);
  vec2 inner = sphere_hits(b, q_in);
  if (inner.x > inner.y || inner.y <= a || inner.x >= e) return vec4(a, e, 0.0f, 0.0f);
  return vec4(a, max(a, inner.x), min(e, inner.y), e);
}

const float DETAIL_CELL = 1600.0f;  // m: the detail noise's coarse cell (the fine one is a quarter)

float cover_lod(float footprint) { return max(log2(max(footprint, 1.0f) / u_cover_texel), 0.0f); }

// The cover in direction n at mip level `lod`. Where a cover texel spans more than a sample
// (lod < 1) the base level is filtered by the cubic B-spline (cube_bspline.glsl): trilinear
// lookups alone show the texel grid as a staircase of straight edges from low orbit. Between
// lod 0 and 1 the two are blended, so nothing switches with distance.
float cover_at(vec3 n, float lod) {
  if (lod >= 1.0f) return textureLod(cover_map, n, lod).r;
  CubeBsplineTaps taps = cube_bspline_taps(n, u_cover_size);
  float c00 = textureLod(cover_map, taps.d00, 0.0f).r, c10 = textureLod(cover_map, taps.d10, 0.0f).r;
  float c01 = textureLod(cover_map, taps.d01, 0.0f).r, c11 = textureLod(cover_map, taps.d11, 0.0f).r;
  float smooth_cover = mix(mix(c00, c10, taps.g.x), mix(c01, c11, taps.g.x), taps.g.y);
  // Close up (lod 0, most samples below 2000 km) the mipmapped lookup has no weight: not fetched.
  return lod > 0.0f ? mix(smooth_cover, textureLod(cover_map, n, lod).r, lod) : smooth_cover;
}

// Cloud density in [0, 1] at p (relative to the planet centre) for a sample that stands for
// `footprint` metres: the cover at p's direction sets how high the column reaches (0.15 of the
// shell at the thinnest, all of it at coverage 1) and how dense it is; the base and the top are
// soft. Close up, two octaves of value noise erode it (more where the cover is thin); they fade
// out smoothly where a sample covers a noise cell, so nothing switches with distance.
float cloud_density(vec3 p, float footprint) {
  float r = length(p);
  float hf = (r - u_radius - u_cloud_base) / (u_cloud_top - u_cloud_base);
  if (hf <= 0.0f || hf >= 1.0f) return 0.0f;
  float c = cover_at(p / r, cover_lod(footprint));
  if (c <= 0.0f) return 0.0f;
  float top = 0.15f + 0.85f * c;
  float column = smoothstep(0.0f, 0.08f, hf) * (1.0f - smoothstep(0.75f * top, top, hf));
  float density = smoothstep(0.0f, 0.15f, c) * (0.4f + 0.6f * c) * column;
  float coarse = 1.0f - smoothstep(0.5f * DETAIL_CELL, 2.0f * DETAIL_CELL, footprint);
  if (coarse > 0.0f) {
    float fine = 1.0f - smoothstep(0.125f * DETAIL_CELL, 0.5f * DETAIL_CELL, footprint);
    float n1 = textureLod(detail_noise, p / (32.0f * DETAIL_CELL), 0.0f).r;
    float n2 = textureLod(detail_noise, p / (8.0f * DETAIL_CELL) + vec3(0.37f), 0.0f).r;
    float n = 0.7f * n1 + 0.3f * mix(0.5f, n2, fine);
    float erosion = clamp((n - 0.45f * (1.0f - c) - 0.1f) * 3.0f, 0.0f, 1.0f);
    density *= mix(1.0f, erosion, coarse);
  }
  return density;
}

// Optical depth of the shell from p (relative to the centre) towards the sun, `steps` samples
// spread over the path to the shell's top (at most 60 km: beyond, low sun light is gone anyway).
float optical_depth_to_sun(vec3 p, int steps, float footprint) {
  float b = dot(p, u_sun);
  float r_top = u_radius + u_cloud_top;
  float q = dot(p, p) - r_top * r_top;
  vec2 top = sphere_hits(b, q);
  float length_to_top = min(max(top.y, 0.0f), 60000.0f);
  float start = 0.0f;
  if (dot(p, p) < (u_radius + u_cloud_base) * (u_radius + u_cloud_base)) {
    float r_base = u_radius + u_cloud_base;
    start = max(sphere_hits(b, dot(p, p) - r_base * r_base).y, 0.0f);
  }
  float span = max(length_to_top - start, 0.0f);
  float depth = 0.0f;
  for (int i = 0; i < steps; ++i) {
    float t0 = float(i) / float(steps), t1 = float(i + 1) / float(steps);
    // Quadratic spacing: short steps near p, where the light's shadow detail is.
    float s = start + span * 0.25f * (t0 + t1) * (t0 + t1);
    depth += cloud_density(p + s * u_sun, footprint) * span * (t1 * t1 - t0 * t0);
  }
  return depth * u_extinction;
}

// Share of the light that gets through a cloud layer of optical depth tau by multiple scattering
// (two-stream, asymmetry 0.85: 1 / (1 + 0.75 x 0.15 tau)).
float diffuse_transmission(float tau) { return 1.0f / (1.0f + 0.1125f * tau); }

float hg(float nu, float g) { return henyey_greenstein(nu, g); }

// Ambient light of the sky (isotropic radiance) at a point with local up n: a blue share of the
// sunlight that fades across the terminator.
vec3 sky_ambient(vec3 n) {
  float mu = dot(n, u_sun);
  return solar_irradiance() * vec3(0.030f, 0.045f, 0.075f) * smoothstep(-0.12f, 0.35f, mu);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(radiance_image);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec2 uv = (vec2(pixel) + 0.5f) / vec2(size);
  float aspect = float(size.y) / float(size.x);
  vec2 xy = vec2(2.0f * uv.x - 1.0f, (1.0f - 2.0f * uv.y) * aspect) * u_tan_half_fov;
  vec3 d = normalize(u_forward + xy.x * u_right + xy.y * u_up);

  vec3 oc = -u_centre;  // camera relative to the centre
  float b = dot(oc, d);
  vec2 ground = sphere_hits(b, u_q_ground);
  bool hits_ground = ground.x <= ground.y && ground.x > 0.0f;
  vec2 air = sphere_hits(b, u_q_atmosphere);
  float air_start = max(air.x, 0.0f);
  float ray_end = hits_ground ? ground.x : max(air.y, 0.0f);
  bool in_air = air.x <= air.y && air.y > 0.0f;

  // The cloud shell: up to two intervals, the steps shared in proportion to their lengths.
  float jitter = hash_to_unit3(pcg3d(uvec3(uvec2(pixel), 11u))).x;
  vec4 shell = shell_intervals(b, u_q_base, u_q_top, ray_end);
  float len0 = max(shell.y - shell.x, 0.0f), len1 = max(shell.w - shell.z, 0.0f);
  vec3 cloud_light = vec3(0.0f);
  float cloud_transmittance = 1.0f;
  float weighted_distance = 0.0f, weight_sum = 0.0f;
  if (len0 + len1 > 0.0f) {
    int steps = max(u_cloud_steps, 1);
    float dt = (len0 + len1) / float(steps);
    vec3 sun_at_cloud = vec3(-1.0f);  // sunlight at the shell, computed at the first dense sample
    for (int i = 0; i < steps && cloud_transmittance > 0.005f; ++i) {
      float s = (float(i) + jitter) * dt;
      float t = s < len0 ? shell.x + s : shell.z + (s - len0);
      vec3 p = oc + t * d;
      float footprint = max(t * u_pixel_angle, 0.25f * dt);
      float density = cloud_density(p, footprint);
      if (density <= 0.0f) continue;
      vec3 n = normalize(p);
      if (sun_at_cloud.x < 0.0f) sun_at_cloud = solar_irradiance() * transmittance_to_space(p, u_sun, u_radius);
      float sigma = density * u_extinction;
      float tau_light = optical_depth_to_sun(p, 4, footprint);
      float nu = dot(d, u_sun);
      float phase = 0.7f * hg(nu, 0.6f) + 0.3f * hg(nu, -0.3f);
      // Single scattering plus the light that diffuses through the cloud (multiple scattering,
      // isotropic), with the two-stream transmission 1 / (1 + 0.75 (1 - g) tau) of a cloud of
      // asymmetry g = 0.85.
      vec3 source = CLOUD_ALBEDO * (sun_at_cloud * (phase * exp(-tau_light) + 0.3f * diffuse_transmission(tau_light)) +
                                    sky_ambient(n));
      float step_transmittance = exp(-sigma * dt);
      cloud_light += cloud_transmittance * source * (1.0f - step_transmittance);
      weighted_distance += t * cloud_transmittance * (1.0f - step_transmittance);
      weight_sum += cloud_transmittance * (1.0f - step_transmittance);
      cloud_transmittance *= step_transmittance;
    }
  }
  float cloud_distance = weight_sum > 0.0f ? weighted_distance / weight_sum : 0.0f;

  // The ground: texture, sunlight through air and cloud, sky light, city lights at night.
  vec3 background = vec3(0.0f);
  if (hits_ground) {
    vec3 g = oc + ground.x * d;
    vec3 n = normalize(g);
    float footprint = max(ground.x * u_pixel_angle / max(-dot(n, d), 0.05f), 1.0f);
    float day_lod = max(log2(footprint / u_day_texel), 0.0f);
    vec2 tex = equirect_uv(n);
    vec3 albedo = textureLod(day_texture, tex, day_lod).rgb;
    vec3 lights = textureLod(night_texture, tex, day_lod).rgb;
    float mu = dot(n, u_sun);
    vec3 direct = vec3(0.0f);
    if (mu > -0.02f) {
      // Cloud shadow: the shell's optical depth towards the sun; some light diffuses through.
      float tau = optical_depth_to_sun(g, u_shadow_steps, footprint);
      float shadow = exp(-tau) + (1.0f - exp(-tau)) * diffuse_transmission(tau);
      direct = solar_irradiance() * transmittance_to_space(g + 1.0f * n, u_sun, u_radius) * max(mu, 0.0f) * shadow;
    }
    vec3 sky = PI_F * sky_ambient(n);
    float night = 1.0f - smoothstep(-0.1f, 0.05f, mu);
    background = albedo / PI_F * (direct + sky) + u_night_lights * night * lights;
    // Sun glint: the sea's facets mirror the direct sunlight (already through air and cloud) into
    // the view, radiance = BRDF x irradiance on the horizontal.
    float water = textureLod(water_texture, tex, day_lod).r;
    if (water > 0.0f && mu > 0.0f) background += water * sun_glint_brdf(n, -d, u_sun, u_sea_wind) * direct;
  }

  vec3 radiance;
  if (in_air && ray_end > air_start) {
    vec3 start = oc + air_start * d;
    vec3 inscatter_total, inscatter_split, transmittance_total, transmittance_split;
    float split = weight_sum > 0.0f ? cloud_distance - air_start : 0.0f;
    sky_single_scattering(start, d, ray_end - air_start, split, u_sun, u_radius, u_sky_steps, inscatter_total,
                          inscatter_split, transmittance_total, transmittance_split);
    radiance = inscatter_split + transmittance_split * cloud_light +
               cloud_transmittance * (inscatter_total - inscatter_split + transmittance_total * background);
  } else {
    radiance = cloud_light + cloud_transmittance * background;
  }
  imageStore(radiance_image, pixel, vec4(radiance, 1.0f - cloud_transmittance));
}
