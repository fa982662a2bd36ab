// The one compiled copy of the GLSL function library (shaders/lib), with external linkage.
// Every library file is included here; each includes the files it needs, so the order does not
// matter. shader_math.hpp declares what this defines (generated from the same files).
#include "shader_math/hooks.hpp"

namespace nephele::glsl {
#include "lib/atmosphere.glsl"
#include "lib/cloud_density.glsl"
#include "lib/cloud_properties.glsl"
#include "lib/cloud_march.glsl"
#include "lib/cover_density.glsl"
#include "lib/cube_bspline.glsl"
#include "lib/cube_faces.glsl"
#include "lib/cube_sampling.glsl"
#include "lib/curl_flow.glsl"
#include "lib/curl_spline.glsl"
#include "lib/equirect_mapping.glsl"
#include "lib/hash.glsl"
#include "lib/implicit_field.glsl"
#include "lib/ground_relief.glsl"
#include "lib/land_cover.glsl"
#include "lib/land_mosaic.glsl"
#include "lib/latitude_bands.glsl"
#include "lib/model_march.glsl"
#include "lib/moving_flow.glsl"
#include "lib/noise_rows.glsl"
#include "lib/noise_types.glsl"
#include "lib/parameters.glsl"
#include "lib/perlin.glsl"
#include "lib/portable_math.glsl"
#include "lib/ray_sphere.glsl"
#include "lib/slab_scattering.glsl"
#include "lib/sun_glint.glsl"
#include "lib/render_types.glsl"
#include "lib/terrain.glsl"
#include "lib/tileable_noise.glsl"
#include "lib/warp_step.glsl"
#include "lib/weather_systems.glsl"
#include "lib/webanck_forms.glsl"
#include "lib/worley.glsl"
#include "lib/worley_fbm.glsl"

// The procedural curl as the warp's velocity source (the GPU's warp.comp defines its own, with
// the noise offset); the cube map's and the spline's are library functions.
vec3 warp_velocity(vec3 w, IN(CurlParams) curl) { return curl_velocity(w, curl); }
vec4 SplineSource::fetch(int layer, int i, int j) const {
  const int row = cells + 2 * SPLINE_MARGIN;
  return texels[(static_cast<size_t>(layer) * row + j) * row + i];
}
ivec3 imageSize(IN(SplineSource) spline) {
  const int row = spline.cells + 2 * SPLINE_MARGIN;
  return ivec3(row, row, spline.layers);
}
}  // namespace nephele::glsl
