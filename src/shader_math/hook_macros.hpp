// The hook macros of hooks.hpp, apart so that a file that includes shader_math.hpp (which
// #undefs them) can define them again for library text of its own (the tests' probes).
// No include guard on purpose.
#define CUBE_SOURCE_PARAM , IN(CubeSource) source
#define CUBE_SOURCE_ARG , source
#define CUBE_FETCH(face, i, j) source.fetch(face, i, j)
#define CUBE_SIZE source.size
#define SPLINE_SOURCE_PARAM , IN(SplineSource) spline
#define SPLINE_SOURCE_ARG , spline
#define SPLINE_FETCH(face, i, j) spline.fetch(face, i, j)
#define SPLINE_CELLS spline.cells
#define MARCH_SOURCES_PARAM , IN(MarchSources) sources
#define MARCH_SOURCES_ARG , sources
#define NOISE_LOD(x, lod) sources.noise.sample_lod(x, lod)
#define WEATHER_COVERAGE(uv, channel) sources.weather.sample(uv, channel)
#define MARCH_TERRAIN_ARG , sources.terrain
#define CONVECTIVE_DENSITY(q, cloud) sources.convective.sample(q, cloud)
#define LAYER_SHADOW(uv, map) sources.shadows.sample(uv, map)
#define SKY_SHADOW(uv) sources.sky_shadow.sample(uv, 0)
// The warp's stepping rules are templates over the velocity source (shaders/lib/warp_step.glsl).
#define WARP_TEMPLATE template <class Field>
#define WARP_FIELD_PARAM , IN(Field) field
#define WARP_FIELD_ARG , field
#define WARP_VELOCITY(w) warp_velocity(w, field)
