// A brute-force clear-sky reference in double precision: the model of Bruneton's "Precomputed
// Atmospheric Scattering: a New Implementation" (2017; his demo's Earth: Rayleigh with an 8 km
// scale height, Mie 1.2 km with the Cornette-Shanks phase of g = 0.8 and single-scattering
// albedo 0.9, 300 Dobson units of ozone in a tent between 10, 25 and 40 km), evaluated by
// quadrature instead of precomputed tables, at the three wavelengths of nephele's RGB
// (680, 550, 440 nm). Radii are nephele's (6371 km, the air 100 km deep) and the ground is black,
// so that what is compared is the air's own light. Single scattering is integrated with fine
// steps; double scattering by a sphere of directions at each point of the view ray; the orders
// above two by the geometric series of their ratio (docs/orbit_view.md, "The sky against
// Bruneton's model"). Test support only: tests/test_sky_colours.cpp.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace nephele::test {

struct ReferenceAtmosphere {
  double bottom_radius = 6371000.0;
  double top_radius = 6471000.0;
  glm::dvec3 rayleigh_scattering{5.802e-6, 13.558e-6, 33.1e-6};
  double rayleigh_scale_height = 8000.0;
  double mie_scattering = 3.996e-6;
  double mie_extinction = 4.440e-6;
  double mie_scale_height = 1200.0;
  double mie_g = 0.8;
  // Peak absorption of ozone (1/m): 300 DU = 8.06e22 molecules/m^2 spread over the tent's
  // 15 km, times the cross sections at 680, 550, 440 nm (1.209e-25, 3.5e-25, 1.582e-26 m^2).
  glm::dvec3 ozone_absorption{0.650e-6, 1.881e-6, 0.085e-6};
  glm::dvec3 solar_irradiance{1.474, 1.8504, 1.91198};
};

struct SkyRadiance {
  glm::dvec3 single{0.0};  // order 1
  glm::dvec3 second{0.0};  // order 2
  glm::dvec3 higher{0.0};  // orders 3 and up, the geometric series of second / single
  glm::dvec3 total() const { return single + second + higher; }
};

class AtmosphereReferenceModel {
 public:
  explicit AtmosphereReferenceModel(ReferenceAtmosphere atmosphere = {});

  glm::dvec3 extinction(double altitude) const;
  // Transmittance from p (metres from the Earth's centre) along unit d to the top of the air;
  // zero where the ray meets the ground. 2000 steps, exact to well below 1e-4.
  glm::dvec3 transmittance_to_space(glm::dvec3 p, glm::dvec3 d) const;
  // The sky's radiance (W m^-2 sr^-1 nm^-1) reaching p from direction -d along the ray p + t d
  // up to the ground or the top, the sun towards unit `sun`; with double scattering when
  // `orders` is 2 or more.
  SkyRadiance radiance(glm::dvec3 p, glm::dvec3 d, glm::dvec3 sun, int orders) const;

 private:
  // Transmittance to space tabulated by altitude and the cosine of the direction's zenith angle
  // for the inner integrals of double scattering (bilinear; below 1e-3 off the exact values).
  glm::dvec3 table_transmittance(double radius, double mu) const;
  // Single scattering along p + t d by `steps` steps, the sun's transmittance from the table.
  glm::dvec3 single_from_table(glm::dvec3 p, glm::dvec3 d, glm::dvec3 sun, int steps) const;
  double ray_length(glm::dvec3 p, glm::dvec3 d) const;
  std::function<glm::dvec3(double)> extinction_function() const;

  ReferenceAtmosphere air_;
  std::vector<glm::dvec3> table_;
};

double rayleigh_phase_reference(double nu);
double cornette_shanks_phase(double nu, double g);

}  // namespace nephele::test
