// Ray marching of the cloud layers and the sky, one view ray per pixel (the pass is
// shaders/render/clouds.comp; docs/rendering.md describes the method). Local frame: east,
// north, up with the camera at the origin; the Earth is the sphere osculating the WGS84
// ellipsoid at the viewpoint, its centre straight below. The textures are parameters named by
// what they hold (prelude.glsl's types; in C++ the classes of src/shader_math/hooks.hpp), read
// with GLSL's texture functions:
//   NoiseVolume noise_volume        RGBA at x (one period per unit, repeating), trilinear within
//                                   and linear between mip levels: RG the shape and detail noise,
//                                   B the standardised gradient-noise octave mean behind G3, A
//                                   the W3 field (render/noise_volume.comp)
//   WeatherField weather_field      layer c: the weather field's channel c at uv in [0, 1]^2,
//                                   bilinear, clamped to the edge
//   TerrainTexture terrain_heights  the ground (terrain.glsl)
//   ConvectiveVolumes convective_volumes  the convective clouds' densities (convective_density
//                                   below; docs/convection.md)
//   ShadowMaps layer_shadows        layer `map`: the shadow map of higher_layers_depth below
//   ShadowMaps sky_shadow           layer 0: the sky's shadow map (sky_sun_visibility below)
#ifndef NEPHELE_CLOUD_MARCH_GLSL
#define NEPHELE_CLOUD_MARCH_GLSL
#include "prelude.glsl"
#include "render_types.glsl"
#include "atmosphere.glsl"
#include "cloud_density.glsl"
#include "webanck_forms.glsl"
#include "hash.glsl"
#include "ray_sphere.glsl"
#include "terrain.glsl"
#include "land_cover.glsl"
#include "sun_glint.glsl"
#include "slab_scattering.glsl"
#include "implicit_field.glsl"

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

float coverage_at(vec3 p, int channel, IN(MarchParams) m, IN(WeatherField) weather_field) {
  vec2 uv = 0.5f + 0.5f * vec2(p) / m.weather_extent;
  return texture(weather_field, vec3(uv, float(channel))).x;
}

// A layer's shape-noise lookups at a point: the height fraction h in the layer, the coverage c,
// the shape value (0 outside the layer or where the weather gives no cover) and the base detail
// value, with the noise coordinates and mip level that a detail lookup goes on with.
// Webanck's types (cumulus, alto) keep phi in shape, the mean of delta in detail, their
// envelope in gate and p_n in coordinates; lod is then that of a field of frequency 1.
struct ShapeSample {
  float h, c, shape, detail, lod, gate;
  float erosion;  // Webanck's types: delta's weight at the coverage (webanck_forms.glsl's windows)
  vec3 coordinates;
};

bool webanck_type(int type) { return type == CLOUD_CUMULUS || type == CLOUD_ALTO; }

// Base cells of the baked G3 and W3 fields per period of the noise volume (noise_volume.comp).
const float BAKED_CELLS = 4.0f;

// A field of base frequency f at p_n from the volume: f p_n / BAKED_CELLS periods, shifted by
// a fixed offset per field so that the fields read different parts of the volume. lod: that of
// a field of frequency 1 (log2 of the footprint in texels at f = 1).
vec4 baked_fields(vec3 pn, float frequency, int field, float lod, IN(NoiseVolume) noise_volume) {
  vec3 decorrelate = fract(float(field) * vec3(0.3819660f, 0.6180340f, 0.2360680f));
  return textureLod(noise_volume, pn * (frequency / BAKED_CELLS) + decorrelate, max(lod + log2(frequency), 0.0f));
}

// G3 of the baked standardised octave mean (channel B) and W3 (channel A).
float baked_g3(vec3 pn, float frequency, int field, float lod, IN(NoiseVolume) noise_volume) {
  return normal_cdf(baked_fields(pn, frequency, field, lod, noise_volume).z);
}

float baked_w3(vec3 pn, float frequency, int field, float lod, IN(NoiseVolume) noise_volume) {
  return baked_fields(pn, frequency, field, lod, noise_volume).w;
}

// The mean of delta over the fields (E[G3] = 1/2, E[W3] = WEBANCK_W3_MEAN): what the light
// march subtracts instead of reading the four detail fields.
const float WEBANCK_W3_MEAN = 0.70f;

// How many of Webanck's shape fields a lookup reads: the bound reads n2 and n3 and takes
// k2 = 1 (its largest value, so phi can only shrink); the light march takes k2 at the mean of
// n4 and n5 (1/2: k1 = 1/4, k2 = 7/8); the view samples read all four.
const int WEBANCK_BOUND = 0;
const int WEBANCK_LIGHT = 1;
const int WEBANCK_FULL = 2;

// Webanck's phi from the baked fields, opened by the weather's coverage c through the forms'
// coverage windows (webanck_forms.glsl: the share c of the columns holds cloud), with delta's
// weight for that c in erosion and delta's mean times it in detail.
void webanck_shape(INOUT(ShapeSample) q, int type, float k, float tau, int fields, IN(NoiseVolume) noise_volume) {
  vec3 pn = q.coordinates;
  vec3 offset = vec3(-tau, 0.0f, 0.0f);
  if (type == CLOUD_CUMULUS) {
    float n2 = baked_g3(vec3(0.65f * pn.x, pn.y, pn.z) + offset, 15.0f, 2, q.lod, noise_volume);
    float n3 = baked_g3(pn + 2.0f * offset, 40.0f, 3, q.lod, noise_volume);
    float n4 = fields == WEBANCK_BOUND ? 0.0f : 0.5f;
    float n5 = 0.5f;
    if (fields == WEBANCK_FULL) {
      n4 = baked_g3(pn + 2.0f * offset, 40.0f, 4, q.lod, noise_volume);
      n5 = baked_g3(pn + 3.0f * offset, 80.0f, 5, q.lod, noise_volume);
    }
    vec2 phi = cumulus_phi_at(vec4(n2, n3, n4, n5), q.c, q.h);
    q.shape = phi.x;
    q.erosion = phi.y;
    q.detail = phi.y * cumulus_delta(WEBANCK_W3_MEAN, WEBANCK_W3_MEAN, 0.5f, 0.5f);
    q.gate = cumulus_gate(q.h);
  } else {
    float n1 = baked_g3(vec3(0.35f * pn.x, pn.y, pn.z) + 2.0f * offset, 36.0f, 11, q.lod, noise_volume);
    vec2 phi = alto_phi_at(k, q.c, n1);
    q.shape = phi.x;
    q.erosion = phi.y;
    q.detail = phi.y * alto_delta(k, 0.5f, WEBANCK_W3_MEAN);
    q.gate = alto_gate(q.h);
  }
}

// Webanck's delta from the baked detail fields.
float webanck_detail(IN(ShapeSample) q, int type, float k, float tau, IN(NoiseVolume) noise_volume) {
  vec3 pn = q.coordinates;
  vec3 offset = vec3(-tau, 0.0f, 0.0f);
  if (type == CLOUD_CUMULUS) {
    float n6 = baked_w3(pn + 4.0f * offset, 160.0f, 6, q.lod, noise_volume);
    float n7 = baked_w3(pn + 0.8f * offset, 240.0f, 7, q.lod, noise_volume);
    float n8 = baked_g3(pn + 8.0f * offset, 288.0f, 8, q.lod, noise_volume);
    float n9 = baked_g3(pn + 8.0f * offset, 384.0f, 9, q.lod, noise_volume);
    return q.erosion * cumulus_delta(n6, n7, n8, n9);
  }
  float n2 = baked_g3(pn + 8.0f * offset, 96.0f, 12, q.lod, noise_volume);
  float n3 = baked_w3(pn + 8.0f * offset, 400.0f, 13, q.lod, noise_volume);
  return q.erosion * alto_delta(k, n2, n3);
}

// footprint: the length one sample stands for (the pixel's width at that distance, or the step),
// which picks the noise volume's mip level so that distant clouds do not alias into speckle.
// fields: WEBANCK_BOUND, _LIGHT or _FULL, how much of the Webanck types' shape to read.
ShapeSample shape_at(vec3 p, vec3 centre, int layer, float footprint, int fields, IN(MarchParams) m,
                     IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field) {
  LayerParams l = m.layers[layer];
  ShapeSample q;
  float altitude = length(p - centre) - m.earth_radius;
  q.h = (altitude - l.base) / (l.top - l.base);
  q.c = coverage_at(p, l.channel, m, weather_field);
  q.shape = 0.0f;
  q.detail = 0.0f;
  q.lod = 0.0f;
  q.gate = 1.0f;
  q.erosion = 1.0f;
  q.coordinates = vec3(0.0f);
  if (q.c <= 0.0f || q.h < 0.0f || q.h > 1.0f) return q;
  if (webanck_type(l.type)) {
    // p_n in the wind's frame; tau in units of p_n (the base field n2 drifts with the wind).
    q.coordinates = webanck_position(vec3(vec2(p), altitude), l.wind);
    q.lod = log2(max(footprint * (m.noise_texels / (BAKED_CELLS * 108000.0f)), 1.0e-30f));
    webanck_shape(q, l.type, 1.0f - l.morph, l.noise_offset.x / 108000.0f, fields, noise_volume);
    return q;
  }
  // Noise coordinates in the wind's frame, moved by the wind's offset (tau).
  vec2 along_across = vec2(dot(vec2(p), l.wind), dot(vec2(p), vec2(-l.wind.y, l.wind.x))) - l.noise_offset;
  vec2 period = noise_period(l.type);
  q.coordinates = vec3(along_across / period, altitude / period.y);
  float texel = period.x / m.noise_texels;
  q.lod = log2(max(footprint / texel, 1.0f));
  vec2 noise = vec2(textureLod(noise_volume, q.coordinates, q.lod));
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
float extinction_bound(int layer, IN(ShapeSample) q, IN(MarchParams) m) {
  LayerParams l = m.layers[layer];
  if (webanck_type(l.type)) return q.c <= 0.0f || q.h < 0.0f || q.h > 1.0f ? 0.0f : l.extinction * q.shape * q.gate;
  return l.extinction * cloud_density(l.type, q.h, q.c, q.shape, 1.0f);
}

float extinction_bound_at(vec3 p, vec3 centre, int layer, float footprint, IN(MarchParams) m,
                          IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field) {
  return extinction_bound(layer, shape_at(p, centre, layer, footprint, WEBANCK_BOUND, m, noise_volume, weather_field),
                          m);
}

// Detail of the heaped clouds below what their fields hold, Schneider's detail erosion at render
// time: a convective volume holds its model's lobes down to 4 voxels (docs/model.md), whose
// trilinear facets of 86 to 117 m show on a tower seen from 15 km, and the cumulus layer's
// finest Webanck field has a period of 280 m. The marcher erodes their edges further with the
// noise volume's detail channel (inverted Worley fBm, 8 cells and 3 octaves a period) over
// DETAIL_PERIOD metres fixed to the cloud (250 m cells, octaves down to 60 m), by model_erode
// with strength m.detail_erosion (0: the density as it is); a density of 1 or more (a cloud's
// core) is left alone. The footprint (the sample's length) picks the noise's mip level, so a
// distant cloud gets the detail's mean.
const float DETAIL_PERIOD = 2000.0f;
float detail_eroded(float density, vec3 x, float footprint, IN(MarchParams) m, IN(NoiseVolume) noise_volume) {
  if (m.detail_erosion <= 0.0f || density <= 0.0f || density >= 1.0f) return density;
  float lod = log2(max(footprint * m.noise_texels / DETAIL_PERIOD, 1.0f));
  float detail = textureLod(noise_volume, x / DETAIL_PERIOD, lod).y;
  return model_erode(density, detail, m.detail_erosion);
}

// Extinction (1/m) of a layer at p. fine: also read the detail noise (the light march does
// without it).
float density_at(vec3 p, vec3 centre, int layer, float footprint, bool fine, IN(MarchParams) m,
                 IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field) {
  LayerParams l = m.layers[layer];
  ShapeSample q = shape_at(p, centre, layer, footprint, fine ? WEBANCK_FULL : WEBANCK_LIGHT, m, noise_volume,
                           weather_field);
  // Where even the bound is zero (most of the sky) the detail lookup is skipped.
  if (extinction_bound(layer, q, m) <= 0.0f) return 0.0f;
  if (webanck_type(l.type)) {
    // The light march subtracts delta's mean instead of reading the detail fields.
    float delta = fine ? webanck_detail(q, l.type, 1.0f - l.morph, l.noise_offset.x / 108000.0f,
                                        noise_volume) : q.detail;
    float density = max(q.shape - delta, 0.0f);
    // The cumulus's edges in view get the heaped clouds' detail, in metres of the wind's frame
    // moving with the cells.
    if (fine && l.type == CLOUD_CUMULUS)
      density = detail_eroded(density, q.coordinates * 108000.0f - vec3(l.noise_offset.x, 0.0f, 0.0f), footprint, m,
                              noise_volume);
    return l.extinction * density * q.gate;
  }
  float detail = fine ? textureLod(noise_volume, q.coordinates * 4.0f, q.lod + 2.0f).y : q.detail;
  return l.extinction * cloud_density(l.type, q.h, q.c, q.shape, mix(q.detail, detail, 0.5f));
}

// Optical depth from p towards the sun within the same layer (the layers wholly above it: higher_layers_depth).
float optical_depth_to_sun(vec3 p, vec3 centre, int layer, IN(MarchParams) m, IN(NoiseVolume) noise_volume,
                           IN(WeatherField) weather_field) {
  LayerParams l = m.layers[layer];
  float length_to_exit = min((l.top - l.base) / max(m.sun.z, 0.15f), 4000.0f);
  float tau = 0.0f;
  for (int i = 0; i < m.light_steps; ++i) {
    vec2 s = light_sample(i, m.light_steps, length_to_exit);  // (distance, step), quadratic
    tau += density_at(p + s.x * m.sun, centre, layer, s.y, false, m, noise_volume, weather_field) * s.y;
  }
  return tau;
}

// Samples per layer crossed of a shadow ray (shadow_depth).
const int SHADOW_STEPS = 6;

// ---- Convective clouds: density volumes of implicit models (docs/convection.md) ----

// The volume coordinates of p in convective cloud c: x along its axis, y to the left, z up by
// altitude; the cloud's volume is the unit cube.
vec3 convective_coordinates(vec3 p, vec3 centre, int c, IN(MarchParams) m) {
  ConvectiveParams v = m.convective[c];
  vec2 offset = vec2(p) - v.centre;
  vec2 side = vec2(-v.axis.y, v.axis.x);
  float altitude = length(p - centre) - m.earth_radius;
  return vec3(dot(offset, v.axis) / v.extent + 0.5f, dot(offset, side) / v.extent + 0.5f,
              (altitude - v.bottom) / v.extent);
}

bool in_unit_cube(vec3 q) {
  return q.x >= 0.0f && q.x <= 1.0f && q.y >= 0.0f && q.y <= 1.0f && q.z >= 0.0f && q.z <= 1.0f;
}

// The density of convective cloud `cloud` at q in [0, 1]^3, trilinear, clamped to the edge of
// its own volume: volume c lies in the z-layers [c N, (c + 1) N) of the stack (N^3 each), and z
// is clamped to its own texel centres so that no sample blends two volumes.
float convective_density(IN(ConvectiveVolumes) convective_volumes, vec3 q, int cloud) {
  ivec3 size = textureSize(convective_volumes, 0);
  float n = float(size.x);
  float z = (float(cloud) * n + clamp(q.z * n, 0.5f, n - 0.5f)) / float(size.z);
  return texture(convective_volumes, vec3(q.x, q.y, z)).x;
}

// The extinction (1/m) of the convective clouds at p (x) and the height fraction, 0 at the
// base and 1 at the top, of the cloud that holds most of it (y; the ambient light's height).
// footprint: the length the sample stands for (detail_eroded's level of detail).
vec2 convective_at(vec3 p, vec3 centre, float footprint, IN(MarchParams) m, IN(NoiseVolume) noise_volume,
                   IN(ConvectiveVolumes) convective_volumes) {
  float sigma = 0.0f;
  float h = 0.0f;
  float strongest = 0.0f;
  for (int c = 0; c < m.convective_count; ++c) {
    vec3 q = convective_coordinates(p, centre, c, m);
    if (!in_unit_cube(q)) continue;  // the box test before the texture
    ConvectiveParams v = m.convective[c];
    // The detail's coordinates: metres in the cloud's volume, each cloud its own part of the noise.
    vec3 x = q * v.extent + vec3(float(c) * 733.0f, float(c) * 1297.0f, 0.0f);
    float s = v.extinction *
              detail_eroded(convective_density(convective_volumes, q, c), x, footprint, m, noise_volume);
    sigma += s;
    if (s > strongest) {
      strongest = s;
      h = clamp((v.bottom + q.z * v.extent - v.cloud_base) / (v.cloud_top - v.cloud_base), 0.0f, 1.0f);
    }
  }
  return vec2(sigma, h);
}

// The part of the ray o + t d, 0 <= t <= limit, inside convective cloud c's box: (start, end),
// empty when start >= end. Across: the two pairs of vertical planes of its sides; up: the shell
// between its bottom and top altitudes (the hull of ray_shell's two intervals).
vec2 convective_box(vec3 o, vec3 d, vec3 centre, int c, float limit, IN(MarchParams) m) {
  ConvectiveParams v = m.convective[c];
  vec2 t = vec2(0.0f, limit);
  vec2 offset = vec2(o) - v.centre;
  float half_edge = 0.5f * v.extent;
  for (int k = 0; k < 2; ++k) {
    vec2 normal = k == 0 ? v.axis : vec2(-v.axis.y, v.axis.x);
    float po = dot(offset, normal);
    float pd = dot(vec2(d), normal);
    if (abs(pd) < 1.0e-9f) {
      if (abs(po) > half_edge) return vec2(1.0f, 0.0f);
      continue;
    }
    float t0 = (-half_edge - po) / pd;
    float t1 = (half_edge - po) / pd;
    t = vec2(max(t.x, min(t0, t1)), min(t.y, max(t0, t1)));
  }
  vec4 s = ray_shell(o, d, centre, m.earth_radius + v.bottom, m.earth_radius + v.bottom + v.extent, limit);
  bool first = s.x < s.y;
  bool second = s.z < s.w;
  if (!first && !second) return vec2(1.0f, 0.0f);
  return vec2(max(t.x, first ? s.x : s.z), min(t.y, second ? s.w : s.y));
}

// The stretch of the ray that crosses any convective box, from the first entry to the last exit
// (start >= end: none).
vec2 convective_span(vec3 o, vec3 d, vec3 centre, float limit, IN(MarchParams) m) {
  vec2 span = vec2(limit, 0.0f);
  for (int c = 0; c < m.convective_count; ++c) {
    vec2 r = convective_box(o, d, centre, c, limit, m);
    if (r.x < r.y) span = vec2(min(span.x, r.x), max(span.y, r.y));
  }
  return span;
}

// How far the light march towards the sun follows the convective boxes (the anvil's side of a
// cumulonimbus at a low sun).
const float CONVECTIVE_LIGHT_REACH = 20000.0f;

// Optical depth from p towards the sun through the convective clouds, samples spaced as the
// layers' light march (light_sample) up to where the last box along the sun ends.
float convective_depth_to_sun(vec3 p, vec3 centre, IN(MarchParams) m, IN(NoiseVolume) noise_volume,
                              IN(ConvectiveVolumes) convective_volumes) {
  vec2 span = convective_span(p, m.sun, centre, CONVECTIVE_LIGHT_REACH, m);
  float tau = 0.0f;
  if (span.x >= span.y) return tau;
  for (int i = 0; i < m.light_steps; ++i) {
    vec2 s = light_sample(i, m.light_steps, span.y);
    tau += convective_at(p + s.x * m.sun, centre, s.y, m, noise_volume, convective_volumes).x * s.y;
  }
  return tau;
}

// The convective clouds' share of a ground point's shadow: 2 SHADOW_STEPS midpoint samples
// where the sun ray crosses their boxes.
float convective_shadow_depth(vec3 p, vec3 centre, INOUT(int) loop_count, IN(MarchParams) m, IN(NoiseVolume) noise_volume,
                              IN(ConvectiveVolumes) convective_volumes) {
  loop_count += m.convective_count;
  vec2 span = convective_span(p, m.sun, centre, m.max_distance, m);
  float tau = 0.0f;
  if (span.x >= span.y) return tau;
  float ds = (span.y - span.x) / float(2 * SHADOW_STEPS);
  for (int i = 0; i < 2 * SHADOW_STEPS; ++i)
    tau += convective_at(p + (span.x + (float(i) + 0.5f) * ds) * m.sun, centre, ds, m, noise_volume,
                         convective_volumes).x * ds;
  loop_count += 2 * SHADOW_STEPS * (1 + m.convective_count);
  return tau;
}

// Single-scattering albedo of the convective clouds' water droplets.
const float CONVECTIVE_ALBEDO = 0.99f;

// Optical depth from p towards the sun through the layers whose base is at or above min_base,
// except layer skip (-1: none): the clouds' shadows on the ground, and the shadow maps' texels.
// (Called per cloud sample for the shadows of higher layers on lower ones, it made llvmpipe cut
// loops before the marcher's count reached LOOP_LIMIT, so the loop guard missed them: the maps
// below replace that.) SHADOW_STEPS midpoint samples of the light march's density per interval;
// counts its loop iterations into loop_count.
float layers_shadow_depth(vec3 p, vec3 centre, int skip, float min_base, INOUT(int) loop_count,
                          IN(MarchParams) m, IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field) {
  float tau = 0.0f;
  loop_count += m.layer_count;  // every iteration of the layer loop counts towards the limit
  for (int layer = 0; layer < m.layer_count; ++layer) {
    LayerParams l = m.layers[layer];
    if (layer == skip || l.base < min_base) continue;
    vec4 s = ray_shell(p, m.sun, centre, m.earth_radius + l.base, m.earth_radius + l.top, m.max_distance);
    loop_count += 2;
    for (int k = 0; k < 2; ++k) {
      float a = max(k == 0 ? s.x : s.z, 0.0f);
      float b = k == 0 ? s.y : s.w;
      if (a >= b) continue;
      float ds = (b - a) / float(SHADOW_STEPS);
      for (int i = 0; i < SHADOW_STEPS; ++i) {
        tau += density_at(p + (a + (float(i) + 0.5f) * ds) * m.sun, centre, layer, ds, false, m, noise_volume,
                          weather_field) * ds;
      }
      loop_count += SHADOW_STEPS;
    }
  }
  return tau;
}

// The same plus the convective clouds' (all of them, whatever their altitude).
float shadow_depth(vec3 p, vec3 centre, int skip, float min_base, INOUT(int) loop_count,
                   IN(MarchParams) m, IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field,
                   IN(ConvectiveVolumes) convective_volumes) {
  float layers = layers_shadow_depth(p, centre, skip, min_base, loop_count, m, noise_volume, weather_field);
  return layers + convective_shadow_depth(p, centre, loop_count, m, noise_volume, convective_volumes);
}

// ---- Shadows of higher layers on lower ones (docs/rendering.md, "Shadows between layers") ----
// A layer with layers wholly above it (base at or above its top) has a shadow map: over the
// camera's tangent plane, the optical depth towards the sun through those layers from the
// points of the layer's top shell (render/layer_shadows.comp fills it once per render). A point
// p of the layer lies on the sun ray through the point where that ray leaves the top shell, and
// beyond that point the ray meets only higher layers: the map read there is p's depth through
// them, so each sample takes one lookup instead of a march through the layers above.

// The tangent-plane coordinates of q: its projection from the Earth's centre onto the plane
// z = 0 through the camera.
vec2 shadow_map_xy(vec3 q, vec3 centre) { return vec2(q) * (-centre.z / (q.z - centre.z)); }

// The point of the shell at `altitude` whose tangent-plane coordinates are xy.
vec3 shadow_map_origin(vec2 xy, vec3 centre, float altitude, IN(MarchParams) m) {
  return centre + (m.earth_radius + altitude) * normalize(vec3(xy, 0.0f) - centre);
}

// The map's value at uv in [0, 1]^2 (a texel's centre when the pass fills it): the depth through
// the layers wholly above `layer` from the top shell's point there; the map spans
// [-shadow_extent, shadow_extent]^2 of the tangent plane. Layer -1: the sky's map, the depth
// through every layer and convective cloud from the shell of the lowest base (sky_sun_visibility).
float shadow_map_texel(vec2 uv, vec3 centre, int layer, INOUT(int) loop_count, IN(MarchParams) m,
                       IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field,
                       IN(ConvectiveVolumes) convective_volumes) {
  if (layer < 0) {
    vec3 q = shadow_map_origin((2.0f * uv - 1.0f) * m.shadow_extent, centre, m.sky_shadow_base, m);
    return shadow_depth(q, centre, -1, -1.0e30f, loop_count, m, noise_volume, weather_field, convective_volumes);
  }
  vec3 q = shadow_map_origin((2.0f * uv - 1.0f) * m.shadow_extent, centre, m.layers[layer].top, m);
  return layers_shadow_depth(q, centre, layer, m.layers[layer].top, loop_count, m, noise_volume, weather_field);
}

// Where the sun ray from p (below the shell at `altitude`) leaves that shell, as the map's
// coordinates uv.
vec2 shadow_map_uv(vec3 p, vec3 centre, float altitude, IN(MarchParams) m) {
  vec2 shell = ray_sphere(p, m.sun, centre, m.earth_radius + altitude);
  vec3 q = p + max(shell.y, 0.0f) * m.sun;
  return 0.5f + 0.5f * shadow_map_xy(q, centre) / m.shadow_extent;
}

// The optical depth from p (in layer `layer`) towards the sun through the layers wholly above
// it, from its shadow map; 0 where the layer has none.
float higher_layers_depth(vec3 p, vec3 centre, int layer, IN(MarchParams) m, IN(ShadowMaps) layer_shadows) {
  int map = m.layers[layer].shadow_map;
  if (map < 0) return 0.0f;
  return texture(layer_shadows, vec3(shadow_map_uv(p, centre, m.layers[layer].top, m), float(map))).x;
}

// ---- Crepuscular rays (docs/rendering.md) ----
// The sun's share at a sample p of the clear-sky integral: exp(-depth through the clouds) below
// the lowest base, from the sky's map (the same construction as the layers' maps, from the
// lowest base's shell, in a texture of its own at a quarter of their size: the sky's samples lie
// kilometres apart), so that the air in the clouds' shadows scatters less sunlight: shafts of
// light and shadow; 1 above the lowest base (within the layers the clouds themselves hide most
// of that air), outside the map (no cloud is marched beyond max_distance) and without a map.
float sky_sun_visibility(vec3 p, vec3 centre, IN(MarchParams) m, IN(ShadowMaps) sky_shadow) {
  if (m.sky_shadow_map < 0 || length(p - centre) >= m.earth_radius + m.sky_shadow_base) return 1.0f;
  vec2 uv = shadow_map_uv(p, centre, m.sky_shadow_base, m);
  if (uv.x < 0.0f || uv.y < 0.0f || uv.x > 1.0f || uv.y > 1.0f) return 1.0f;
  return exp(-texture(sky_shadow, vec3(uv, 0.0f)).x);
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
  float distance;  // while marching: the sum of what each step absorbs times its distance
  float weight;    // while marching: the sum of what the steps absorb
  int loop_count;
};

// The march start's offset in [0, 1) of a pixel in a frame: Jimenez's interleaved gradient
// noise ("Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH 2014),
// fract(52.9829189 fract(0.06711056 x + 0.00583715 y)), whose neighbouring pixels take offsets
// far apart (low-frequency error becomes fine grain that a few frames or a blur average out),
// plus frame x (golden ratio - 1), an additive recurrence that fills [0, 1) evenly.
float march_jitter(ivec2 pixel, int frame) {
  float ign = fract(52.9829189f * fract(0.06711056f * float(pixel.x) + 0.00583715f * float(pixel.y)));
  return fract(ign + 0.618034f * float(frame));
}

// Inside the convective span the samples follow the density volumes' voxels: one sample a voxel
// of the finest volume (VIEW_REFINE per coarse step, spaced evenly), since a cloud's edge there
// is about a voxel thick and a coarser march puts it wherever each pixel's jitter says (a moire
// of dots on the towers); at most CONVECTIVE_MAX_STEPS coarse steps. Returns 0 without clouds.
const int CONVECTIVE_MAX_STEPS = 512;
int convective_steps(float span, IN(MarchParams) m, IN(ConvectiveVolumes) convective_volumes) {
  if (m.convective_count == 0) return 0;
  float voxel = 1.0e30f;
  float n = float(textureSize(convective_volumes, 0).x);
  for (int c = 0; c < m.convective_count; ++c) voxel = min(voxel, m.convective[c].extent / n);
  return int(min(float(CONVECTIVE_MAX_STEPS), ceil(span / (float(VIEW_REFINE) * voxel))));
}

// Where sample fraction t in [0, 1] of a march interval lies, as a fraction of its length:
// quadratic (s = t^2, short steps near the start of the interval, long ones far away, where a
// pixel covers more ground anyway), or even in the convective span (convective_steps).
float march_fraction(float t, bool even) { return even ? t : t * t; }

// Marches the stretch [a, b] of the view ray d: layer `layer`'s density (-1: none) plus, when
// `convective`, the convective clouds' (where the stretch lies in their boxes). jitter in [0, 1):
// the offset of the samples within their steps; nu = cos(angle between d and the sun).
void march_interval(float a, float b, int layer, bool convective, vec3 d, vec3 centre, float jitter, float nu,
                    INOUT(CloudMarch) result, IN(MarchParams) m, IN(NoiseVolume) noise_volume,
                    IN(WeatherField) weather_field, IN(ConvectiveVolumes) convective_volumes,
                    IN(ShadowMaps) layer_shadows) {
  vec3 origin_from_centre = -centre;
  LayerParams l = m.layers[max(layer, 0)];
  // Samples spaced by march_fraction. Long grazing intervals near the horizon get up to four
  // times the samples; the convective span at least a sample a voxel.
  int steps = m.view_steps * int(clamp((b - a) / 20000.0f, 1.0f, 4.0f));
  if (convective) steps = max(steps, convective_steps(b - a, m, convective_volumes));
  float n = float(steps);
  // Sun light arriving at the layer through the clear atmosphere, once per interval.
  vec3 mid = origin_from_centre + (0.5f * (a + b)) * d;
  vec3 sunlight = solar_irradiance() * transmittance_to_space(mid, m.sun, m.earth_radius);
  float albedo = layer >= 0 ? 0.99f * (1.0f - l.darkness) : 0.0f;
  // Coarse steps probe the cheap bound (inside the convective boxes: the box test); a coarse
  // step that holds cloud (or follows one that did, to catch edges between probes) is marched
  // in VIEW_REFINE sub-steps with the full density and a light march each, so the samples go
  // where the cloud is.
  bool was_cloudy = false;
  result.loop_count += 17;  // transmittance_to_space of the interval
  for (int i = 0; i < steps && result.transmittance > 0.01f; ++i) {
    result.loop_count += 1;
    float t0 = float(i) / n;
    float t1 = float(i + 1) / n;
    float t = (float(i) + jitter) / n;
    float s = a + (b - a) * march_fraction(t, convective);
    float coarse = (b - a) * (march_fraction(t1, convective) - march_fraction(t0, convective));
    bool cloudy = layer >= 0 && extinction_bound_at(s * d, centre, layer, max(coarse, s * m.pixel_angle), m,
                                                    noise_volume, weather_field) > 0.0f;
    if (convective) {
      cloudy = true;  // the whole stretch lies in the convective span
      result.loop_count += m.convective_count;
    }
    if (!cloudy && !was_cloudy) continue;
    was_cloudy = cloudy;
    for (int j = 0; j < VIEW_REFINE && result.transmittance > 0.01f; ++j) {
      float u0 = t0 + (t1 - t0) * float(j) / float(VIEW_REFINE);
      float u1 = t0 + (t1 - t0) * float(j + 1) / float(VIEW_REFINE);
      float u = t0 + (t1 - t0) * (float(j) + jitter) / float(VIEW_REFINE);
      float sj = a + (b - a) * march_fraction(u, convective);
      float ds = (b - a) * (march_fraction(u1, convective) - march_fraction(u0, convective));
      result.loop_count += 1;
      vec3 p = sj * d;
      float sigma_layer = layer >= 0 ? density_at(p, centre, layer, max(ds, sj * m.pixel_angle), true, m,
                                                  noise_volume, weather_field) : 0.0f;
      vec2 cloud = vec2(0.0f);
      if (convective) {
        cloud = convective_at(p, centre, max(ds, sj * m.pixel_angle), m, noise_volume, convective_volumes);
        result.loop_count += m.convective_count;
      }
      float sigma = sigma_layer + cloud.x;
      if (sigma <= 0.0f) continue;
      float h = layer >= 0 ? clamp((length(p - centre) - m.earth_radius - l.base) / (l.top - l.base), 0.0f,
                                   1.0f) : cloud.y;
      if (layer >= 0 && cloud.x > 0.0f) h = (h * sigma_layer + cloud.y * cloud.x) / sigma;
      float tau = 0.0f;
      if (m.light_steps > 0) {
        // Its own layer's depth by the light march, the layers above it from their map.
        if (layer >= 0) tau = optical_depth_to_sun(p, centre, layer, m, noise_volume,
                                                   weather_field) + higher_layers_depth(p, centre, layer, m,
            layer_shadows);
        if (convective) {
          tau += convective_depth_to_sun(p, centre, m, noise_volume, convective_volumes);
          result.loop_count += m.light_steps * (1 + m.convective_count) + 2 * m.convective_count;
        }
      }
      result.loop_count += m.light_steps + 3;  // the light march and the scattering octaves
      // Ambient: half the sphere sees the sky (radiance E/pi, dimmer towards the cloud's base),
      // half the ground; isotropic scattering of a radiance field L adds sigma_s L.
      vec3 ambient = 0.5f * (m.ambient * ((0.4f + 0.6f * h) / PI_F) + m.ground_radiance);
      float scattering = albedo * sigma_layer + CONVECTIVE_ALBEDO * cloud.x;  // sigma_s
      vec3 source = scattering * (sunlight * (sun_scattering(tau, nu) * powder_factor(tau, nu, m.powder)) + ambient);
      float step_transmittance = exp(-sigma * ds);
      float absorbed = 1.0f - step_transmittance;
      result.radiance += result.transmittance * source * absorbed / sigma;
      result.distance += result.transmittance * absorbed * sj;
      result.weight += result.transmittance * absorbed;
      result.transmittance *= step_transmittance;
    }
  }
}

// The share of the sun's horizontal irradiance that clouds of optical depth tau along the sun ray
// (mu: the sun's sine) scatter down to the ground as diffuse light: a conservatively scattering
// layer of vertical optical depth t lets through about slab_diffuse_transmittance(t) of the light
// falling on it (slab_scattering.glsl); e^-tau of that is the direct sun, the rest arrives
// diffuse, white. Taken column by column along the sun ray (t = tau mu): an overcast of t = 15
// leaves the ground a third of the sun's light where the clear sky's alone was a sixth.
float cloud_diffuse_share(float tau, float mu) {
  float through = slab_diffuse_transmittance(tau * max(mu, 0.0f));
  return max(through - exp(-tau), 0.0f);
}

// Marches the layers and the convective clouds along the unit view direction d. jitter in
// [0, 1): the offset of the samples within their steps. The layers' intervals are marched in
// order of their starts; the convective span's points are each marched once with the
// convective density added: with the first layer interval that holds them (the density is then
// the sum of both, so clouds that share space are composited in depth), or, where no layer
// interval does, alone.
CloudMarch march_clouds(vec3 d, vec3 centre, float cloud_limit, float jitter, IN(MarchParams) m,
                        IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field,
                        IN(ConvectiveVolumes) convective_volumes, IN(ShadowMaps) layer_shadows) {
  RayIntervals intervals = layer_intervals(d, centre, cloud_limit, m);
  float nu = dot(d, m.sun);
  CloudMarch result;
  result.radiance = vec3(0.0f);
  result.transmittance = 1.0f;
  result.distance = 0.0f;
  result.weight = 0.0f;
  // At most, for building the sorted intervals, and the convective boxes' tests.
  result.loop_count = 4 * MAX_LAYERS * MAX_LAYERS + m.convective_count;
  vec2 span = convective_span(vec3(0.0f), d, centre, cloud_limit, m);
  float covered = span.x;  // the convective span is marched up to here
  for (int k = 0; k <= intervals.count && result.transmittance > 0.01f; ++k) {
    bool last = k == intervals.count;
    float a = last ? span.y : intervals.bounds[k].x;
    float b = last ? span.y : intervals.bounds[k].y;
    int layer = last ? -1 : intervals.layer[k];
    // The span before this interval that no layer interval holds: the convective clouds alone.
    float gap_end = min(a, span.y);
    if (covered < gap_end) march_interval(covered, gap_end, -1, true, d, centre, jitter, nu, result, m, noise_volume,
                                          weather_field, convective_volumes, layer_shadows);
    covered = max(covered, gap_end);
    if (last) break;
    float c0 = max(a, covered);
    float c1 = min(b, span.y);
    if (c0 >= c1) {
      march_interval(a, b, layer, false, d, centre, jitter, nu, result, m, noise_volume, weather_field,
                     convective_volumes, layer_shadows);
      continue;
    }
    if (a < c0) march_interval(a, c0, layer, false, d, centre, jitter, nu, result, m, noise_volume, weather_field,
                               convective_volumes, layer_shadows);
    march_interval(c0, c1, layer, true, d, centre, jitter, nu, result, m, noise_volume, weather_field,
                   convective_volumes, layer_shadows);
    if (c1 < b) march_interval(c1, b, layer, false, d, centre, jitter, nu, result, m, noise_volume, weather_field,
                               convective_volumes, layer_shadows);
    covered = c1;
  }
  result.distance = result.weight > 0.0f ? result.distance / result.weight : 0.0f;
  return result;
}

// Where the view ray in direction d ends: x, the distance to the ground (terrain.glsl), or -1
// where it meets no ground before y, the distance to the top of the atmosphere. loops: the
// terrain march's iterations. render_pixel ends its march there, and the upsampling of a render
// at reduced resolution takes x at every full-size pixel as its guide (render/view_depth.comp).
vec2 view_ray_end(vec3 d, IN(MarchParams) m, OUT(int) loops, IN(TerrainTexture) terrain_heights) {
  vec3 centre = vec3(0.0f, 0.0f, -(m.earth_radius + m.camera_altitude));
  vec2 top = ray_sphere(vec3(0.0f), d, centre, m.earth_radius + ATMOSPHERE_THICKNESS);
  float ground = terrain_hit(-centre, d, m.earth_radius, max(top.y, 0.0f), m.terrain, loops, terrain_heights);
  return vec2(ground > 0.0f ? ground : -1.0f, max(top.y, 0.0f));
}

// The pixel's radiance (RGB, linear) and cloud opacity (A): the clouds composited into the
// clear sky and the ground. loop_count: the iterations its loops took, sky and ground included;
// ground_distance: view_ray_end's x (the guide of the upsampling, render/upsample.hpp).
vec4 render_pixel(ivec2 pixel, ivec2 size, IN(MarchParams) m, OUT(int) loop_count, OUT(float) ground_distance,
                  IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field, IN(TerrainTexture) terrain_heights,
                  IN(LandCoverTexture) land_cover, IN(ConvectiveVolumes) convective_volumes, IN(ShadowMaps) layer_shadows,
                  IN(ShadowMaps) sky_shadow) {
  vec3 d = view_direction(pixel, size, m);
  vec3 centre = vec3(0.0f, 0.0f, -(m.earth_radius + m.camera_altitude));
  vec3 origin_from_centre = -centre;

  // The ray ends at the ground (terrain.glsl) or at the top of the atmosphere.
  int ground_loops = 0;
  vec2 end = view_ray_end(d, m, ground_loops, terrain_heights);
  bool hits_ground = end.x > 0.0f;
  ground_distance = end.x;
  float ray_end = hits_ground ? end.x : end.y;
  float cloud_limit = min(ray_end, m.max_distance);

  // A per-pixel offset of the samples trades banding for noise; each frame of an accumulation
  // moves it on by the golden ratio, so N frames spread every pixel's offsets evenly.
  float jitter = march_jitter(pixel, m.frame);
  CloudMarch clouds = march_clouds(d, centre, cloud_limit, jitter, m, noise_volume, weather_field, convective_volumes,
                                   layer_shadows);
  // The sky's loops (a sun transmittance per step) and the ground's.
  loop_count = clouds.loop_count + 17 * m.sky_steps + 16 + ground_loops;

  // The light around the air: the sky's (and, where the ray ends on the ground, what the clouds
  // over that ground scatter down) above, the ground's below.
  vec3 air_light = m.ground_ambient;
  vec3 ground = vec3(0.0f);
  if (hits_ground) {
    // Lambertian ground (land_cover.glsl's albedo), lit by the sun and the sky; lakes and rivers
    // mirror the sky and the sun by Fresnel's law on top of the light from under their surface.
    vec3 point = origin_from_centre + ray_end * d;
    vec3 normal = terrain_normal(point, m.earth_radius, m.terrain, terrain_heights);
    vec3 up = normalize(point);
    // The pixel's footprint on the ground, stretched along the view where it grazes the ground.
    float footprint = ray_end * m.pixel_angle / max(abs(dot(d, normal)), 0.02f);
    GroundSurface surface;
    surface.albedo = vec3(0.15f);
    surface.water = 0.0f;
    if (m.terrain.enabled != 0)
      surface = ground_surface(terrain_plane(point, m.earth_radius), length(point) - m.earth_radius, normal, up,
                               footprint, m.terrain, land_cover);
    int shadow_loops = 0;
    float sunlit = terrain_sunlit(point, normal, m.sun, m.earth_radius, m.terrain, shadow_loops, terrain_heights);
    loop_count += shadow_loops;
    // The clouds' shadows: every layer between the ground and the sun.
    int cloud_shadow_loops = 0;
    float cloud_depth = shadow_depth(ray_end * d, centre, -1, -1.0e30f, cloud_shadow_loops, m, noise_volume,
                                     weather_field, convective_volumes);
    float shadow = exp(-cloud_depth);
    loop_count += cloud_shadow_loops;
    vec3 sun_above = solar_irradiance() * transmittance_to_space(point, m.sun, m.earth_radius);
    vec3 sunlight = sun_above * (sunlit * shadow);
    vec3 sun_at_ground = sunlight * max(dot(normal, m.sun), 0.0f);
    // The sky's light and what the clouds between the point and the sun scatter down.
    vec3 diffuse = m.ground_ambient + sun_above * (max(m.sun.z, 0.0f) * cloud_diffuse_share(cloud_depth, m.sun.z));
    air_light = diffuse;
    ground = (surface.albedo / PI_F) * (sun_at_ground + diffuse);
    if (surface.water > 0.0f) {
      // The water's surface is level: the sky (its mean radiance, ambient / pi) and the sun's
      // glint on the wind-roughened facets (sun_glint.glsl) by Fresnel, the rest from below.
      vec3 sun_on_water = sunlight * max(dot(up, m.sun), 0.0f);
      vec3 water = (WATER_ALBEDO / PI_F) * (sun_on_water + diffuse) +
                   water_fresnel(dot(up, -d)) * diffuse / PI_F + sun_glint_brdf(up, -d, m.sun, LAKE_WIND) * sun_on_water;
      ground = mix(ground, water, surface.water);
    }
  }
  // The clear sky, split at the clouds' mean distance for aerial perspective, its sunlight
  // shadowed by the clouds (crepuscular rays).
  vec3 inscatter_total, inscatter_split, transmittance_total, transmittance_split;
  SkyIntegral sky = sky_integral_begin(d, ray_end, clouds.distance, m.sun, m.sky_steps);
  sky.skylight = 0.5f * (air_light / PI_F + m.ground_radiance);
  for (int i = 0; i < m.sky_steps; ++i) {
    vec3 q = sky_integral_point(sky, origin_from_centre, d, i);
    sky_integral_step(sky, q, i, m.sun, m.earth_radius, sky_sun_visibility(q + centre, centre, m, sky_shadow));
  }
  sky_integral_end(sky, inscatter_total, inscatter_split, transmittance_total, transmittance_split);
  vec3 background = hits_ground ? transmittance_total * ground : vec3(0.0f);
  vec3 color = inscatter_split + transmittance_split * clouds.radiance +
               clouds.transmittance * (inscatter_total - inscatter_split + background);
  return vec4(color, 1.0f - clouds.transmittance);
}

#endif
