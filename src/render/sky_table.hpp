#pragma once
// The air's multiple-scattering table of the orbit view (atmosphere.glsl's ScatteringTable:
// Hillaire 2020's Psi by sun angle and altitude), made by the shader's own function: on the GPU
// (shaders/render/sky_table.comp) for the renderer, on the CPU for the tests that check it.
#include <epoxy/gl.h>

#include <vector>

#include "shader_math/shader_math.hpp"

namespace nephele::render {

// The mean albedo of what lies under the air seen from orbit, clouds included: the Earth's
// Bond albedo, about 0.30 (Stephens et al. 2015, "The albedo of Earth", Rev. Geophys. 53).
constexpr float kPlanetAlbedo = 0.30f;

// MULTIPLE_SCATTERING_TABLE_SIZE^2 texels, rows of altitude from the ground up, mu_sun from -1 at
// the left to 1 at the right (multiple_scattering_table_entry), RGB with A = 1.
std::vector<glsl::vec4> multiple_scattering_table(float earth_radius, float ground_albedo);

// The same table as a GL_RGBA32F 2D texture, bilinear and clamped to its edges (the caller
// deletes it). Needs a current GL context.
GLuint multiple_scattering_texture(float earth_radius, float ground_albedo);

}  // namespace nephele::render
