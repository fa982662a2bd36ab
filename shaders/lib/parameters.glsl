// Parameter blocks of the shared functions (uniform structs in GLSL, aggregates in C++).
// Kept apart from the functions so that C++ can give them external linkage.
#ifndef NEPHELE_PARAMETERS_GLSL
#define NEPHELE_PARAMETERS_GLSL

struct FbmParams {
  float frequency;   // cells per unit length at octave 0
  int octaves;       // number of octaves; 0 gives a constant 0
  float lacunarity;  // frequency ratio between octaves
  float gain;        // amplitude ratio between octaves
  uint seed;         // each octave hashes with its own key derived from the seed
  ivec3 period;      // cells per period at octave 0 (0 = not periodic); scaled by lacunarity
};

struct CurlParams {
  FbmParams potential_north;  // w1, dominant in the northern hemisphere
  FbmParams potential_south;  // w2, dominant in the southern hemisphere, sign reversed
  float prevailing;           // P: strength of the zonal (prevailing wind) bands
  float mix_frequency;        // a in m(lat) = sin(a lat)
  float strength;             // s: the potential is s phi, so velocities scale with s
  float smoothing;            // lambda of smooth_worley (worley.glsl); 0: classic 1 - F1
  float storm_tracks;         // f: focus of the vortices on the storm tracks (0: none, 1: none at the equator)
  int zonal_cells;            // circulation cells per hemisphere of the zonal winds (0: they follow m)
  float storm_track_shift;    // s: the envelope is A(z - s), its tracks moved north with --month (0: annual mean)
};

// How the flow moves (moving_flow.glsl). Times are flow units counted from `origin` L, so that
// float keeps its precision at any date (the host subtracts the origin in double).
struct FlowMotion {
  float generation_time;  // L: the vortices of generation g live while |t - g L| < L
  int origin;             // the generation whose centre is the time 0 of the time arguments
  float drift;            // 1: the vortices drift with the zonal wind; 0: they stay in place
  int generations;        // > 0: the noise of generation g is that of g mod generations (a loop)
};

// The moving flow evaluated where a stepping rule asks (moving_flow.glsl's procedural source).
struct MovingCurl {
  CurlParams curl;
  vec3 offset;  // of the potentials' noise, as curl_flow_shifted's
  FlowMotion motion;
};

#endif
