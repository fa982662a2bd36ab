// Parameter blocks of the renderer (uniform structs in GLSL, aggregates in C++).
#ifndef NEPHELE_RENDER_TYPES_GLSL
#define NEPHELE_RENDER_TYPES_GLSL

// One cloud layer as the ray marcher sees it. Lengths in metres, altitudes above the Earth
// sphere that osculates the WGS84 ellipsoid at the viewpoint.
struct LayerParams {
  int type;              // CLOUD_* in cloud_density.glsl
  int channel;           // coverage channel of the weather field
  float base;            // altitude of the layer's bottom
  float top;             // altitude of the layer's top
  float extinction;      // 1/m at density 1
  float morph;           // alto: 0 altostratus .. 1 altocumulus
  float darkness;        // reduces the single-scattering albedo
  float min_distance;    // the layer starts this far from the camera (cumulonimbus)
  vec2 wind;             // unit wind direction (towards), east-north
  vec2 noise_offset;     // how far the wind moved the noise (tau), along and across the wind, m
};

#endif
