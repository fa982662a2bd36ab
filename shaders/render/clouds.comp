#version 450
// Ray marching of the cloud layers and the sky, one invocation per pixel. Local frame: east,
// north, up with the camera at the origin; the Earth is the sphere osculating the WGS84
// ellipsoid at the viewpoint, its centre straight below.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D radiance_image;
layout(binding = 1) uniform sampler3D noise_volume;
layout(binding = 2) uniform sampler2DArray weather_field;
// Pixels whose loops ran (or would have run) past LOOP_LIMIT iterations in all: Mesa's llvmpipe
// stops every loop of an invocation there, so such pixels are cut short on that driver
// (docs/rendering.md). The host reads the count and warns.
layout(std430, binding = 3) buffer LoopGuard { uint loop_limited_pixels; };
const int LOOP_LIMIT = 65535;

#include "../lib/render_types.glsl"
#include "../lib/atmosphere.glsl"
#include "../lib/cloud_density.glsl"
#include "../lib/hash.glsl"

const int MAX_LAYERS = 8;
const int VIEW_REFINE = 2;  // sub-steps of a coarse view step that holds cloud (docs/rendering.md)
uniform LayerParams u_layers[MAX_LAYERS];
uniform int u_layer_count;
uniform float u_earth_radius;
uniform float u_camera_altitude;
uniform vec3 u_forward;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_tan_half_fov;
uniform int u_panorama;
uniform float u_heading;
uniform vec3 u_sun;
uniform vec3 u_ambient;        // sky irradiance on a horizontal surface
uniform vec3 u_ground_radiance;  // radiance of the sunlit and skylit ground below the clouds
uniform int u_view_steps;
uniform int u_light_steps;
uniform int u_sky_steps;
uniform float u_weather_extent;  // half-size of the weather field square, metres
uniform float u_max_distance;
uniform float u_pixel_angle;     // angle subtended by one pixel (radians), for noise level of detail
uniform float u_noise_texels;    // texels per side of the noise volume

vec3 view_direction(ivec2 pixel, ivec2 size) {
  vec2 uv = (vec2(pixel) + 0.5f) / vec2(size);
  if (u_panorama != 0) {
    // 360 x 180 equirectangular view sphere, the heading at the centre, up at the top.
    float azimuth = u_heading + (uv.x - 0.5f) * 2.0f * PI_F;
    float elevation = (0.5f - uv.y) * PI_F;
    return vec3(cos(elevation) * sin(azimuth), cos(elevation) * cos(azimuth), sin(elevation));
  }
  float aspect = float(size.y) / float(size.x);
  vec2 xy = vec2(2.0f * uv.x - 1.0f, (1.0f - 2.0f * uv.y) * aspect) * u_tan_half_fov;
  return normalize(u_forward + xy.x * u_right + xy.y * u_up);
}

float coverage_at(vec3 p, int channel) {
  vec2 uv = 0.5f + 0.5f * p.xy / u_weather_extent;
  return texture(weather_field, vec3(uv, float(channel))).x;
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
ShapeSample shape_at(vec3 p, vec3 centre, int layer, float footprint) {
  LayerParams l = u_layers[layer];
  ShapeSample q;
  float altitude = length(p - centre) - u_earth_radius;
  q.h = (altitude - l.base) / (l.top - l.base);
  q.c = coverage_at(p, l.channel);
  q.shape = 0.0f;
  q.detail = 0.0f;
  q.lod = 0.0f;
  q.coordinates = vec3(0.0f);
  if (q.c <= 0.0f || q.h < 0.0f || q.h > 1.0f) return q;
  // Noise coordinates in the wind's frame, moved by the wind's offset (tau).
  vec2 along_across = vec2(dot(p.xy, l.wind), dot(p.xy, vec2(-l.wind.y, l.wind.x))) - l.noise_offset;
  vec2 period = noise_period(l.type);
  q.coordinates = vec3(along_across / period, altitude / period.y);
  float texel = period.x / u_noise_texels;
  q.lod = log2(max(footprint / texel, 1.0f));
  vec2 noise = textureLod(noise_volume, q.coordinates, q.lod).xy;
  // A second lookup at an incommensurate, rotated scale (7.3 periods) breaks the volume's tiling,
  // which would otherwise line distant clouds up in a regular array.
  vec3 x = q.coordinates;
  vec3 macro_coordinates = vec3(0.0822f * x.x + 0.0548f * x.y, -0.0548f * x.x + 0.0822f * x.y, 0.1371f * x.z + 0.37f);
  float macro = textureLod(noise_volume, macro_coordinates, max(q.lod - 3.0f, 0.0f)).x;
  q.shape = uniform_from_mix(mix(noise.x, macro, 0.4f), 0.4f);
  q.detail = noise.y;
  return q;
}

// The largest extinction the layer can have at the sample whatever the detail noise (every
// density grows with it, tested): zero over most of the sky, and it needs no detail lookup.
// (cloud_density is zero outside the layer and without cover.)
float extinction_bound(int layer, ShapeSample q) {
  LayerParams l = u_layers[layer];
  return l.extinction * cloud_density(l.type, q.h, q.c, q.shape, 1.0f, l.morph);
}

float extinction_bound_at(vec3 p, vec3 centre, int layer, float footprint) {
  return extinction_bound(layer, shape_at(p, centre, layer, footprint));
}

// Extinction (1/m) of a layer at p. fine: also read the detail noise (the light march does
// without it).
float density_at(vec3 p, vec3 centre, int layer, float footprint, bool fine) {
  LayerParams l = u_layers[layer];
  ShapeSample q = shape_at(p, centre, layer, footprint);
  // Where even the bound is zero (most of the sky) the detail lookup is skipped.
  if (extinction_bound(layer, q) <= 0.0f) return 0.0f;
  float detail = fine ? textureLod(noise_volume, q.coordinates * 4.0f, q.lod + 2.0f).y : q.detail;
  return l.extinction * cloud_density(l.type, q.h, q.c, q.shape, mix(q.detail, detail, 0.5f), l.morph);
}

// Optical depth from p towards the sun within the same layer (other layers' shadows are left out).
float optical_depth_to_sun(vec3 p, vec3 centre, int layer) {
  LayerParams l = u_layers[layer];
  float length_to_exit = min((l.top - l.base) / max(u_sun.z, 0.15f), 4000.0f);
  // Samples spaced quadratically (s = L t^2): the light that reaches a point is decided by the
  // first hundred metres towards the sun (an optical depth of 1 every 50 m in a cumulus), so
  // the steps are short there and long further out.
  float n = float(u_light_steps);
  float tau = 0.0f;
  for (int i = 0; i < u_light_steps; ++i) {
    float t0 = float(i) / n;
    float t1 = float(i + 1) / n;
    float t = 0.5f * (t0 + t1);
    float ds = length_to_exit * (t1 * t1 - t0 * t0);
    tau += density_at(p + (length_to_exit * t * t) * u_sun, centre, layer, ds, false) * ds;
  }
  return tau;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(radiance_image);
  if (pixel.x >= size.x || pixel.y >= size.y) return;
  vec3 d = view_direction(pixel, size);
  vec3 centre = vec3(0.0f, 0.0f, -(u_earth_radius + u_camera_altitude));
  vec3 origin_from_centre = -centre;

  // The ray ends at the ground or at the top of the atmosphere.
  vec2 ground = ray_sphere(vec3(0.0f), d, centre, u_earth_radius);
  bool hits_ground = ground.x < ground.y && ground.x > 0.0f;
  vec2 top = ray_sphere(vec3(0.0f), d, centre, u_earth_radius + ATMOSPHERE_THICKNESS);
  float ray_end = hits_ground ? ground.x : max(top.y, 0.0f);
  float cloud_limit = min(ray_end, u_max_distance);

  // Intervals of the ray inside each layer, marched in order of distance.
  vec4 intervals[2 * MAX_LAYERS];
  int interval_layer[2 * MAX_LAYERS];
  int count = 0;
  int loop_count = 4 * MAX_LAYERS * MAX_LAYERS;  // at most, for building the sorted intervals
  for (int layer = 0; layer < u_layer_count; ++layer) {
    LayerParams l = u_layers[layer];
    vec4 s = ray_shell(vec3(0.0f), d, centre, u_earth_radius + l.base, u_earth_radius + l.top, cloud_limit);
    for (int k = 0; k < 2; ++k) {
      float a = max(k == 0 ? s.x : s.z, l.min_distance);
      float b = k == 0 ? s.y : s.w;
      if (a < b) {
        int j = count++;
        while (j > 0 && intervals[j - 1].x > a) {
          intervals[j] = intervals[j - 1];
          interval_layer[j] = interval_layer[j - 1];
          --j;
        }
        intervals[j] = vec4(a, b, 0.0f, 0.0f);
        interval_layer[j] = layer;
      }
    }
  }

  // A fixed per-pixel offset of the samples trades banding for noise, the same on every run.
  float jitter = hash_to_unit3(pcg3d(uvec3(uvec2(pixel), 7u))).x;
  float nu = dot(d, u_sun);
  vec3 cloud_radiance = vec3(0.0f);
  float cloud_transmittance = 1.0f;
  float weighted_distance = 0.0f;
  float weight = 0.0f;
  for (int k = 0; k < count && cloud_transmittance > 0.01f; ++k) {
    int layer = interval_layer[k];
    LayerParams l = u_layers[layer];
    float a = intervals[k].x;
    float b = intervals[k].y;
    // Samples spaced quadratically: s_i = a + (b - a) t_i^2 puts short steps near the start of
    // the interval and long ones far away, where a pixel covers more ground anyway.
    // Long grazing intervals near the horizon get up to four times the samples.
    int steps = u_view_steps * int(clamp((b - a) / 20000.0f, 1.0f, 4.0f));
    float n = float(steps);
    // Sun light arriving at the layer through the clear atmosphere, once per interval.
    vec3 mid = origin_from_centre + (0.5f * (a + b)) * d;
    vec3 sunlight = solar_irradiance() * transmittance_to_space(mid, u_sun, u_earth_radius);
    float albedo = 0.99f * (1.0f - l.darkness);
    // Coarse steps probe the cheap bound; a coarse step that holds cloud (or follows one that
    // did, to catch edges between probes) is marched in VIEW_REFINE sub-steps with the full density
    // and a light march each, so the samples go where the cloud is.
    bool was_cloudy = false;
    loop_count += 17;  // transmittance_to_space of the interval
    for (int i = 0; i < steps && cloud_transmittance > 0.01f; ++i) {
      loop_count += 1;
      float t0 = float(i) / n;
      float t1 = float(i + 1) / n;
      float t = (float(i) + jitter) / n;
      float s = a + (b - a) * t * t;
      float coarse = (b - a) * (t1 * t1 - t0 * t0);
      bool cloudy = extinction_bound_at(s * d, centre, layer, max(coarse, s * u_pixel_angle)) > 0.0f;
      if (!cloudy && !was_cloudy) continue;
      was_cloudy = cloudy;
      for (int j = 0; j < VIEW_REFINE && cloud_transmittance > 0.01f; ++j) {
        float u0 = t0 + (t1 - t0) * float(j) / float(VIEW_REFINE);
        float u1 = t0 + (t1 - t0) * float(j + 1) / float(VIEW_REFINE);
        float u = t0 + (t1 - t0) * (float(j) + jitter) / float(VIEW_REFINE);
        float sj = a + (b - a) * u * u;
        float ds = (b - a) * (u1 * u1 - u0 * u0);
        loop_count += 1;
        vec3 p = sj * d;
        float sigma = density_at(p, centre, layer, max(ds, sj * u_pixel_angle), true);
        if (sigma <= 0.0f) continue;
        float h = clamp((length(p - centre) - u_earth_radius - l.base) / (l.top - l.base), 0.0f, 1.0f);
        float tau = u_light_steps > 0 ? optical_depth_to_sun(p, centre, layer) : 0.0f;
        loop_count += u_light_steps + 3;  // the light march and the scattering octaves
        // Ambient: half the sphere sees the sky (radiance E/pi, dimmer towards the cloud's base),
        // half the ground; isotropic scattering of a radiance field L adds sigma_s L.
        vec3 ambient = 0.5f * (u_ambient * ((0.4f + 0.6f * h) / PI_F) + u_ground_radiance);
        vec3 source = albedo * sigma * (sunlight * sun_scattering(tau, nu) + ambient);
        float step_transmittance = exp(-sigma * ds);
        float absorbed = 1.0f - step_transmittance;
        cloud_radiance += cloud_transmittance * source * absorbed / sigma;
        weighted_distance += cloud_transmittance * absorbed * sj;
        weight += cloud_transmittance * absorbed;
        cloud_transmittance *= step_transmittance;
      }
    }
  }
  float cloud_distance = weight > 0.0f ? weighted_distance / weight : 0.0f;
  // The sky's loops (a sun transmittance per step) and the ground's, then the verdict.
  loop_count += 17 * u_sky_steps + 16;
  if (loop_count >= LOOP_LIMIT) atomicAdd(loop_limited_pixels, 1u);

  // The clear sky, split at the clouds' mean distance for aerial perspective.
  vec3 inscatter_total, inscatter_split, transmittance_total, transmittance_split;
  sky_single_scattering(origin_from_centre, d, ray_end, cloud_distance, u_sun, u_earth_radius, u_sky_steps,
                        inscatter_total, inscatter_split, transmittance_total, transmittance_split);
  vec3 background = vec3(0.0f);
  if (hits_ground) {
    // Lambertian ground, albedo 0.15, lit by the sun and the sky.
    vec3 point = origin_from_centre + ray_end * d;
    vec3 normal = normalize(point);
    vec3 sun_at_ground = solar_irradiance() * transmittance_to_space(point, u_sun, u_earth_radius) *
                         max(dot(normal, u_sun), 0.0f);
    background = transmittance_total * (0.15f / PI_F) * (sun_at_ground + u_ambient);
  }
  vec3 color = inscatter_split + transmittance_split * cloud_radiance +
               cloud_transmittance * (inscatter_total - inscatter_split + background);
  imageStore(radiance_image, pixel, vec4(color, 1.0f - cloud_transmittance));
}
