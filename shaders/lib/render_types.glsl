// Parameter blocks of the renderer (uniform structs in GLSL, aggregates in C++).
#ifndef NEPHELE_RENDER_TYPES_GLSL
#define NEPHELE_RENDER_TYPES_GLSL

const int MAX_LAYERS = 8;  // layers one render marches at most
const int MAX_CONVECTIVE = 4;  // convective clouds (density volumes) one render marches at most

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
  float min_distance;    // the layer starts this far from the camera (no rule uses it today)
  vec2 wind;             // unit wind direction (towards), east-north
  vec2 noise_offset;     // how far the wind moved the noise (tau), along and across the wind, m
  int shadow_map;        // layer of the shadow maps with the depth through the layers above; -1: none
};

// The ground's height field (shaders/lib/terrain.glsl, docs/terrain.md).
struct TerrainParams {
  int enabled;           // 0: the bare sphere
  float extent;          // half-size of the height field's square, metres
  float top;             // highest altitude in it (above the sphere), metres
  float texel;           // its texel spacing, metres
  float reach;           // horizontal radius (m) within which the ceiling bounds the ground; 0: unused
  int land;              // 1: the land cover texture (land_cover.glsl) holds lakes, rivers and towns
  float land_near;       // half-sizes of its near and far levels' squares, metres
  float land_far;
  float land_texels;     // texels per side of each level
  float snow_line;       // the season's snow line, metres above sea level (land_cover.glsl)
  float crop_stage;      // the season's crops: 0 bare soil, 1 green, 2 ripe (land_cover.glsl)
};

// One convective cloud's density volume (docs/convection.md) as the marcher sees it: a cube of
// edge `extent` standing on the ground point `centre` (east, north of the camera), its bottom
// at altitude `bottom`; the volume's x runs along `axis`, its y to the left of it, its z up
// (altitude, so the cube follows the Earth's curvature like the layers' shells).
struct ConvectiveParams {
  vec2 centre;           // metres east and north of the camera
  vec2 axis;             // unit direction of the volume's x (where the anvil spreads), east-north
  float bottom;          // altitude of the cube's bottom
  float extent;          // the cube's edge, metres
  float cloud_base;      // altitudes of the cloud's base and top (the ambient light's height)
  float cloud_top;
  float extinction;      // 1/m at density 1
};

// Everything the ray marcher (cloud_march.glsl) reads besides its two textures: the uniform
// u_march of shaders/render/clouds.comp, filled by render::march_params on the host. Local
// frame: east, north, up with the camera at the origin.
struct MarchParams {
  LayerParams layers[MAX_LAYERS];
  int layer_count;
  float earth_radius;      // the sphere osculating the WGS84 ellipsoid at the viewpoint
  float camera_altitude;
  vec3 forward;            // the perspective view's axes
  vec3 right;
  vec3 up;
  float tan_half_fov;
  int panorama;            // 1: 360 x 180 equirectangular view sphere instead
  float heading;           // panorama's centre, radians clockwise from north
  vec3 sun;                // unit direction towards the sun
  vec3 ambient;            // sky irradiance on a horizontal surface at the clouds (2 km)
  vec3 ground_ambient;     // the same at the ground (the camera's altitude, at most 2 km)
  vec3 ground_radiance;    // radiance of the sunlit and skylit ground below the clouds
  int view_steps;
  int light_steps;
  int sky_steps;
  float weather_extent;    // half-size of the weather field square, metres
  float max_distance;
  float pixel_angle;       // angle subtended by one pixel (radians), for noise level of detail
  float noise_texels;      // texels per side of the noise volume
  int frame;               // which frame of a temporal accumulation (shifts the jitter)
  float shadow_extent;     // half-size of the shadow maps' square (cloud_march.glsl), metres
  int sky_shadow_map;      // the sky's shadow map (crepuscular rays): its layer (0) of its own texture, -1: none
  float sky_shadow_base;   // its shell's altitude: the lowest layer base, metres
  float powder;            // strength of the powder term (cloud_density.glsl), 0: none
  TerrainParams terrain;   // the ground (its heights are the third texture)
  ConvectiveParams convective[MAX_CONVECTIVE];  // volume c is layer c of the fourth texture
  int convective_count;
  float detail_erosion;     // erosion of the heaped clouds' edges by the detail noise (cloud_march.glsl), 0: none
};

#endif
