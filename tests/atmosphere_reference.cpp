#include "atmosphere_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace nephele::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kTableAltitudes = 64;
constexpr int kTableCosines = 512;

// Gauss-Legendre nodes and weights on [-1, 1] (16 points), by Newton's iteration on P_16.
struct GaussLegendre {
  std::array<double, 16> x{}, w{};
  GaussLegendre() {
    const int n = 16;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
      double derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = n * (z * p1 - p0) / (z * z - 1.0);
        const double step = p1 / derivative;
        z -= step;
        if (std::abs(step) < 1e-15) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * derivative * derivative);
    }
  }
};

// Distances along p + t d to where the line meets the sphere of radius r (t0 <= t1); false if it
// misses.
bool sphere_hits(glm::dvec3 p, glm::dvec3 d, double r, double& t0, double& t1) {
  const double b = glm::dot(p, d);
  const double c = glm::dot(p, p) - r * r;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  t0 = -b - root;
  t1 = -b + root;
  return true;
}

// Two unit vectors perpendicular to unit a and to each other.
void basis(glm::dvec3 a, glm::dvec3& u, glm::dvec3& v) {
  const glm::dvec3 helper = std::abs(a.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  u = glm::normalize(glm::cross(helper, a));
  v = glm::cross(a, u);
}

// Midpoint steps along p + t d over [0, length]: calls step(i, q, h, to_here, ds) with the
// sample q, its altitude h and the transmittance from p to it (the step's own first half
// included).
template <class Step>
void march(const ReferenceAtmosphere& air, const std::function<glm::dvec3(double)>& extinction, glm::dvec3 p,
           glm::dvec3 d, double length, int steps, Step step) {
  const double ds = length / steps;
  glm::dvec3 depth(0.0);
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 q = p + (ds * (i + 0.5)) * d;
    const double h = glm::length(q) - air.bottom_radius;
    const glm::dvec3 sigma = extinction(h);
    step(i, q, h, glm::exp(-(depth + 0.5 * ds * sigma)), ds);
    depth += sigma * ds;
  }
}

}  // namespace

double rayleigh_phase_reference(double nu) { return 3.0 / (16.0 * kPi) * (1.0 + nu * nu); }

double cornette_shanks_phase(double nu, double g) {
  const double k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
  return k * (1.0 + nu * nu) / std::pow(1.0 + g * g - 2.0 * g * nu, 1.5);
}

AtmosphereReferenceModel::AtmosphereReferenceModel(ReferenceAtmosphere atmosphere) : air_(atmosphere) {
  table_.resize(static_cast<size_t>(kTableAltitudes) * kTableCosines);
  const double depth = air_.top_radius - air_.bottom_radius;
  for (int i = 0; i < kTableAltitudes; ++i) {
    const double s = static_cast<double>(i) / (kTableAltitudes - 1);
    const glm::dvec3 p(0.0, 0.0, air_.bottom_radius + depth * s * s);
    for (int j = 0; j < kTableCosines; ++j) {
      const double mu = -1.0 + 2.0 * j / (kTableCosines - 1);
      const glm::dvec3 d(std::sqrt(std::max(0.0, 1.0 - mu * mu)), 0.0, mu);
      table_[static_cast<size_t>(i) * kTableCosines + j] = transmittance_to_space(p, d);
    }
  }
}

std::function<glm::dvec3(double)> AtmosphereReferenceModel::extinction_function() const {
  return [this](double h) { return extinction(h); };
}

glm::dvec3 AtmosphereReferenceModel::extinction(double altitude) const {
  const double h = std::max(altitude, 0.0);
  const double ozone = std::max(0.0, 1.0 - std::abs(h - 25000.0) / 15000.0);
  return air_.rayleigh_scattering * std::exp(-h / air_.rayleigh_scale_height) +
         glm::dvec3(air_.mie_extinction * std::exp(-h / air_.mie_scale_height)) + air_.ozone_absorption * ozone;
}

double AtmosphereReferenceModel::ray_length(glm::dvec3 p, glm::dvec3 d) const {
  double t0 = 0.0, t1 = 0.0;
  if (sphere_hits(p, d, air_.bottom_radius, t0, t1) && t0 > 0.0) return t0;
  if (!sphere_hits(p, d, air_.top_radius, t0, t1)) return 0.0;
  return std::max(t1, 0.0);
}

glm::dvec3 AtmosphereReferenceModel::transmittance_to_space(glm::dvec3 p, glm::dvec3 d) const {
  double t0 = 0.0, t1 = 0.0;
  if (sphere_hits(p, d, air_.bottom_radius, t0, t1) && t1 > 0.0 && glm::dot(p, d) < 0.0) return glm::dvec3(0.0);
  const double length = ray_length(p, d);
  const int steps = 2000;
  glm::dvec3 depth(0.0);
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 q = p + (length * (i + 0.5) / steps) * d;
    depth += extinction(glm::length(q) - air_.bottom_radius) * (length / steps);
  }
  return glm::exp(-depth);
}

glm::dvec3 AtmosphereReferenceModel::table_transmittance(double radius, double mu) const {
  const double depth = air_.top_radius - air_.bottom_radius;
  const double s = std::sqrt(std::clamp((radius - air_.bottom_radius) / depth, 0.0, 1.0)) * (kTableAltitudes - 1);
  const double c = (std::clamp(mu, -1.0, 1.0) + 1.0) * 0.5 * (kTableCosines - 1);
  const int i = std::min(static_cast<int>(s), kTableAltitudes - 2);
  const int j = std::min(static_cast<int>(c), kTableCosines - 2);
  const double fs = s - i, fc = c - j;
  auto at = [&](int a, int b) { return table_[static_cast<size_t>(a) * kTableCosines + b]; };
  return glm::mix(glm::mix(at(i, j), at(i, j + 1), fc), glm::mix(at(i + 1, j), at(i + 1, j + 1), fc), fs);
}

glm::dvec3 AtmosphereReferenceModel::single_from_table(glm::dvec3 p, glm::dvec3 d, glm::dvec3 sun, int steps) const {
  const double length = ray_length(p, d);
  const double nu = glm::dot(d, sun);
  const glm::dvec3 rayleigh = air_.rayleigh_scattering * rayleigh_phase_reference(nu);
  const double mie = air_.mie_scattering * cornette_shanks_phase(nu, air_.mie_g);
  glm::dvec3 radiance(0.0);
  march(air_, extinction_function(), p, d, length, steps,
        [&](int, glm::dvec3 q, double h, glm::dvec3 to_here, double ds) {
          const glm::dvec3 source = rayleigh * std::exp(-h / air_.rayleigh_scale_height) +
                                    glm::dvec3(mie * std::exp(-h / air_.mie_scale_height));
          const double r = glm::length(q);
          radiance += to_here * source * table_transmittance(r, glm::dot(q, sun) / r) * ds;
        });
  return radiance * air_.solar_irradiance;
}

SkyRadiance AtmosphereReferenceModel::radiance(glm::dvec3 p, glm::dvec3 d, glm::dvec3 sun, int orders) const {
  SkyRadiance out;
  // From outside the air the ray starts where it enters it.
  if (glm::length(p) > air_.top_radius) {
    double t0 = 0.0, t1 = 0.0;
    if (!sphere_hits(p, d, air_.top_radius, t0, t1) || t1 <= 0.0) return out;
    p += std::max(t0, 0.0) * d;
    p *= (air_.top_radius - 1e-3) / glm::length(p);
  }
  const double length = ray_length(p, d);
  const double nu = glm::dot(d, sun);
  const glm::dvec3 rayleigh = air_.rayleigh_scattering * rayleigh_phase_reference(nu);
  const double mie = air_.mie_scattering * cornette_shanks_phase(nu, air_.mie_g);

  // Single scattering: 4000 steps with the sun's exact transmittance at every 8th.
  glm::dvec3 to_sun(0.0);
  march(air_, extinction_function(), p, d, length, 4000,
        [&](int i, glm::dvec3, double h, glm::dvec3 to_here, double ds) {
          if (i % 8 == 0) to_sun = transmittance_to_space(p + (ds * (i + 4.0)) * d, sun);
          out.single += to_here *
                        (rayleigh * std::exp(-h / air_.rayleigh_scale_height) +
                         glm::dvec3(mie * std::exp(-h / air_.mie_scale_height))) *
                        to_sun * ds;
        });
  out.single *= air_.solar_irradiance;
  if (orders < 2) return out;

  // Double scattering: at each of 64 points of the view ray the single-scattered light from a
  // sphere of directions (16 Gauss-Legendre cosines about the view direction, where the Mie
  // phase's forward peak lies, times 32 azimuths) scattered into the view.
  static const GaussLegendre gauss;
  glm::dvec3 u, v;
  basis(d, u, v);
  const int azimuths = 32;
  march(air_, extinction_function(), p, d, length, 64, [&](int, glm::dvec3 q, double h, glm::dvec3 to_here, double ds) {
    glm::dvec3 rayleigh_in(0.0), mie_in(0.0);
    for (int a = 0; a < 16; ++a) {
      const double c = gauss.x[a];
      const double sine = std::sqrt(std::max(0.0, 1.0 - c * c));
      for (int b = 0; b < azimuths; ++b) {
        const double phi = 2.0 * kPi * (b + 0.5) / azimuths;
        const glm::dvec3 w = c * d + sine * (std::cos(phi) * u + std::sin(phi) * v);
        const glm::dvec3 light = single_from_table(q, w, sun, 48);
        const double weight = gauss.w[a] * 2.0 * kPi / azimuths;
        rayleigh_in += light * rayleigh_phase_reference(c) * weight;
        mie_in += light * cornette_shanks_phase(c, air_.mie_g) * weight;
      }
    }
    out.second += to_here *
                  (air_.rayleigh_scattering * std::exp(-h / air_.rayleigh_scale_height) * rayleigh_in +
                   air_.mie_scattering * std::exp(-h / air_.mie_scale_height) * mie_in) *
                  ds;
  });
  for (int k = 0; k < 3; ++k) {
    const double ratio = out.single[k] > 0.0 ? std::min(out.second[k] / out.single[k], 0.9) : 0.0;
    out.higher[k] = out.second[k] * ratio / (1.0 - ratio);
  }
  return out;
}

}  // namespace nephele::test
