#pragma once
// The orbit view's textures, made once per renderer (render/orbit_renderer.cpp): the planet's
// equirect maps and the cover's cube, each with its mip chain made on the CPU
// (core/mip_levels.hpp). Half-float texels are rounded here, to nearest even, rather than by the
// driver: Mesa's llvmpipe truncates floats it converts to half, a GPU driver may round, and a
// texture made here holds the same bits on every driver (docs/orbit_view.md, "Cost").
#include "core/image.hpp"
#include "render/orbit_renderer.hpp"

namespace nephele::render {

// The day or night map (linear RGB; a grey map's value as RGB; alpha 1) as RGBA16F, repeating in
// longitude and clamped in latitude, filtered trilinearly: returns the texture's name.
unsigned colour_map_texture(const core::ImageData& image);
// The water fraction (first channel, clamped to 0..1) as R8, filtered as the colour maps.
unsigned water_fraction_texture(const core::ImageData& image);
// The ground's slopes (east, north; ground_relief.glsl) as RG16F, filtered as the colour maps:
// slopes need three digits (ETOPO5's steepest 9 km cells rise by about 0.3 a metre). With a
// third channel (the slopes' roughness) RGB16F.
unsigned slope_texture(const core::ImageData& image);
// The cover cube as RGBA16F (cover, tau, cloud top km, 0), each face's levels made apart (as
// OpenGL makes them), clamped at the faces' edges (seamless filtering is the renderer's state).
unsigned cover_texture(const CoverCube& cover);

}  // namespace nephele::render
