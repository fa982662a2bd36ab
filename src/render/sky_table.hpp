#pragma once
// The air's tables of the orbit view, each made by the shader's own function: on the GPU for the
// renderer, on the CPU for the tests that check it. The multiple-scattering table
// (atmosphere.glsl's ScatteringTable: Hillaire 2020's Psi by sun angle and altitude,
// shaders/render/sky_table.comp) and the transmittance table (TransmittanceTable: Bruneton
// 2017's transmittance to the top by altitude and direction, shaders/render/transmittance_table.comp).
#include <epoxy/gl.h>

#include <vector>

#include "shader_math/shader_math.hpp"

namespace nephele::render {

// The mean albedo of what lies under the air seen from orbit, clouds included: the Earth's
// Bond albedo, about 0.30 (Stephens et al. 2015, "The albedo of Earth", Rev. Geophys. 53).
constexpr float kPlanetAlbedo = 0.30f;

// MULTIPLE_SCATTERING_TABLE_SIZE^2 texels, rows of altitude from the ground up, mu_sun from -1 at
// the left to 1 at the right (multiple_scattering_table_entry), RGB with A = 1; the sunlight
// through the transmittance table of the same radius.
std::vector<glsl::vec4> multiple_scattering_table(float earth_radius, float ground_albedo);

// The same table as a GL_RGBA32F 2D texture, bilinear and clamped to its edges (the caller
// deletes it), from the transmittance texture of the same radius (transmittance_texture). Needs a
// current GL context.
GLuint multiple_scattering_texture(GLuint transmittance, float earth_radius, float ground_albedo);

// TRANSMITTANCE_TABLE_WIDTH x TRANSMITTANCE_TABLE_HEIGHT texels, rows of altitude from the ground
// up (transmittance_table_entry), RGB with A = 1.
std::vector<glsl::vec4> transmittance_table(float earth_radius);

// The same table as a GL_RGBA32F 2D texture, bilinear and clamped to its edges (the caller
// deletes it). Needs a current GL context.
GLuint transmittance_texture(float earth_radius);

}  // namespace nephele::render
