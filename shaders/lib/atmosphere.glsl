// Clear-sky atmosphere: Rayleigh and Mie single scattering on a spherical Earth.
// Coefficients from Bruneton's 2017 reference implementation ("Precomputed Atmospheric
// Scattering: a New Implementation", his demo's Earth) and Hillaire, "A Scalable and Production
// Ready Sky and Atmosphere Rendering Technique" (EGSR 2020), with its multiple scattering.
#ifndef NEPHELE_ATMOSPHERE_GLSL
#define NEPHELE_ATMOSPHERE_GLSL
#include "prelude.glsl"
#include "portable_math.glsl"
#include "ray_sphere.glsl"

const float ATMOSPHERE_THICKNESS = 100000.0f;
const float RAYLEIGH_SCALE_HEIGHT = 8000.0f;
const float MIE_SCALE_HEIGHT = 1200.0f;
const float MIE_SCATTERING = 3.996e-6f;
const float MIE_EXTINCTION = 4.440e-6f;
const float MIE_ASYMMETRY = 0.8f;

// Rayleigh scattering at 680, 550, 440 nm (1/m) and the solar irradiance there (W m^-2 nm^-1).
vec3 rayleigh_scattering() { return vec3(5.802e-6f, 13.558e-6f, 33.1e-6f); }
// Ozone's absorption (1/m) where it is densest: 300 Dobson units (8.06e22 molecules/m^2) over
// the tent of ozone_density (15 km), times the cross sections at 680, 550, 440 nm (1.209e-25,
// 3.5e-25, 1.582e-26 m^2; Bruneton 2017). The Chappuis band takes green and red: the zenith
// stays blue at twilight and the limb's blue is deeper.
vec3 ozone_absorption() { return vec3(0.650e-6f, 1.881e-6f, 0.085e-6f); }
// Ozone's density relative to its peak: a tent from 10 km up to 25 km and down to 40 km.
float ozone_density(float h) { return max(0.0f, 1.0f - abs(h - 25000.0f) / 15000.0f); }
vec3 solar_irradiance() { return vec3(1.474f, 1.8504f, 1.91198f); }

// The orbit view's ambient light of the sky (isotropic radiance) at a point with local up n and
// the sun towards `sun`: a blue share of the sunlight that fades across the terminator.
vec3 sky_ambient(vec3 n, vec3 sun) {
  return solar_irradiance() * vec3(0.030f, 0.045f, 0.075f) * smoothstep(-0.12f, 0.35f, dot(n, sun));
}

float rayleigh_phase(float nu) { return 3.0f / (16.0f * PI_F) * (1.0f + nu * nu); }

// Henyey-Greenstein phase function, normalised over the sphere.
float henyey_greenstein(float nu, float g) {
  float denominator = 1.0f + g * g - 2.0f * g * nu;
  return (1.0f - g * g) / (4.0f * PI_F * denominator * sqrt(max(denominator, 1.0e-8f)));
}

// Cornette and Shanks' phase function for the air's aerosols (1992, "Physically reasonable
// analytic expression for the single-scattering phase function", Appl. Opt. 31; Bruneton 2017's
// Mie phase): Henyey-Greenstein's forward lobe with Rayleigh's 1 + nu^2, normalised over the sphere.
float cornette_shanks(float nu, float g) {
  float denominator = 1.0f + g * g - 2.0f * g * nu;
  return 3.0f / (8.0f * PI_F) * (1.0f - g * g) / (2.0f + g * g) * (1.0f + nu * nu) /
         (denominator * sqrt(max(denominator, 1.0e-8f)));
}

// Extinction (1/m) at altitude h.
vec3 air_extinction(float h) {
  return rayleigh_scattering() * exp(-max(h, 0.0f) / RAYLEIGH_SCALE_HEIGHT) +
         vec3(MIE_EXTINCTION * exp(-max(h, 0.0f) / MIE_SCALE_HEIGHT)) + ozone_absorption() * ozone_density(h);
}

// Scattering (1/m) at altitude h, Rayleigh and Mie together.
vec3 air_scattering(float h) {
  return rayleigh_scattering() * exp(-max(h, 0.0f) / RAYLEIGH_SCALE_HEIGHT) +
         vec3(MIE_SCATTERING * exp(-max(h, 0.0f) / MIE_SCALE_HEIGHT));
}

// The air's optical depth (per colour) from point p (relative to the Earth's centre, radius R) to
// the top of the atmosphere along unit direction d, through the planet if the ray meets it.
// Midpoint rule in `steps` steps of t with s = L t^2: short steps low down, where the air is dense
// (the Mie scale height is only 1.2 km of the 100 km path).
vec3 optical_depth_to_top(vec3 p, vec3 d, float earth_radius, int steps) {
  vec2 top = ray_sphere(p, d, vec3(0.0f), earth_radius + ATMOSPHERE_THICKNESS);
  float length_to_top = max(top.y, 0.0f);
  vec3 depth = vec3(0.0f);
  for (int i = 0; i < steps; ++i) {
    float t0 = float(i) / float(steps);
    float t1 = float(i + 1) / float(steps);
    float t = 0.5f * (t0 + t1);
    vec3 q = p + (length_to_top * t * t) * d;
    depth += air_extinction(length(q) - earth_radius) * (length_to_top * (t1 * t1 - t0 * t0));
  }
  return depth;
}

// Transmittance from p to the top of the atmosphere along d; zero when the ray meets the ground
// (a ray from the surface or above meets it when it points down and the line crosses the
// sphere). 16 steps of optical_depth_to_top.
vec3 transmittance_to_space(vec3 p, vec3 d, float earth_radius) {
  vec2 ground = ray_sphere(p, d, vec3(0.0f), earth_radius);
  if (ground.x < ground.y && ground.y > 0.0f && dot(p, d) < 0.0f) return vec3(0.0f);
  return exp(-optical_depth_to_top(p, d, earth_radius, 16));
}

// The same from a table (Bruneton 2017, "Precomputed Atmospheric Scattering: a New
// Implementation", his transmittance texture): the transmittance to the top from radius r along
// a direction at cosine mu from the zenith, for every r in the air and every mu above the
// horizon, made once (transmittance_table_entry) and read with one bilinear lookup
// (transmittance_from_table) where transmittance_to_space integrates 16 steps of three
// exponentials each: the orbit view's sky takes it at each of its samples. The table's axes are
// Bruneton's: across, the distance d to the top between its least (straight up, top - r) and its
// largest (towards the horizon, rho + H), so that the horizon is always the last column; up,
// rho / H with rho = sqrt(r^2 - R^2) and H its value at the top, which gives the dense low air
// most of the rows (altitude rho^2 / 2R: the first eighth of the rows holds the lowest 1.6 km).
const int TRANSMITTANCE_TABLE_WIDTH = 256;
const int TRANSMITTANCE_TABLE_HEIGHT = 64;
// The steps of each entry's optical depth: the midpoint rule's error falls as 1/n^2, to 1/256 of
// the 16 steps' (up to 0.65 % of the depth; docs/orbit_view.md, "The transmittance table").
const int TRANSMITTANCE_TABLE_STEPS = 256;

// A texture coordinate whose texel centres span x in [0, 1] over n texels.
float table_coordinate(float x, int n) { return 0.5f / float(n) + x * (1.0f - 1.0f / float(n)); }

// The table's coordinates of (r, mu); r within [R, R + ATMOSPHERE_THICKNESS]. Lengths as
// differences of nearby radii, (top - r)(top + r) rather than top^2 - r^2, so that float keeps
// metres at the ground.
vec2 transmittance_table_uv(float r, float mu, float earth_radius) {
  float top = earth_radius + ATMOSPHERE_THICKNESS;
  float H = sqrt(ATMOSPHERE_THICKNESS * (top + earth_radius));
  float rho = sqrt(max((r - earth_radius) * (r + earth_radius), 0.0f));
  float d = max(-r * mu + sqrt(max((top - r) * (top + r) + r * r * mu * mu, 0.0f)), 0.0f);
  float d_min = top - r, d_max = rho + H;
  return vec2(table_coordinate((d - d_min) / (d_max - d_min), TRANSMITTANCE_TABLE_WIDTH),
              table_coordinate(rho / H, TRANSMITTANCE_TABLE_HEIGHT));
}

// The table's texel (i, j): the (r, mu) of its centre, inverting transmittance_table_uv, and the
// transmittance along that ray in TRANSMITTANCE_TABLE_STEPS steps (the last column grazes the
// ground: its ray crosses the whole air near the surface and is dark, as the horizon's sun).
vec3 transmittance_table_entry(int i, int j, float earth_radius) {
  float top = earth_radius + ATMOSPHERE_THICKNESS;
  float H = sqrt(ATMOSPHERE_THICKNESS * (top + earth_radius));
  float rho = H * float(j) / float(TRANSMITTANCE_TABLE_HEIGHT - 1);
  float r = sqrt(rho * rho + earth_radius * earth_radius);
  float d_min = top - r, d_max = rho + H;
  float d = d_min + (d_max - d_min) * float(i) / float(TRANSMITTANCE_TABLE_WIDTH - 1);
  float mu = d <= 0.0f ? 1.0f : clamp((H * H - rho * rho - d * d) / (2.0f * r * d), -1.0f, 1.0f);
  vec3 p = vec3(0.0f, 0.0f, r);
  vec3 direction = vec3(sqrt(max(1.0f - mu * mu, 0.0f)), 0.0f, mu);
  return exp(-optical_depth_to_top(p, direction, earth_radius, TRANSMITTANCE_TABLE_STEPS));
}

// The transmittance from p (inside the air; its radius is clamped to it) along unit d to the top
// of the atmosphere, from the table; zero where the ray meets the ground, as
// transmittance_to_space: the ray points down and r^2 mu^2 >= r^2 - R^2, the latter as
// (r - R)(r + R) so that float decides it to a metre at the surface.
vec3 transmittance_from_table(IN(TransmittanceTable) table, vec3 p, vec3 d, float earth_radius) {
  float r = length(p);
  float r_mu = dot(p, d);
  if (r_mu < 0.0f && r_mu * r_mu >= (r - earth_radius) * (r + earth_radius)) return vec3(0.0f);
  float inside = clamp(r, earth_radius, earth_radius + ATMOSPHERE_THICKNESS);
  return vec3(textureLod(table, transmittance_table_uv(inside, r_mu / r, earth_radius), 0.0f));
}

// Multiple scattering (Hillaire 2020, section 5.5): the light that the air scatters more than
// once, as an isotropic radiance Psi at altitude h with the sun at cosine mu_sun from the zenith;
// a view ray's sample adds its scattering times Psi. The second order L2 is the single scattering
// (isotropic phase) and the sunlit ground (Lambertian, ground_albedo) seen along the directions
// of a sphere, the sunlight at each step through the air of the transmittance table; the orders
// above follow as the geometric series of the share f of isotropic light that the air around the
// point scatters back to it: Psi = L2 / (1 - f). Tabulated once (multiple_scattering_table_entry)
// and read at each sample (multiple_scattering).
// The sphere's integral is split at the horizon's dip, cos = -sqrt(1 - R^2 / r^2): the rays just
// above it cross the most air and carry most of the light, those just below end on the ground
// nearby, so the integrand is steepest there. Each side takes `rings` / 2 rings of cosines spaced
// quadratically towards the dip, times `azimuths` azimuths, and each ray `steps` steps spaced
// quadratically from x, where the air is densest along it. At the table's counts
// (MULTIPLE_SCATTERING_RINGS, _AZIMUTHS, _STEPS) within 1.3 % of the converged integral (2.5 % at
// 60 km towards a setting sun) where Hillaire's 64 directions of uniform cosines, 20 steps each,
// erred from -32 % to +206 %, for the same cost once the sunlight comes from the table
// (docs/orbit_view.md).
const int MULTIPLE_SCATTERING_TABLE_SIZE = 32;  // texels per side: mu_sun across, altitude up
const int MULTIPLE_SCATTERING_RINGS = 16;
const int MULTIPLE_SCATTERING_AZIMUTHS = 8;
const int MULTIPLE_SCATTERING_STEPS = 40;
vec3 multiple_scattering_transfer(IN(TransmittanceTable) transmittance, float h, float mu_sun, float earth_radius,
                                  float ground_albedo, int rings, int azimuths, int steps) {
  float r = earth_radius + h;
  vec3 x = vec3(0.0f, 0.0f, r);
  vec3 sun = vec3(sqrt(max(0.0f, 1.0f - mu_sun * mu_sun)), 0.0f, mu_sun);
  float dip = -sqrt(max(h * (r + earth_radius), 0.0f)) / r;
  int half_rings = rings / 2;
  vec3 second = vec3(0.0f);
  vec3 transfer = vec3(0.0f);
  for (int i = 0; i < half_rings * 2 * azimuths; ++i) {
    // Ring k of a side at the cosine dip +- span t^2 (t the ring's middle share), its share of
    // the sphere span (t1^2 - t0^2) / 2 over the azimuths.
    int ring = i / azimuths;
    bool above = ring < half_rings;
    float k = float(above ? ring : ring - half_rings);
    float t0 = k / float(half_rings), t1 = (k + 1.0f) / float(half_rings);
    float t = 0.5f * (t0 + t1);
    float span = above ? 1.0f - dip : 1.0f + dip;
    float cos_theta = above ? dip + span * t * t : dip - span * t * t;
    float weight = 0.5f * span * (t1 * t1 - t0 * t0) / float(azimuths);
    float phi = 2.0f * PI_F * (float(i % azimuths) + 0.5f) / float(azimuths);
    float sin_theta = sqrt(max(0.0f, 1.0f - cos_theta * cos_theta));
    vec3 w = vec3(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
    vec2 ground = ray_sphere(x, w, vec3(0.0f), earth_radius);
    vec2 top = ray_sphere(x, w, vec3(0.0f), earth_radius + ATMOSPHERE_THICKNESS);
    // A downward ray meets the ground (at once from the table's lowest row, x on the ground, where
    // the nearer root rounds to either side of 0): as transmittance_to_space's test.
    bool meets_ground = ground.x < ground.y && ground.y > 0.0f && dot(x, w) < 0.0f;
    float length_along = meets_ground ? max(ground.x, 0.0f) : max(top.y, 0.0f);
    vec3 light = vec3(0.0f);
    vec3 transmitted = vec3(1.0f);  // along the direction, from x to the step
    for (int j = 0; j < steps; ++j) {
      float a0 = float(j) / float(steps), a1 = float(j + 1) / float(steps);
      float a = 0.5f * (a0 + a1);
      float ds = length_along * (a1 * a1 - a0 * a0);
      vec3 q = x + (length_along * a * a) * w;
      float hq = length(q) - earth_radius;
      vec3 extinction = max(air_extinction(hq), vec3(1.0e-12f));
      vec3 scattering = air_scattering(hq);
      vec3 step_transmittance = exp(-extinction * ds);
      vec3 step_share = (vec3(1.0f) - step_transmittance) / extinction;
      light += transmitted * scattering * transmittance_from_table(transmittance, q, sun, earth_radius) * step_share /
               (4.0f * PI_F);
      transfer += transmitted * scattering * step_share * weight;
      transmitted *= step_transmittance;
    }
    if (meets_ground) {
      vec3 g = x + length_along * w;
      vec3 n = normalize(g);
      light += transmitted * transmittance_from_table(transmittance, g + n, sun, earth_radius) * max(dot(n, sun), 0.0f) *
               ground_albedo / PI_F;
    }
    second += light * weight;
  }
  return solar_irradiance() * second / (vec3(1.0f) - transfer);
}

// The table's texel (i, j): mu_sun from -1 to 1 across; up, the altitude from 0 to the air's top
// as the square of the row's share, (j / n)^2 ATMOSPHERE_THICKNESS, so that the rows crowd where
// the air is dense and Psi changes fastest (rows at 0, 0.10, 0.42, 0.94 km ... against 3.2 km
// apart: read between linear rows, Psi in the lowest 2 km came out up to 5 % low, now within 3 %
// everywhere; docs/orbit_view.md).
vec3 multiple_scattering_table_entry(IN(TransmittanceTable) transmittance, int i, int j, float earth_radius,
                                     float ground_albedo) {
  float n = float(MULTIPLE_SCATTERING_TABLE_SIZE - 1);
  float row = float(j) / n;
  return multiple_scattering_transfer(transmittance, ATMOSPHERE_THICKNESS * row * row, 2.0f * float(i) / n - 1.0f,
                                      earth_radius, ground_albedo, MULTIPLE_SCATTERING_RINGS,
                                      MULTIPLE_SCATTERING_AZIMUTHS, MULTIPLE_SCATTERING_STEPS);
}

// Psi at point q (from the Earth's centre) with the sun towards `sun`, from the table: texel
// centres at the table's nodes (the rows' altitudes the squares of their shares), bilinear
// between them.
vec3 multiple_scattering(IN(ScatteringTable) table, vec3 q, vec3 sun, float earth_radius) {
  float r = length(q);
  const int n = MULTIPLE_SCATTERING_TABLE_SIZE;
  vec2 uv = vec2(table_coordinate(0.5f * (dot(q, sun) / r + 1.0f), n),
                 table_coordinate(sqrt(clamp((r - earth_radius) / ATMOSPHERE_THICKNESS, 0.0f, 1.0f)), n));
  return vec3(textureLod(table, uv, 0.0f));
}

// The clear-sky integral along a view ray, step by step, so that a caller may shadow the sun
// at each sample (cloud_march.glsl: crepuscular rays). Midpoint rule in `steps` steps of ds.
struct SkyIntegral {
  vec3 rayleigh;  // the phase-weighted scattering coefficients at sea level
  float mie;
  vec3 skylight;  // mean radiance of the light around the air besides the sun (0: single scattering)
  float ds;
  float split;
  vec3 radiance;
  vec3 transmittance;
  vec3 inscatter_split;
  vec3 transmittance_split;
  bool split_done;
};

SkyIntegral sky_integral_begin(vec3 d, float distance, float split, vec3 sun, int steps) {
  SkyIntegral s;
  float nu = dot(d, sun);
  s.rayleigh = rayleigh_scattering() * rayleigh_phase(nu);
  s.mie = MIE_SCATTERING * cornette_shanks(nu, MIE_ASYMMETRY);
  s.skylight = vec3(0.0f);
  s.ds = distance / float(steps);
  s.split = split;
  s.radiance = vec3(0.0f);
  s.transmittance = vec3(1.0f);
  s.inscatter_split = vec3(0.0f);
  s.transmittance_split = vec3(1.0f);
  s.split_done = split <= 0.0f;
  return s;
}

// The sample of step i: its point, from o (relative to the Earth's centre) along d.
vec3 sky_integral_point(IN(SkyIntegral) s, vec3 o, vec3 d, int i) {
  float s0 = float(i) * s.ds;
  return o + (s0 + 0.5f * s.ds) * d;
}

// Step i with its sample q, where the sunlight arrives through the air with sun_transmittance
// (transmittance_to_space or transmittance_from_table) times sun_visibility (1: clear).
void sky_integral_step_in_sunlight(INOUT(SkyIntegral) s, vec3 q, int i, vec3 sun_transmittance, float earth_radius,
                                   float sun_visibility) {
  float s0 = float(i) * s.ds;
  float ds = s.ds;
  float h = length(q) - earth_radius;
  vec3 extinction = max(air_extinction(h), vec3(1.0e-12f));
  vec3 source = (s.rayleigh * exp(-h / RAYLEIGH_SCALE_HEIGHT) + vec3(s.mie * exp(-h / MIE_SCALE_HEIGHT))) *
                sun_transmittance * solar_irradiance() * sun_visibility;
  // Second-order scattering, isotropic approximation: the air scatters the mean radiance around
  // it into the view whatever the phase function (its integral is 1). It keeps a cloud's shadow
  // in the air from turning black, where the sun's single scattering is gone.
  source += air_scattering(h) * s.skylight;
  if (!s.split_done && s0 + ds > s.split) {
    // The split falls in this step: its first part, with the step's source, goes into the
    // split values.
    vec3 part_transmittance = exp(-extinction * (s.split - s0));
    s.inscatter_split = s.radiance + s.transmittance * source * (vec3(1.0f) - part_transmittance) / extinction;
    s.transmittance_split = s.transmittance * part_transmittance;
    s.split_done = true;
  }
  // Energy-conserving integration over the step (Hillaire 2016, "Physically Based Sky,
  // Atmosphere and Cloud Rendering in Frostbite"): source (1 - e^{-sigma ds}) / sigma.
  vec3 step_transmittance = exp(-extinction * ds);
  s.radiance += s.transmittance * source * (vec3(1.0f) - step_transmittance) / extinction;
  s.transmittance *= step_transmittance;
}

// Step i with its sample q; the sun's direct light reaches q through the air (16 steps of
// transmittance_to_space) times sun_visibility (1: clear).
void sky_integral_step(INOUT(SkyIntegral) s, vec3 q, int i, vec3 sun, float earth_radius, float sun_visibility) {
  sky_integral_step_in_sunlight(s, q, i, transmittance_to_space(q, sun, earth_radius), earth_radius, sun_visibility);
}

void sky_integral_end(IN(SkyIntegral) s, OUT(vec3) inscatter_total, OUT(vec3) inscatter_split,
                      OUT(vec3) transmittance_total, OUT(vec3) transmittance_split) {
  inscatter_split = s.split_done ? s.inscatter_split : s.radiance;
  transmittance_split = s.split_done ? s.transmittance_split : s.transmittance;
  inscatter_total = s.radiance;
  transmittance_total = s.transmittance;
}

// Single-scattered sky radiance along a view ray from o (relative to the Earth's centre) in
// direction d over [0, distance], and the transmittance over it. `split` is a distance at which
// the partial in-scattering is also returned (for compositing clouds). Returns the in-scattered
// radiance in inscatter_total, the part before `split` in inscatter_split.
void sky_single_scattering(vec3 o, vec3 d, float distance, float split, vec3 sun, float earth_radius,
                           int steps, OUT(vec3) inscatter_total, OUT(vec3) inscatter_split,
                           OUT(vec3) transmittance_total, OUT(vec3) transmittance_split) {
  SkyIntegral s = sky_integral_begin(d, distance, split, sun, steps);
  for (int i = 0; i < steps; ++i) sky_integral_step(s, sky_integral_point(s, o, d, i), i, sun, earth_radius, 1.0f);
  sky_integral_end(s, inscatter_total, inscatter_split, transmittance_total, transmittance_split);
}

// The sky along a view ray as sky_single_scattering, with the multiple scattering of `table`
// (multiple_scattering) added at each sample and the sunlight's way through the air read from
// `transmittance` (transmittance_from_table): the orbit view's sky.
void sky_scattering(IN(ScatteringTable) table, IN(TransmittanceTable) transmittance, vec3 o, vec3 d, float distance,
                    float split, vec3 sun, float earth_radius, int steps, OUT(vec3) inscatter_total,
                    OUT(vec3) inscatter_split, OUT(vec3) transmittance_total, OUT(vec3) transmittance_split) {
  SkyIntegral s = sky_integral_begin(d, distance, split, sun, steps);
  for (int i = 0; i < steps; ++i) {
    vec3 q = sky_integral_point(s, o, d, i);
    s.skylight = multiple_scattering(table, q, sun, earth_radius);
    sky_integral_step_in_sunlight(s, q, i, transmittance_from_table(transmittance, q, sun, earth_radius),
                                  earth_radius, 1.0f);
  }
  sky_integral_end(s, inscatter_total, inscatter_split, transmittance_total, transmittance_split);
}

#endif
