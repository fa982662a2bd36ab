// Probe of lib/cloud_march.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp). The
// GLSL side reads the renderer's textures at their units (render/march_sources.glsl).
// The functions (x[0].x):
const int PROBE_VIEW_DIRECTION = 0;
const int PROBE_COVERAGE_AT = 1;
const int PROBE_SHAPE_AT = 2;
const int PROBE_DENSITY_AT = 3;  // extinction_bound, extinction_bound_at, density_at
const int PROBE_OPTICAL_DEPTH_TO_SUN = 4;
const int PROBE_LAYER_INTERVALS = 5;
const int PROBE_MARCH_CLOUDS = 6;
const int PROBE_RENDER_PIXEL = 7;
const int PROBE_LOOP_LIMITED = 8;  // loop_limited(x[0].y)
const int PROBE_BAKED_FIELDS = 9;  // baked_fields, baked_g3, baked_w3
const int PROBE_WEBANCK_SHAPE = 10;  // webanck_shape, webanck_detail
const int PROBE_SHADOW_DEPTH = 11;  // shadow_depth, march_jitter
const int PROBE_CONVECTIVE_AT = 12;  // convective_at, convective_coordinates
const int PROBE_CONVECTIVE_BOX = 13;  // convective_box, convective_span
const int PROBE_CONVECTIVE_SHADOW = 14;  // convective_depth_to_sun, convective_shadow_depth
const int PROBE_MARCH_WITH_CONVECTIVE = 15;  // march_clouds with the convective cloud
const int PROBE_MARCH_CONVECTIVE_INTERVAL = 16;  // march_interval with the convective cloud
const int PROBE_SHADOW_MAP_UV = 17;  // shadow_map_uv, higher_layers_depth
const int PROBE_SHADOW_MAP_ORIGIN = 18;  // shadow_map_origin, shadow_map_xy
const int PROBE_SHADOW_MAP_TEXEL = 19;  // shadow_map_texel, layers_shadow_depth
const int PROBE_SKY_SUN_VISIBILITY = 20;  // shadow_map_uv, sky_sun_visibility
const int PROBE_VIEW_RAY_END = 21;
const int PROBE_CONVECTIVE_DENSITY = 22;
// detail_eroded(x[0].z at x[1] with footprint x[0].w, strength x[0].y) and
// convective_at(x[2], the same footprint and strength)
const int PROBE_DETAIL_EROSION = 24;
const int PROBE_CLOUD_DIFFUSE_SHARE = 25;  // cloud_diffuse_share(x[0].y, x[0].z)
const int PROBE_CONVECTIVE_STEPS = 23;  // convective_steps over x[0].y metres, march_fraction(x[0].z)
#ifndef __cplusplus
// The renderer's textures and hooks (one convective volume here: its stack of one clamps as the
// C++ twin's ConvectiveSource does).
#include "../render/march_sources.glsl"
#endif

// A cumulus and an alto layer seen from 860 m, the sun 40 degrees up in the south-west.
MarchParams probe_march_params() {
  MarchParams m;
  m.layers[0].type = CLOUD_CUMULUS;
  m.layers[0].channel = 2;
  m.layers[0].base = 1500.0f;
  m.layers[0].top = 3000.0f;
  m.layers[0].extinction = 0.01f;
  m.layers[0].morph = 0.0f;
  m.layers[0].darkness = 0.0f;
  m.layers[0].min_distance = 0.0f;
  m.layers[0].wind = vec2(0.6f, 0.8f);
  m.layers[0].noise_offset = vec2(120.0f, 0.0f);
  m.layers[1].type = CLOUD_ALTO;
  m.layers[1].channel = 1;
  m.layers[1].base = 3500.0f;
  m.layers[1].top = 5000.0f;
  m.layers[1].extinction = 0.002f;
  m.layers[1].morph = 0.5f;
  m.layers[1].darkness = 0.2f;
  m.layers[1].min_distance = 0.0f;
  m.layers[1].wind = vec2(0.6f, 0.8f);
  m.layers[1].noise_offset = vec2(120.0f, 0.0f);
  m.layers[0].shadow_map = 0;   // the cumulus lies wholly below the alto
  m.layers[1].shadow_map = -1;
  m.layer_count = 2;
  m.earth_radius = 6367000.0f;
  m.camera_altitude = 860.0f;
  m.forward = vec3(0.0f, 0.9781476f, 0.2079117f);
  m.right = vec3(1.0f, 0.0f, 0.0f);
  m.up = vec3(0.0f, -0.2079117f, 0.9781476f);
  m.tan_half_fov = 0.7f;
  m.panorama = 0;
  m.heading = 0.3f;
  m.sun = vec3(-0.5416752f, -0.5416752f, 0.6427876f);
  m.ambient = vec3(0.3f, 0.45f, 0.7f);
  m.ground_ambient = vec3(0.35f, 0.5f, 0.75f);
  m.ground_radiance = vec3(0.05f, 0.05f, 0.045f);
  m.view_steps = 6;
  m.light_steps = 3;
  m.sky_steps = 6;
  m.weather_extent = 40000.0f;
  m.max_distance = 150000.0f;
  m.shadow_extent = 30000.0f;
  m.sky_shadow_map = -1;  // the one map is the cumulus's (PROBE_SKY_SUN_VISIBILITY lends it to the sky)
  m.sky_shadow_base = 1500.0f;
  m.powder = 0.0f;
  m.pixel_angle = 0.0875f;
  m.noise_texels = 16.0f;
  m.terrain.enabled = 0;  // the bare sphere (tests/probes/terrain.glsl probes the terrain)
  m.terrain.extent = 1.0f;
  m.terrain.top = 0.0f;
  m.terrain.texel = 1.0f;
  m.terrain.reach = 0.0f;
  m.terrain.land = 0;  // no land cover (tests/probes/land_cover.glsl probes it)
  m.terrain.land_near = 1.0f;
  m.terrain.land_far = 1.0f;
  m.terrain.land_texels = 1.0f;
  m.terrain.snow_line = 2500.0f;
  m.terrain.crop_stage = 1.0f;
  // One convective cloud 20 km north, turned to (0.6, 0.8); marched only by PROBE_CONVECTIVE_AT to
  // PROBE_MARCH_CONVECTIVE_INTERVAL.
  m.convective_count = 0;
  m.detail_erosion = 0.0f;
  for (int c = 0; c < MAX_CONVECTIVE; ++c) {
    m.convective[c].centre = vec2(0.0f, 20000.0f);
    m.convective[c].axis = vec2(0.6f, 0.8f);
    m.convective[c].bottom = 1000.0f;
    m.convective[c].extent = 6000.0f;
    m.convective[c].cloud_base = 1500.0f;
    m.convective[c].cloud_top = 6000.0f;
    m.convective[c].extinction = 0.01f;
  }
  return m;
}

// x[0] = (function, a, b, c), x[1] = a point, x[2] = a direction, x[3] = further numbers.
vec4 probe_cloud_march(mat4 x, IN(NoiseVolume) noise_volume, IN(WeatherField) weather_field,
                       IN(TerrainTexture) terrain_heights, IN(LandCoverTexture) land_cover,
                       IN(ConvectiveVolumes) convective_volumes,
                       IN(ShadowMaps) layer_shadows, IN(ShadowMaps) sky_shadow) {
  int f = int(x[0].x);
  MarchParams m = probe_march_params();
  vec3 p = vec3(x[1]);
  vec3 d = vec3(x[2]);
  vec3 centre = vec3(0.0f, 0.0f, -(m.earth_radius + m.camera_altitude));
  int layer = int(x[0].y);
  float footprint = x[0].z;
  if (f == PROBE_VIEW_DIRECTION) {
    m.panorama = int(x[0].w);
    return vec4(view_direction(ivec2(int(x[3].x), int(x[3].y)), ivec2(16, 9), m), 0.0f);
  }
  if (f == PROBE_COVERAGE_AT) return vec4(coverage_at(p, int(x[0].y), m, weather_field), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SHAPE_AT) {
    ShapeSample q = shape_at(p, centre, layer, footprint, WEBANCK_FULL, m, noise_volume, weather_field);
    return vec4(q.h, q.c, q.shape, q.detail);
  }
  if (f == PROBE_DENSITY_AT) {
    ShapeSample q = shape_at(p, centre, layer, footprint, WEBANCK_FULL, m, noise_volume, weather_field);
    return vec4(extinction_bound(layer, q, m), extinction_bound_at(p, centre, layer, footprint, m, noise_volume,
                                                                   weather_field),
                density_at(p, centre, layer, footprint, true, m, noise_volume, weather_field),
                density_at(p, centre, layer, footprint, false, m, noise_volume, weather_field));
  }
  if (f == PROBE_OPTICAL_DEPTH_TO_SUN)
    return vec4(optical_depth_to_sun(p, centre, layer, m, noise_volume, weather_field), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_LAYER_INTERVALS) {
    RayIntervals r = layer_intervals(d, centre, x[0].z, m);
    return vec4(float(r.count), r.count > 0 ? r.bounds[0].x : 0.0f, r.count > 0 ? r.bounds[0].y : 0.0f,
                r.count > 0 ? float(r.layer[0]) : -1.0f);
  }
  if (f == PROBE_MARCH_CLOUDS) {
    CloudMarch c = march_clouds(d, centre, x[0].z, x[0].w, m, noise_volume, weather_field, convective_volumes,
                                layer_shadows);
    return vec4(c.radiance, c.transmittance);
  }
  if (f == PROBE_RENDER_PIXEL) {
    int loops = 0;
    float ground = 0.0f;
    vec4 pixel = render_pixel(ivec2(int(x[3].x), int(x[3].y)), ivec2(16, 9), m, loops, ground, noise_volume,
                              weather_field, terrain_heights, land_cover, convective_volumes, layer_shadows,
                              sky_shadow);
    return loop_limited(loops) ? vec4(-1.0f) : pixel;
  }
  if (f == PROBE_VIEW_RAY_END) {
    // Where the view ray d ends: the ground's distance (or -1) and the atmosphere's top.
    int loops = 0;
    vec2 end = view_ray_end(d, m, loops, terrain_heights);
    return vec4(end, float(loops), 0.0f);
  }
  if (f == PROBE_BAKED_FIELDS) {
    // The baked Webanck fields at p_n = x[1] (frequency x[0].z, level of detail x[0].w).
    vec4 v = baked_fields(p, footprint, layer, x[0].w, noise_volume);
    return vec4(v.z, baked_g3(p, footprint, layer, x[0].w, noise_volume), baked_w3(p, footprint, layer, x[0].w,
        noise_volume),
                webanck_type(layer) ? 1.0f : 0.0f);
  }
  if (f == PROBE_WEBANCK_SHAPE) {
    // Webanck's shape (fields x[0].w) and detail of layer x[0].y at p_n = x[1], h and c in x[3].
    ShapeSample q;
    q.h = x[3].x;
    q.c = x[3].y;
    q.lod = x[3].z;
    q.coordinates = p;
    webanck_shape(q, m.layers[layer].type, 0.5f, 0.01f, int(x[0].w), noise_volume);
    return vec4(q.shape, q.detail, q.gate, webanck_detail(q, m.layers[layer].type, 0.5f, 0.01f, noise_volume));
  }
  if (f == PROBE_SHADOW_DEPTH) {
    // Shadow depth from p (below layer x[0].y's top, min_base x[0].z) and a pixel's jitter.
    int loops = 0;
    float tau = shadow_depth(p, centre, layer, footprint, loops, m, noise_volume, weather_field, convective_volumes);
    return vec4(tau, float(loops), march_jitter(ivec2(int(x[3].x), int(x[3].y)), int(x[3].z)), 0.0f);
  }
  if (f == PROBE_SHADOW_MAP_UV) {
    // The shadow map of layer x[0].y: where p's sun ray leaves the layer's top (uv), and the
    // depth read there.
    vec2 uv = shadow_map_uv(p, centre, m.layers[layer].top, m);
    return vec4(uv, higher_layers_depth(p, centre, layer, m, layer_shadows), 0.0f);
  }
  if (f == PROBE_SKY_SUN_VISIBILITY) {
    // Crepuscular rays: the sky's map (the test binds the cumulus's there too) from the shell at
    // altitude x[0].z: where p's sun ray leaves it (uv) and the sun's share at p.
    m.sky_shadow_map = 0;
    m.sky_shadow_base = x[0].z;
    vec2 uv = shadow_map_uv(p, centre, x[0].z, m);
    return vec4(uv, sky_sun_visibility(p, centre, m, sky_shadow), 0.0f);
  }
  if (f == PROBE_SHADOW_MAP_ORIGIN) {
    // The top shell's point above the tangent-plane coordinates x[3].xy, and its coordinates
    // again.
    vec3 q = shadow_map_origin(vec2(x[3]), centre, m.layers[layer].top, m);
    vec2 xy = shadow_map_xy(q, centre);
    return vec4(length(q - centre) - m.earth_radius, xy.x - x[3].x, xy.y - x[3].y, 0.0f);
  }
  if (f == PROBE_SHADOW_MAP_TEXEL) {
    // Depths through the layers above: the texel value at uv = x[3].xy, and the march from the
    // top shell's point there.
    int loops = 0;
    vec3 q = shadow_map_origin((2.0f * vec2(x[3]) - 1.0f) * m.shadow_extent, centre, m.layers[layer].top, m);
    return vec4(shadow_map_texel(vec2(x[3]), centre, layer, loops, m, noise_volume, weather_field, convective_volumes),
                layers_shadow_depth(q, centre, layer, m.layers[layer].top, loops, m, noise_volume, weather_field),
                0.0f, 0.0f);
  }
  if (f == PROBE_CONVECTIVE_DENSITY) {
    // Convective volume x[0].y at q = x[1].
    return vec4(convective_density(convective_volumes, vec3(x[1]), int(x[0].y)), 0.0f, 0.0f, 0.0f);
  }
  m.convective_count = 1;
  if (f == PROBE_CLOUD_DIFFUSE_SHARE) return vec4(cloud_diffuse_share(x[0].y, x[0].z), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_DETAIL_EROSION) {
    m.detail_erosion = x[0].y;
    return vec4(detail_eroded(x[0].z, vec3(x[1]), x[0].w, m, noise_volume),
                convective_at(vec3(x[2]), centre, x[0].w, m, noise_volume, convective_volumes), 0.0f);
  }
  if (f == PROBE_CONVECTIVE_STEPS)
    return vec4(float(convective_steps(x[0].y, m, convective_volumes)), march_fraction(x[0].z, true),
                march_fraction(x[0].z, false), 0.0f);
  if (f == PROBE_CONVECTIVE_AT) {
    // The convective cloud at p: extinction, height fraction, inside its box, volume z.
    vec2 v = convective_at(p, centre, x[3].w, m, noise_volume, convective_volumes);
    vec3 q = convective_coordinates(p, centre, 0, m);
    return vec4(v.x, v.y, in_unit_cube(q) ? 1.0f : 0.0f, q.z);
  }
  if (f == PROBE_CONVECTIVE_BOX) {
    // A ray from p along d (limit x[0].z): its box interval and the span.
    return vec4(convective_box(p, d, centre, 0, x[0].z, m), convective_span(p, d, centre, x[0].z, m));
  }
  if (f == PROBE_CONVECTIVE_SHADOW) {
    int loops = 0;
    float shadow = convective_shadow_depth(p, centre, loops, m, noise_volume, convective_volumes);
    return vec4(convective_depth_to_sun(p, centre, m, noise_volume, convective_volumes), shadow, float(loops), 0.0f);
  }
  if (f == PROBE_MARCH_WITH_CONVECTIVE) {
    // The layers and the convective cloud marched together (limit x[0].z, jitter x[0].w), the
    // layers' extinctions scaled by x[3].x where it is positive (so that the march reaches a
    // cloud behind them).
    if (x[3].x > 0.0f) {
      for (int l = 0; l < m.layer_count; ++l) m.layers[l].extinction *= x[3].x;
    }
    CloudMarch c = march_clouds(d, centre, x[0].z, x[0].w, m, noise_volume, weather_field, convective_volumes,
                                layer_shadows);
    return vec4(c.radiance, c.transmittance);
  }
  if (f == PROBE_MARCH_CONVECTIVE_INTERVAL) {
    // The convective cloud on [x[3].x, x[3].y] of the ray d (jitter x[0].w), with layer x[0].y
    // (-1: alone).
    CloudMarch c;
    c.radiance = vec3(0.0f);
    c.transmittance = 1.0f;
    c.distance = 0.0f;
    c.weight = 0.0f;
    c.loop_count = 0;
    march_interval(x[3].x, x[3].y, layer, true, d, centre, x[0].w, dot(d, m.sun), c, m, noise_volume, weather_field,
                   convective_volumes, layer_shadows);
    return vec4(c.radiance, c.transmittance);
  }
  return vec4(loop_limited(int(x[0].y)) ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);  // PROBE_LOOP_LIMITED
}

#ifndef __cplusplus
// The GPU probe passes x alone: the renderer's textures at their units.
vec4 probe_cloud_march(mat4 x) {
  return probe_cloud_march(x, noise_volume, weather_field, terrain_heights, land_cover, convective_volumes, layer_shadows,
                           sky_shadow);
}
#endif
