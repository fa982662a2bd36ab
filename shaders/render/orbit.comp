#version 450
// The orbit view (docs/orbit_view.md): a textured planet, volumetric clouds whose columns follow
// the global cover's cube map (cover, optical thickness and cloud-top height: each texel's cloud
// a slab below its top, as thick as its type and tau make it), cloud shadows on the ground, city
// lights on the night side and the atmosphere of shaders/lib/atmosphere.glsl (single scattering
// and the table of multiple scattering) in front of both, the sunlight everywhere through the air
// of the transmittance table.
// One invocation per pixel, one work group per tile of ORBIT_TILE x ORBIT_TILE pixels listed in
// `tiles` (the tiles whose rays can meet the air: src/render/orbit_tiles.cpp, whose ORBIT_TILE is
// this one; the host clears the others). Positions are relative to the camera: the host computes
// the camera and planet in double and hands over the planet's centre relative to the camera as float, and
// for each sphere q = |camera - centre|^2 - r^2 (exact in double; in float it would cancel
// catastrophically near the ground). Axes are Earth-centred, Earth-fixed (+Z north, +X latitude
// 0 longitude 0), as the cover's cube map is.
const int ORBIT_TILE = 8;
layout(local_size_x = ORBIT_TILE, local_size_y = ORBIT_TILE, local_size_z = 1) in;
layout(rgba32f, binding = 0) uniform writeonly image2D radiance_image;
layout(binding = 1) uniform sampler2D day_texture;    // equirect, linear RGB, row 0 = north
layout(binding = 2) uniform sampler2D night_texture;  // equirect, linear RGB (city lights)
layout(binding = 3) uniform samplerCube cover_map;    // (cover, tau, cloud top km, 0), GL face convention
layout(binding = 4) uniform sampler2D sky_table;      // the air's multiple scattering (atmosphere.glsl)
layout(binding = 5) uniform sampler2D water_texture;  // equirect, fraction of open water (sun glint)
layout(std430, binding = 6) readonly buffer Tiles { uvec2 tiles[]; };  // (column, row), tile units
layout(binding = 7) uniform sampler2D transmittance_table;  // the air's transmittance to its top (atmosphere.glsl)
layout(binding = 8) uniform sampler2D relief_texture;  // equirect, the ground's slopes (east, north), m/m
layout(binding = 9) uniform sampler2D coast_texture;   // a window's share of water (GSHHG), row 0 = north

#include "../lib/atmosphere.glsl"
#include "../lib/cloud_properties.glsl"
#include "../lib/cube_bspline.glsl"
#include "../lib/equirect_mapping.glsl"
#include "../lib/ground_relief.glsl"
#include "../lib/hash.glsl"
#include "../lib/land_mosaic.glsl"
#include "../lib/slab_scattering.glsl"
#include "../lib/sun_glint.glsl"

uniform int u_tile_count;      // entries of `tiles`
uniform ivec2 u_image_size;    // the camera's pixels (the image may be larger)
uniform vec3 u_centre;         // planet centre relative to the camera, m
uniform float u_q_ground;      // |camera - centre|^2 - r^2 for the ground, cloud base, cloud top
uniform float u_q_base;        // and atmosphere top spheres (double on the host), m^2
uniform float u_q_top;
uniform float u_q_atmosphere;
uniform float u_radius;        // planet radius, m
uniform float u_cloud_base;    // altitude of the shell's bottom, m: no cloud below
uniform float u_cloud_top;     // altitude of the shell's top, m: none above
uniform vec3 u_forward;
uniform vec3 u_right;
uniform vec3 u_up;
uniform float u_tan_half_fov;
uniform float u_pixel_angle;   // radians per pixel
uniform vec3 u_sun;            // unit direction towards the sun
uniform float u_night_lights;  // radiance of a city-light texel of value 1
uniform float u_sea_wind;      // mean wind over the sea, m/s (the glint's facet slopes; sea_wind_speed)
uniform float u_cover_texel;   // arc length of one cover texel on the ground, m
uniform float u_cover_size;    // cover texels along a face edge
uniform int u_cover_properties;  // 1: the cover map holds tau and cloud tops; 0: derived from the cover
uniform float u_tau_median;      // the fallback's log-normal (the table's defaults)
uniform float u_tau_spread;
uniform float u_cloud_detail;   // 0: the cover's texels as they are; 1: the sub-texel cloud (cloud_slab)
uniform float u_cloud_tau_spread;  // deviation of ln tau inside a texel's cloud (subtexel_optical_thickness)
uniform vec4 u_coast_window;   // coast_texture's south, north, west, east edges (radians); west >= east: none
uniform float u_coast_texel;   // m a coast texel spans north to south
uniform int u_sea_colour;      // 1: water takes the sea's own colour where the day map's alpha (no ice) lets it
uniform float u_day_texel;     // arc length of one day-texture texel, m
uniform float u_relief_texel;  // and of one relief texel
uniform int u_cloud_steps;
uniform int u_shadow_steps;
uniform int u_sky_steps;

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

float cover_lod(float footprint) { return max(log2(max(footprint, 1.0f) / u_cover_texel), 0.0f); }

// The cover's channels (cover, tau, top km, 0) in direction n at mip level `lod`. Where a cover
// texel spans more than a sample (lod < 1) the base level is filtered by the cubic B-spline
// (cube_bspline.glsl): trilinear lookups alone show the texel grid as a staircase of straight
// edges from low orbit. Between lod 0 and 1 the two are blended, so nothing switches with
// distance. Samples that are never seen as edges (`smoothed` false: the light's segments beyond
// its first, which only dim it) take the trilinear lookup alone: the B-spline's four cube lookups
// are most of a cloud sample's cost on llvmpipe. (There the `if` runs for whole groups of lanes,
// masked: prelude.glsl. Measured, leaving the B-spline out altogether gives the same `bench
// orbit` time, 1.59 against 1.60 s at 1280x720.)
// Where the unit vector n lies in coast_texture (false: outside its window).
bool coast_uv(vec3 n, out vec2 uv) {
  uv = vec2(0.0f);
  if (u_coast_window.z >= u_coast_window.w) return false;
  float lat = asin(clamp(n.z, -1.0f, 1.0f));
  float lon = atan(n.y, n.x);
  lon = u_coast_window.z + mod(lon - u_coast_window.z, 2.0f * PI_F);  // from the west edge eastwards
  if (lat < u_coast_window.x || lat > u_coast_window.y || lon > u_coast_window.w) return false;
  uv = vec2((lon - u_coast_window.z) / (u_coast_window.w - u_coast_window.z),
            (u_coast_window.y - lat) / (u_coast_window.y - u_coast_window.x));
  return true;
}

vec4 cover_at(vec3 n, float lod, bool smoothed) {
  vec4 mipmapped = textureLod(cover_map, n, lod);
  vec4 result = mipmapped;
  if (smoothed && lod < 1.0f) {
    CubeBsplineTaps taps = cube_bspline_taps(n, u_cover_size);
    vec4 c00 = textureLod(cover_map, taps.d00, 0.0f), c10 = textureLod(cover_map, taps.d10, 0.0f);
    vec4 c01 = textureLod(cover_map, taps.d01, 0.0f), c11 = textureLod(cover_map, taps.d11, 0.0f);
    result = mix(cube_bspline_combine(taps, c00, c10, c01, c11), mipmapped, lod);
  }
  return result;
}

// The relief of the clouds' tops: the sub-texel field raises the top by this share of the cloud's
// depth per standard deviation (domes over the cores, lower towards the edges; a cumulonimbus of
// 15 km gets overshooting tops of about 2 km, a stratocumulus deck of 300 m undulations of 45 m),
// so that a low sun shows the tops' texture by their shadows on each other. The bases stay flat.
const float TOP_RELIEF_SHARE = 0.15f;

// The cloud's slab at p (m from the planet's centre): (base m, top m, extinction 1/m, the cloud's
// own extinction 1/m), extinctions 0 where clear. The texel's cloud covers the share `cover` of it
// with optical thickness tau; below the texel, subtexel_cloud (cloud_properties.glsl) says which
// part of the sample's footprint is cloudy, with fractal edges down to the footprint's scale and
// the cover's own value where a sample spans half a texel or more, and how thick its cloud is
// there (subtexel_optical_thickness: thicker under the tops' domes, the texel's tau as the
// geometric mean). The sample's mean transmittance
// 1 - c (1 - exp(-tau)) is that of a uniform slab of optical depth covered_optical_depth(c, tau):
// thin cloud and the grey edges let the surface show through, thick cloud is opaque. The light
// that diffuses through the cloud goes by the cloud's own tau (the fourth component), not by that
// mean. The slab reaches from the type's top down by cloud_thickness_km, its top raised or lowered
// by the field's relief. Every ray takes the slab at its own footprint: the view's at the pixel's,
// the light's at its first segment's length (beyond it, the cover's mean: optical_depth_to_sun),
// so the shadows are as sharp as their rays resolve.
// `heights` (lowest, highest altitude, m) is the part of the column the caller needs: where it
// lies wholly below the base or above the highest top the relief can raise, the slab is not
// looked at further (the sub-texel cloud costs up to twelve octaves of noise) and is clear.
// `smoothed`: the cover filtered by the B-spline where its texels are resolved (cover_at).
vec4 cloud_slab(vec3 p, float footprint, vec2 heights, bool smoothed) {
  vec3 n = normalize(p);
  vec4 c = cover_at(n, cover_lod(footprint), smoothed);
  if (u_cover_properties == 0) {
    c.y = optical_thickness_from_cover(c.x, u_tau_median, u_tau_spread);
    c.z = cloud_top_from_cover(c.x, asin(clamp(n.z, -1.0f, 1.0f)));
  }
  if (c.x <= 0.0f || c.y <= 0.0f) return vec4(0.0f);
  float top = 1000.0f * c.z;
  float thickness = 1000.0f * cloud_thickness_km(c.z, c.y);
  float base = max(top - thickness, u_cloud_base);
  if (heights.y < base || heights.x > top + u_cloud_detail * TOP_RELIEF_SHARE * SUBTEXEL_RELIEF_BOUND * thickness)
    return vec4(0.0f);
  float cover = c.x, tau = c.y;
  if (u_cloud_detail > 0.0f) {
    SubtexelCloud detail = subtexel_cloud(n * u_radius, c.x, u_cover_texel, footprint);
    cover = mix(c.x, detail.cover, u_cloud_detail * subtexel_carving(c.z, c.y));
    tau = mix(c.y, subtexel_optical_thickness(c.y, detail, u_cloud_tau_spread), u_cloud_detail);
    top = max(top + u_cloud_detail * TOP_RELIEF_SHARE * thickness * detail.relief, base + 0.1f * thickness);
  }
  float extinction = covered_optical_depth(cover, tau) / thickness;
  return vec4(base, min(top, u_cloud_top), extinction, tau / thickness);
}

// The mean extinctions (1/m; cloud_slab's two) over the segment from p to p + dt d (relative to the
// planet's centre):
// the slab at the segment's middle, times the share of the segment's altitudes inside it, so that
// a slab thinner than a step (a stratocumulus deck of 300 m under a step of a kilometre) has its
// whole optical depth instead of being hit or missed by a sample. `inside` is where the light is
// evaluated: in the segment's part in the slab, at its middle or, in thick cloud, one mean free
// path (1 / extinction) past where the segment enters it, which is where the light that leaves
// the segment was scattered on average: the lit side of a thick cloud, not its dark inside.
// `column` is (the slab's own optical thickness, the own and the mean optical depth of `inside`
// below the slab's top), for the light of its multiple scattering (slab_source).
vec2 segment_extinction(vec3 p, vec3 d, float dt, float footprint, bool smoothed, out vec3 inside, out vec3 column) {
  vec3 middle = p + 0.5f * dt * d;
  inside = middle;
  column = vec3(0.0f);
  float h0 = length(p) - u_radius, h1 = length(p + dt * d) - u_radius;
  float low = min(h0, h1), high = max(h0, h1);
  vec4 slab = cloud_slab(middle, footprint, vec2(low, high), smoothed);
  if (slab.z <= 0.0f || slab.y <= slab.x) return vec2(0.0f);
  float overlap;
  if (high - low < 1.0e-3f * max(dt, 1.0f)) {
    float h = 0.5f * (low + high);
    overlap = h > slab.x && h < slab.y ? 1.0f : 0.0f;
  } else {
    float a = max(low, slab.x), b = min(high, slab.y);
    overlap = clamp((b - a) / (high - low), 0.0f, 1.0f);
    // Where the segment enters the slab and how far it runs in it (linear in t: near enough
    // over a step).
    float entry = clamp(((h1 > h0 ? a : b) - h0) / (h1 - h0), 0.0f, 1.0f) * dt;
    float inside_length = overlap * dt;
    inside = p + (entry + min(0.5f * inside_length, 1.0f / slab.z)) * d;
  }
  float below_top = clamp(slab.y - (length(inside) - u_radius), 0.0f, slab.y - slab.x);
  column = vec3(slab.w * (slab.y - slab.x), slab.w * below_top, slab.z * below_top);
  return slab.zw * overlap;
}

// Optical depths of the clouds from p (relative to the centre) towards the sun, `steps` segments
// spread over the path to the shell's top (at most 60 km: beyond, low sun light is gone anyway):
// the mean one (direct light) and the clouds' own (the light diffusing through them).
vec2 optical_depth_to_sun(vec3 p, int steps, float footprint) {
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
  vec2 depth = vec2(0.0f);
  vec3 inside, column;
  for (int i = 0; i < steps; ++i) {
    float t0 = float(i) / float(steps), t1 = float(i + 1) / float(steps);
    // Quadratic spacing: short steps near p, where the light's shadow detail is.
    float s0 = start + span * t0 * t0, s1 = start + span * t1 * t1;
    // The light integrates the clouds across the segment: they are looked up at its length's
    // scale. The B-spline and the sub-texel cloud only in the first segment, where the tops'
    // relief shades its neighbours and the shadows' edges are drawn; beyond it the cover's mean
    // (its expectation) by one trilinear lookup, at a fraction of the cost of a light ray.
    float scale = max(footprint, 0.5f * (s1 - s0));
    if (i > 0) scale = max(scale, u_cover_texel);
    depth += segment_extinction(p + s0 * u_sun, u_sun, s1 - s0, scale, i == 0, inside, column) * (s1 - s0);
  }
  return depth;
}

// The sunlight through the clouds of depths (mean, own): the direct beam by the mean, the rest
// diffusing through the cloud by its own depth.
float cloud_shadow(vec2 depth) {
  float direct = exp(-depth.x);
  return direct + (1.0f - direct) * slab_diffuse_transmittance(depth.y);
}

// The phase function of the view's single scattering (nu the cosine between the view ray and the
// sun): the droplets' forward lobe (g = 0.85, the silver lining) and a tenth in a broad backward
// lobe for the glory side, about 0.025 per steradian straight back, near the 0.02-0.04 of cloud
// droplets' Mie phase function between 140 and 170 degrees (Hansen and Travis 1974). A stronger
// backward lobe (0.3 of HG(-0.3): 0.07 per steradian) made thin cloud seen from above brighter by
// its single scattering alone than the delta-Eddington slab's whole reflectance.
float cloud_view_phase(float nu) { return 0.9f * henyey_greenstein(nu, 0.85f) + 0.1f * henyey_greenstein(nu, -0.3f); }

void main() {
  int tile = int(gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x);
  if (tile >= u_tile_count) return;
  ivec2 pixel = ivec2(tiles[tile]) * ORBIT_TILE + ivec2(gl_LocalInvocationID.xy);
  ivec2 size = u_image_size;
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
    // Each segment's slab integral is exact where the segment stays over one column, so a ray
    // needs segments only as often as it moves across the cloud's detail: two per cover texel of
    // its horizontal travel in the shell and, with the sub-texel cloud, one per finest wavelength
    // it resolves there (four footprints at the shell's entry). A nadir ray from orbit takes 2,
    // one near the limb or close to the clouds up to u_cloud_steps.
    vec3 entry = oc + shell.x * d;
    float across = sqrt(max(1.0f - pow(dot(d, normalize(entry)), 2.0f), 0.0f));
    float travel = (len0 + len1) * across;
    float per_length = 2.0f / u_cover_texel;
    if (u_cloud_detail > 0.0f) per_length = max(per_length, 0.25f / max(shell.x * u_pixel_angle, 1.0f));
    int steps = clamp(int(ceil(travel * per_length)) + 1, 2, max(u_cloud_steps, 2));
    float dt = (len0 + len1) / float(steps);
    vec3 sun_at_cloud = vec3(-1.0f);  // sunlight at the shell, computed at the first dense sample
    float nu = dot(d, u_sun);
    float phase = cloud_view_phase(nu);
    // Segments between the boundaries (k + jitter) dt, k = 0 .. steps - 1, and the ends (so that
    // the boundaries do not line up between pixels); a segment across the gap between the two
    // intervals is taken in its two parts.
    // On llvmpipe a `continue` or an `if` skips nothing for a group of lanes (they run masked), but
    // a loop ends when its last lane does: so the work that a ray may not need is bounded by trip
    // counts (the second interval's part, the light's steps), which leave the image as it was.
    float total = len0 + len1;
    int parts = len1 > 0.0f ? 2 : 1;
    for (int i = 0; i <= steps && cloud_transmittance > 0.005f; ++i) {
      float a = i == 0 ? 0.0f : min((float(i) - 1.0f + jitter) * dt, total);
      float e = i == steps ? total : min((float(i) + jitter) * dt, total);
      for (int part = 0; part < parts; ++part) {
        float s0 = part == 0 ? a : max(a, len0);
        float s1 = part == 0 ? min(e, len0) : e;
        if (s1 <= s0) continue;
        float t = s0 < len0 ? shell.x + s0 : shell.z + (s0 - len0);
        float segment = s1 - s0;
        vec3 p;
        // The pixel's footprint on the cloud: across the ray t alpha, and along the surface that
        // over the cosine of the ray's incidence, which near the horizon is many times longer.
        // The sub-texel cloud is filtered by the longer (as GPUs choose a texture's level by the
        // larger axis): by the shorter, the octaves between the two would alias into speckle.
        vec3 at = oc + t * d;
        float incidence = max(abs(dot(d, at)) / length(at), 0.05f);
        float footprint = max(t * u_pixel_angle / incidence, 0.25f * dt);
        vec3 column;
        float sigma = segment_extinction(at, d, segment, footprint, true, p, column).x;
        if (sigma <= 0.0f) continue;
        vec3 n = normalize(p);
        if (sun_at_cloud.x < 0.0f) sun_at_cloud = solar_irradiance() * transmittance_from_table(transmittance_table, p, u_sun, u_radius);
        vec2 tau_light = optical_depth_to_sun(p, sigma > 0.0f ? 4 : 0, footprint);
        // Single scattering, plus the multiply scattered light of the sample's own slab
        // (slab_source: the slab reflects and lets through what the delta-Eddington slab does),
        // dimmed by the clouds between the slab's top and the sun, and the sky's light.
        float mu0 = dot(n, u_sun);
        vec2 diffuse = slab_source(column.x, mu0, cloud_view_phase(-mu0), cloud_view_phase(mu0));
        vec2 above = max(tau_light - column.zy / max(mu0, SLAB_MIN_MU0), vec2(0.0f));
        vec3 source = sun_at_cloud * (phase * exp(-tau_light.x) + slab_source_at(diffuse, column.y) * cloud_shadow(above)) +
                      sky_ambient(n, u_sun) * slab_sky_source(column.x);
        float step_transmittance = exp(-sigma * segment);
        float hit_distance = length(p - oc);
        cloud_light += cloud_transmittance * source * (1.0f - step_transmittance);
        weighted_distance += hit_distance * cloud_transmittance * (1.0f - step_transmittance);
        weight_sum += cloud_transmittance * (1.0f - step_transmittance);
        cloud_transmittance *= step_transmittance;
      }
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
    vec4 day = textureLod(day_texture, tex, day_lod);
    vec3 lights = textureLod(night_texture, tex, day_lod).rgb;
    float mu = dot(n, u_sun);
    // The water: the global map's, or within the coast window the shorelines' (sharp to the
    // pixel from low orbit). With the sea's own colour, open water (not the day map's ice) is the
    // sea's body colour and mirrors the sky (docs/orbit_view.md, "Coasts and lakes").
    float water = textureLod(water_texture, tex, day_lod).r;
    vec2 coast;
    if (coast_uv(n, coast)) water = textureLod(coast_texture, coast, max(log2(footprint / u_coast_texel), 0.0f)).r;
    // The relief map's slopes and roughness, filtered as the day map, and the land's woods, fields
    // and relief below the maps' texels (land_mosaic.glsl).
    vec3 relief = textureLod(relief_texture, tex, max(log2(footprint / u_relief_texel), 0.0f)).rgb;
    MosaicSample ground_detail = mosaic_sample(n, u_radius, footprint, relief.b, u_relief_texel);
    vec3 direct = vec3(0.0f);
    if (mu > -0.02f) {
      // Cloud shadow: the shell's optical depth towards the sun; some light diffuses through.
      // The steps repeat the branches' conditions: on llvmpipe only a loop's count skips work.
      int shadow_steps = hits_ground && mu > -0.02f ? u_shadow_steps : 0;
      float shadow = cloud_shadow(optical_depth_to_sun(g, shadow_steps, footprint));
      // The sun's incidence on the relief's slopes (flat: max(mu, 0)); on land with the relief
      // below the map's texels.
      vec2 slopes = relief.rg + (1.0f - water) * ground_detail.relief;
      direct = solar_irradiance() * transmittance_from_table(transmittance_table, g + 1.0f * n, u_sun, u_radius) *
               relief_sun_cosine(n, slopes, u_sun) * shadow;
    }
    vec3 sky = PI_F * sky_ambient(n, u_sun);
    float night = 1.0f - smoothstep(-0.1f, 0.05f, mu);
    float sea = u_sea_colour != 0 ? water * day.a : water;
    vec3 land = day.rgb * land_mosaic(n, day, u_radius, footprint, u_day_texel, ground_detail);
    vec3 albedo = u_sea_colour != 0 ? mix(land, SEA_BODY_ALBEDO, sea) : mix(land, day.rgb, water);
    vec3 sky_albedo = albedo + (u_sea_colour != 0 ? sea * SEA_SKY_REFLECTANCE : 0.0f);
    background = (albedo * direct + sky_albedo * sky) / PI_F + u_night_lights * night * lights;
    // Sun glint: the sea's facets mirror the direct sunlight (already through air and cloud) into
    // the view, radiance = BRDF x irradiance on the horizontal.
    if (sea > 0.0f && mu > 0.0f)
      background += sea * sun_glint_brdf(n, -d, u_sun, sea_wind_speed(g, u_sea_wind)) * direct;
  }

  vec3 radiance;
  if (in_air && ray_end > air_start) {
    vec3 start = oc + air_start * d;
    vec3 inscatter_total, inscatter_split, transmittance_total, transmittance_split;
    float split = weight_sum > 0.0f ? cloud_distance - air_start : 0.0f;
    // No steps outside the air, as the ground's shadow: the branch alone skips nothing on llvmpipe.
    int sky_steps = in_air && ray_end > air_start ? u_sky_steps : 0;
    sky_scattering(sky_table, transmittance_table, start, d, ray_end - air_start, split, u_sun, u_radius, sky_steps,
                   inscatter_total, inscatter_split, transmittance_total, transmittance_split);
    radiance = inscatter_split + transmittance_split * cloud_light +
               cloud_transmittance * (inscatter_total - inscatter_split + transmittance_total * background);
  } else {
    radiance = cloud_light + cloud_transmittance * background;
  }
  imageStore(radiance_image, pixel, vec4(radiance, 1.0f - cloud_transmittance));
}
