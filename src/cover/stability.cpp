#include "cover/stability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "cover/solid_angle.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {
namespace {

using glm::dvec3;

size_t index(int size, int face, int i, int j) { return (static_cast<size_t>(face) * size + j) * size + i; }

dvec3 texel_vector(const std::vector<float>& rgba, size_t k) {
  return dvec3(rgba[4 * k], rgba[4 * k + 1], rgba[4 * k + 2]);
}

dvec3 direction(int size, int face, int i, int j) { return dvec3(glsl::texel_direction(face, i, j, size)); }

// Neighbours along i and j inside the face: central differences, one-sided at the edges.
struct Stencil {
  int i0, i1, j0, j1;
  bool valid() const { return i0 != i1 && j0 != j1; }
};
Stencil stencil(int size, int i, int j) {
  return {std::max(i - 1, 0), std::min(i + 1, size - 1), std::max(j - 1, 0), std::min(j + 1, size - 1)};
}

}  // namespace

FlowRates flow_rates(const std::vector<float>& curl, int size) {
  FlowRates rates;
  rates.size = size;
  rates.spectral_radius.assign(static_cast<size_t>(6) * size * size, 0.0f);
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const Stencil s = stencil(size, i, j);
        if (!s.valid()) continue;
        const dvec3 n = direction(size, face, i, j);
        const dvec3 e1 = direction(size, face, s.i1, j) - direction(size, face, s.i0, j);
        const dvec3 e2 = direction(size, face, i, s.j1) - direction(size, face, i, s.j0);
        const dvec3 d1 =
            texel_vector(curl, index(size, face, s.i1, j)) - texel_vector(curl, index(size, face, s.i0, j));
        const dvec3 d2 =
            texel_vector(curl, index(size, face, i, s.j1)) - texel_vector(curl, index(size, face, i, s.j0));
        // Everything in an orthonormal basis of the tangent plane at n: G E = D, G = D E^-1.
        const dvec3 t1 = glm::normalize(e1 - glm::dot(e1, n) * n);
        const dvec3 t2 = glm::cross(n, t1);
        const double e11 = glm::dot(e1, t1), e12 = glm::dot(e2, t1), e21 = glm::dot(e1, t2), e22 = glm::dot(e2, t2);
        const double d11 = glm::dot(d1, t1), d12 = glm::dot(d2, t1), d21 = glm::dot(d1, t2), d22 = glm::dot(d2, t2);
        const double det_e = e11 * e22 - e12 * e21;
        const double g11 = (d11 * e22 - d12 * e21) / det_e, g12 = (d12 * e11 - d11 * e12) / det_e;
        const double g21 = (d21 * e22 - d22 * e21) / det_e, g22 = (d22 * e11 - d21 * e12) / det_e;
        const double trace = g11 + g22, det = g11 * g22 - g12 * g21;
        const double discriminant = 0.25 * trace * trace - det;
        const double rho = discriminant >= 0 ? 0.5 * std::abs(trace) + std::sqrt(discriminant) : std::sqrt(det);
        rates.spectral_radius[index(size, face, i, j)] = static_cast<float>(rho);
        rates.max_rate = std::max(rates.max_rate, rho);
      }
  return rates;
}

StiffnessReport stiffness_report(const FlowRates& rates, double step, Integrator integrator) {
  StiffnessReport r;
  r.step = step;
  r.max_rate = rates.max_rate;
  r.stiffness = step * rates.max_rate;
  r.limit = stability_limit(integrator);
  if (rates.size == 0) return r;
  const std::vector<double> omega = cover::face_texel_solid_angles(rates.size);
  const size_t per_face = omega.size();
  double beyond = 0.0;
  for (size_t k = 0; k < rates.spectral_radius.size(); ++k)
    if (step * rates.spectral_radius[k] > r.limit) beyond += omega[k % per_face];
  r.beyond_fraction = beyond / (4.0 * M_PI);
  return r;
}

FoldingReport folding_report(const std::vector<float>& warp, int size) {
  FoldingReport r;
  const std::vector<double> omega = cover::face_texel_solid_angles(size);
  double folded = 0.0, squares = 0.0, weights = 0.0;
  r.jacobian_min = std::numeric_limits<double>::infinity();
  r.jacobian_max = -std::numeric_limits<double>::infinity();
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const Stencil s = stencil(size, i, j);
        if (!s.valid()) continue;
        const dvec3 n = direction(size, face, i, j);
        const double area = glm::dot(glm::cross(direction(size, face, s.i1, j) - direction(size, face, s.i0, j),
                                                direction(size, face, i, s.j1) - direction(size, face, i, s.j0)),
                                     n);
        const dvec3 w = glm::normalize(texel_vector(warp, index(size, face, i, j)));
        const double warped_area = glm::dot(
            glm::cross(texel_vector(warp, index(size, face, s.i1, j)) - texel_vector(warp, index(size, face, s.i0, j)),
                       texel_vector(warp, index(size, face, i, s.j1)) - texel_vector(warp, index(size, face, i, s.j0))),
            w);
        const double jacobian = warped_area / area;
        const double weight = omega[static_cast<size_t>(j) * size + i];
        if (!(jacobian > 0.0)) folded += weight;
        r.jacobian_min = std::min(r.jacobian_min, jacobian);
        r.jacobian_max = std::max(r.jacobian_max, jacobian);
        squares += weight * (jacobian - 1.0) * (jacobian - 1.0);
        weights += weight;
      }
  if (weights == 0.0) r.jacobian_min = r.jacobian_max = 1.0;  // size 1: no neighbours, nothing measured
  r.folded_fraction = folded / (4.0 * M_PI);
  r.area_error_rms = weights > 0 ? std::sqrt(squares / weights) : 0.0;
  return r;
}

SubstepReport substep_report(const std::vector<float>& warp) {
  SubstepReport r;
  const size_t texels = warp.size() / 4;
  double sum = 0.0;
  for (size_t k = 0; k < texels; ++k) {
    const double attempts = warp[4 * k + 3];
    sum += std::abs(attempts);
    r.max_attempts = std::max(r.max_attempts, std::abs(attempts));
    if (attempts < 0) ++r.capped_texels;
  }
  r.mean_attempts = texels ? sum / texels : 0.0;
  return r;
}

WarpDiagnostics diagnose_warp(const std::vector<float>& curl, const std::vector<float>& warp, int size,
                              Integrator integrator, double step) {
  WarpDiagnostics d;
  d.adaptive = integrator == Integrator::adaptive;
  d.stiffness = stiffness_report(flow_rates(curl, size), step, integrator);
  d.folding = folding_report(warp, size);
  d.substeps = substep_report(warp);
  const size_t texels = warp.size() / 4;
  long off = 0;
  for (size_t k = 0; k < texels; ++k) {
    const double length = std::sqrt(static_cast<double>(warp[4 * k]) * warp[4 * k] +
                                    static_cast<double>(warp[4 * k + 1]) * warp[4 * k + 1] +
                                    static_cast<double>(warp[4 * k + 2]) * warp[4 * k + 2]);
    if (!(std::abs(length - 1.0) <= 1e-5)) ++off;
  }
  add_warp_warnings(d, integrator, step, off);
  return d;
}

void add_warp_warnings(WarpDiagnostics& d, Integrator integrator, double step, long off, bool moving) {
  char text[512];
  if (!d.adaptive && d.stiffness.beyond_fraction > warn_fraction) {
    std::snprintf(text, sizeof text,
                  "--step %g: the stiffness number h rho reaches %.3g, beyond the stable limit %.3g of %s, on %.3g%% "
                  "of the sphere (the flow's rate of change rho is up to %.4g there); the warp is unreliable in "
                  "those vortex cores: %s",
                  step, d.stiffness.stiffness, d.stiffness.limit, integrator_name(integrator),
                  100.0 * d.stiffness.beyond_fraction, d.stiffness.max_rate,
                  moving ? "use more --iterations with a smaller --step (the same flow time), or a weaker flow "
                           "(--curl-strength)"
                         : "use --integrator adaptive, or more --iterations with a smaller --step");
    d.warnings.push_back(text);
  }
  if (d.adaptive && d.substeps.capped_texels > 0) {
    std::snprintf(text, sizeof text,
                  "%ld texels ran out of --max-substeps before the flow time (their warp stops short); raise "
                  "--max-substeps or --tolerance",
                  d.substeps.capped_texels);
    d.warnings.push_back(text);
  }
  if (d.folding.folded_fraction > 0.0) {
    // The exact flow keeps area (J = 1); J <= 0 between neighbouring texels means the warp
    // stretches the cover faster than the texels resolve, or the integration failed.
    std::snprintf(text, sizeof text,
                  "the warp folds the sphere over itself on %.3g%% of it (area Jacobian down to %.4g, 1 keeps "
                  "area): lower --curl-strength, --curl-gain or the flow time (--iterations x --step), or raise "
                  "--size",
                  100.0 * d.folding.folded_fraction, d.folding.jacobian_min);
    d.warnings.push_back(text);
  }
  if (off > 0) {
    std::snprintf(text, sizeof text, "%ld warped points are not finite unit vectors", off);
    d.warnings.push_back(text);
  }
}

}  // namespace nephele::cover
