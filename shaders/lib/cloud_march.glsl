// Ray marching of the cloud layers and the sky, one view ray per pixel (the pass is
// shaders/render/clouds.comp; docs/rendering.md describes the method). Local frame: east,
// north, up with the camera at the origin; the Earth is the sphere osculating the WGS84
// ellipsoid at the viewpoint, its centre straight below. The including file defines how the
// two textures are read:
//   MARCH_SOURCES_PARAM   extra trailing parameter(s) naming the textures (empty in GLSL)
//   MARCH_SOURCES_ARG     the matching argument(s) (empty in GLSL)
//   NOISE_LOD(x, lod)     vec4 (RG used) of the noise volume at x (one period per unit,
//                         repeating): trilinear within and linear between mip levels at lod
//   WEATHER_COVERAGE(uv, channel)  float: the weather field's channel at uv in [0, 1]^2,
//                         bilinear, clamped to the edge
//   MARCH_TERRAIN_ARG     the ground's height texture as terrain.glsl takes it (empty in GLSL;
//                         the includer also defines terrain.glsl's hooks)
#ifndef NEPHELE_CLOUD_MARCH_GLSL
#define NEPHELE_CLOUD_MARCH_GLSL
#include "prelude.glsl"
#include "render_types.glsl"
#include "atmosphere.glsl"
#include "cloud_density.glsl"
#include "hash.glsl"
#include "ray_sphere.glsl"
#include "terrain.glsl"

// Mesa's llvmpipe stops every loop of an invocation after 65535 iterations in all, so pixels
// whose loops run (or would run) that long are cut short on that driver (docs/rendering.md);
// the marcher counts its iterations and the pass counts such pixels for the host to warn.
const int LOOP_LIMIT = 65535;
const int VIEW_REFINE = 2;  // sub-steps of a coarse view step that holds cloud (docs/rendering.md)

bool loop_limited(int loop_count) { return loop_count >= LOOP_LIMIT; }

vec3 view_direction(ivec2 pixel, ivec2 size, IN(MarchParams) m) {
  vec2 uv = (vec2(pixel) + 0.5f) / vec2(size);
  if (m.panorama != 0) {
    // 360 x 180 equirectangular view sphere, the heading at the centre, up at the top.
    float azimuth = m.heading + (uv.x - 0.5f) * 2.0f * PI_F;
    float elevation = (0.5f - uv.y) * PI_F;
    return vec3(cos(elevation) * sin(azimuth), cos(elevation) * cos(azimuth), sin(elevation));
  }
  float aspect = float(size.y) / float(size.x);
  vec2 xy = vec2(2.0f * uv.x - 1.0f, (1.0f - 2.0f * uv.y) * aspect) * m.tan_half_fov;
  return normalize(m.forward + xy.x * m.right + xy.y * m.up);
}

float coverage_at(vec3 p, int channel, IN(MarchParams) m MARCH_SOURCES_PARAM) {
  vec2 uv = 0.5f + 0.5f * vec2(p) / m.weather_extent;
  return WEATHER_COVERAGE(uv, channel);
}

// A layer's shape-noise lookups at a point: the height fraction h in the layer, the coverage c,
// the shape value (0 outside the layer or where the weather gives no cover) and the base detail
// value, with the noise coordinates and mip level that a detail lookup goes on with.
struct ShapeSample {
  float h, c, shape, detail, lod;
  vec3 coordinates;
};

// footprint: the length one sample stands for (the pixel's width at that distance, or the step),
// which picks the noise volume's mip level so that distant clouds do not alias into speckle.
ShapeSample shape_at(vec3 p, vec3 centre, int layer, float footprint, IN(MarchParams) m MARCH_SOURCES_PARAM) {
  LayerParams l = m.layers[layer];
  ShapeSample q;
  float altitude = length(p - centre) - m.earth_radius;
  q.h = (altitude - l.base) / (l.top - l.base);
  q.c = coverage_at(p, l.channel, m MARCH_SOURCES_ARG);
  q.shape = 0.0f;
  q.detail = 0.0f;
  q.lod = 0.0f;
  q.coordinates = vec3(0.0f);
  if (q.c <= 0.0f || q.h < 0.0f || q.h > 1.0f) return q;
  // Noise coordinates in the wind's frame, moved by the wind's offset (tau).
  vec2 along_across = vec2(dot(vec2(p), l.wind), dot(vec2(p), vec2(-l.wind.y, l.wind.x))) - l.noise_offset;
  vec2 period = noise_period(l.type);
  q.coordinates = vec3(along_across / period, altitude / period.y);
  float texel = period.x / m.noise_texels;
  q.lod = log2(max(footprint / texel, 1.0f));
  vec2 noise = vec2(NOISE_LOD(q.coordinates, q.lod));
  // A second lookup at an incommensurate, rotated scale (7.3 periods) breaks the volume's tiling,
  // which would otherwise line distant clouds up in a regular array.
  vec3 x = q.coordinates;
  vec3 macro_coordinates = vec3(0.0822f * x.x + 0.0548f * x.y, -0.0548f * x.x + 0.0822f * x.y, 0.1371f * x.z + 0.37f);
  float macro = NOISE_LOD(macro_coordinates, max(q.lod - 3.0f, 0.0f)).x;
  q.shape = uniform_from_mix(mix(noise.x, macro, 0.4f), 0.4f);
  q.detail = noise.y;
  return q;
}

// The largest extinction the layer can have at the sample whatever the detail noise (every
// density grows with it, tested): zero over most of the sky, and it needs no detail lookup.
// (cloud_density is zero outside the layer and without cover.)
float extinction_bound(int layer, IN(ShapeSample) q, IN(MarchParams) m) {
  LayerParams l = m.layers[layer];
  return l.extinction * cloud_density(l.type, q.h, q.c, q.shape, 1.0f, l.morph);
}

float extinction_bound_at(vec3 p, vec3 centre, int layer, float footprint, IN(MarchParams) m MARCH_SOURCES_PARAM) {
  return extinction_bound(layer, shape_at(p, centre, layer, footprint, m MARCH_SOURCES_ARG), m);
}

// Extinction (1/m) of a layer at p. fine: also read the detail noise (the light march does
// without it).
float density_at(vec3 p, vec3 centre, int layer, float footprint, bool fine, IN(MarchParams) m MARCH_SOURCES_PARAM) {
  LayerParams l = m.layers[layer];
  ShapeSample q = shape_at(p, centre, layer, footprint, m MARCH_SOURCES_ARG);
  // Where even the bound is zero (most of the sky) the detail lookup is skipped.
  if (extinction_bound(layer, q, m) <= 0.0f) return 0.0f;
  float detail = fine ? NOISE_LOD(q.coordinates * 4.0f, q.lod + 2.0f).y : q.detail;
  return l.extinction * cloud_density(l.type, q.h, q.c, q.shape, mix(q.detail, detail, 0.5f), l.morph);
}

// Optical depth from p towards the sun within the same layer (other layers' shadows are left out).
float optical_depth_to_sun(vec3 p, vec3 centre, int layer, IN(MarchParams) m MARCH_SOURCES_PARAM) {
  LayerParams l = m.layers[layer];
  float length_to_exit = min((l.top - l.base) / max(m.sun.z, 0.15f), 4000.0f);
  float tau = 0.0f;
  for (int i = 0; i < m.light_steps; ++i) {
    vec2 s = light_sample(i, m.light_steps, length_to_exit);  // (distance, step), quadratic
    tau += density_at(p + s.x * m.sun, centre, layer, s.y, false, m MARCH_SOURCES_ARG) * s.y;
  }
  return tau;
}

// The intervals of a view ray inside each layer, in order of distance (start, end in .x, .y):
// a ray crosses a layer's shell in up to two intervals.
struct RayIntervals {
  vec4 bounds[2 * MAX_LAYERS];
  int layer[2 * MAX_LAYERS];
  int count;
};

RayIntervals layer_intervals(vec3 d, vec3 centre, float cloud_limit, IN(MarchParams) m) {
  RayIntervals r;
  r.count = 0;
  for (int layer = 0; layer < m.layer_count; ++layer) {
    LayerParams l = m.layers[layer];
    vec4 s = ray_shell(vec3(0.0f), d, centre, m.earth_radius + l.base, m.earth_radius + l.top, cloud_limit);
    for (int k = 0; k < 2; ++k) {
      float a = max(k == 0 ? s.x : s.z, l.min_distance);
      float b = k == 0 ? s.y : s.w;
      if (a < b) {
        // Insertion into the sorted list.
        int j = r.count;
        r.count += 1;
        while (j > 0 && r.bounds[j - 1].x > a) {
          r.bounds[j] = r.bounds[j - 1];
          r.layer[j] = r.layer[j - 1];
          --j;
        }
        r.bounds[j] = vec4(a, b, 0.0f, 0.0f);
        r.layer[j] = layer;
      }
    }
  }
  return r;
}

// What the march of the layers along one view ray gives: the radiance the clouds send towards
// the camera, the transmittance through them, the clouds' mean distance (weighted by what each
// step absorbs; 0 without cloud), and the loop iterations it took.
struct CloudMarch {
  vec3 radiance;
  float transmittance;
  float distance;
  int loop_count;
};

// Marches the layers along the unit view direction d. jitter in [0, 1): the offset of the
// samples within their steps.
CloudMarch march_clouds(vec3 d, vec3 centre, float cloud_limit, float jitter, IN(MarchParams) m MARCH_SOURCES_PARAM) {
  vec3 origin_from_centre = -centre;
  RayIntervals intervals = layer_intervals(d, centre, cloud_limit, m);
  float nu = dot(d, m.sun);
  CloudMarch result;
  result.radiance = vec3(0.0f);
  result.transmittance = 1.0f;
  result.loop_count = 4 * MAX_LAYERS * MAX_LAYERS;  // at most, for building the sorted intervals
  float weighted_distance = 0.0f;
  float weight = 0.0f;
  for (int k = 0; k < intervals.count && result.transmittance > 0.01f; ++k) {
    int layer = intervals.layer[k];
    LayerParams l = m.layers[layer];
    float a = intervals.bounds[k].x;
    float b = intervals.bounds[k].y;
    // Samples spaced quadratically: s_i = a + (b - a) t_i^2 puts short steps near the start of
    // the interval and long ones far away, where a pixel covers more ground anyway.
    // Long grazing intervals near the horizon get up to four times the samples.
    int steps = m.view_steps * int(clamp((b - a) / 20000.0f, 1.0f, 4.0f));
    float n = float(steps);
    // Sun light arriving at the layer through the clear atmosphere, once per interval.
    vec3 mid = origin_from_centre + (0.5f * (a + b)) * d;
    vec3 sunlight = solar_irradiance() * transmittance_to_space(mid, m.sun, m.earth_radius);
    float albedo = 0.99f * (1.0f - l.darkness);
    // Coarse steps probe the cheap bound; a coarse step that holds cloud (or follows one that
    // did, to catch edges between probes) is marched in VIEW_REFINE sub-steps with the full density
    // and a light march each, so the samples go where the cloud is.
    bool was_cloudy = false;
    result.loop_count += 17;  // transmittance_to_space of the interval
    for (int i = 0; i < steps && result.transmittance > 0.01f; ++i) {
      result.loop_count += 1;
      float t0 = float(i) / n;
      float t1 = float(i + 1) / n;
      float t = (float(i) + jitter) / n;
      float s = a + (b - a) * t * t;
      float coarse = (b - a) * (t1 * t1 - t0 * t0);
      bool cloudy = extinction_bound_at(s * d, centre, layer, max(coarse, s * m.pixel_angle), m MARCH_SOURCES_ARG) > 0.0f;
      if (!cloudy && !was_cloudy) continue;
      was_cloudy = cloudy;
      for (int j = 0; j < VIEW_REFINE && result.transmittance > 0.01f; ++j) {
        float u0 = t0 + (t1 - t0) * float(j) / float(VIEW_REFINE);
        float u1 = t0 + (t1 - t0) * float(j + 1) / float(VIEW_REFINE);
        float u = t0 + (t1 - t0) * (float(j) + jitter) / float(VIEW_REFINE);
        float sj = a + (b - a) * u * u;
        float ds = (b - a) * (u1 * u1 - u0 * u0);
        result.loop_count += 1;
        vec3 p = sj * d;
        float sigma = density_at(p, centre, layer, max(ds, sj * m.pixel_angle), true, m MARCH_SOURCES_ARG);
        if (sigma <= 0.0f) continue;
        float h = clamp((length(p - centre) - m.earth_radius - l.base) / (l.top - l.base), 0.0f, 1.0f);
        float tau = m.light_steps > 0 ? optical_depth_to_sun(p, centre, layer, m MARCH_SOURCES_ARG) : 0.0f;
        result.loop_count += m.light_steps + 3;  // the light march and the scattering octaves
        // Ambient: half the sphere sees the sky (radiance E/pi, dimmer towards the cloud's base),
        // half the ground; isotropic scattering of a radiance field L adds sigma_s L.
        vec3 ambient = 0.5f * (m.ambient * ((0.4f + 0.6f * h) / PI_F) + m.ground_radiance);
        vec3 source = albedo * sigma * (sunlight * sun_scattering(tau, nu) + ambient);
        float step_transmittance = exp(-sigma * ds);
        float absorbed = 1.0f - step_transmittance;
        result.radiance += result.transmittance * source * absorbed / sigma;
        weighted_distance += result.transmittance * absorbed * sj;
        weight += result.transmittance * absorbed;
        result.transmittance *= step_transmittance;
      }
    }
  }
  result.distance = weight > 0.0f ? weighted_distance / weight : 0.0f;
  return result;
}

// The pixel's radiance (RGB, linear) and cloud opacity (A): the clouds composited into the
// clear sky and the ground. loop_count: the iterations its loops took, sky and ground included.
vec4 render_pixel(ivec2 pixel, ivec2 size, IN(MarchParams) m, OUT(int) loop_count MARCH_SOURCES_PARAM) {
  vec3 d = view_direction(pixel, size, m);
  vec3 centre = vec3(0.0f, 0.0f, -(m.earth_radius + m.camera_altitude));
  vec3 origin_from_centre = -centre;

  // The ray ends at the ground (terrain.glsl) or at the top of the atmosphere.
  vec2 top = ray_sphere(vec3(0.0f), d, centre, m.earth_radius + ATMOSPHERE_THICKNESS);
  int ground_loops = 0;
  float ground = terrain_hit(origin_from_centre, d, m.earth_radius, max(top.y, 0.0f), m.terrain, ground_loops MARCH_TERRAIN_ARG);
  bool hits_ground = ground > 0.0f;
  float ray_end = hits_ground ? ground : max(top.y, 0.0f);
  float cloud_limit = min(ray_end, m.max_distance);

  // A fixed per-pixel offset of the samples trades banding for noise, the same on every run.
  float jitter = hash_to_unit3(pcg3d(uvec3(uvec2(pixel), 7u))).x;
  CloudMarch clouds = march_clouds(d, centre, cloud_limit, jitter, m MARCH_SOURCES_ARG);
  // The sky's loops (a sun transmittance per step) and the ground's.
  loop_count = clouds.loop_count + 17 * m.sky_steps + 16 + ground_loops;

  // The clear sky, split at the clouds' mean distance for aerial perspective.
  vec3 inscatter_total, inscatter_split, transmittance_total, transmittance_split;
  sky_single_scattering(origin_from_centre, d, ray_end, clouds.distance, m.sun, m.earth_radius, m.sky_steps,
                        inscatter_total, inscatter_split, transmittance_total, transmittance_split);
  vec3 background = vec3(0.0f);
  if (hits_ground) {
    // Lambertian ground (terrain.glsl's albedo), lit by the sun and the sky.
    vec3 point = origin_from_centre + ray_end * d;
    vec3 normal = terrain_normal(point, m.earth_radius, m.terrain MARCH_TERRAIN_ARG);
    vec3 albedo = m.terrain.enabled != 0 ? terrain_albedo(length(point) - m.earth_radius, normal, normalize(point)) : vec3(0.15f);
    int shadow_loops = 0;
    float sunlit = terrain_sunlit(point, normal, m.sun, m.earth_radius, m.terrain, shadow_loops MARCH_TERRAIN_ARG);
    loop_count += shadow_loops;
    vec3 sun_at_ground = solar_irradiance() * transmittance_to_space(point, m.sun, m.earth_radius) *
                         (sunlit * max(dot(normal, m.sun), 0.0f));
    background = transmittance_total * (albedo / PI_F) * (sun_at_ground + m.ambient);
  }
  vec3 color = inscatter_split + transmittance_split * clouds.radiance +
               clouds.transmittance * (inscatter_total - inscatter_split + background);
  return vec4(color, 1.0f - clouds.transmittance);
}

#endif
