// Probe of lib/cloud_properties.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1] = (frontal, deep convection, cumulus, cirrus) weights,
// x[2] = (latitude, cyclonic depth, surface bias, anvil weight). The functions (x[0].x):
const int PROBE_NORMAL_QUANTILE = 0;    // normal_quantile(a), normal_cdf(a) in y
const int PROBE_TAU_FROM_RANK = 1;      // optical_thickness_from_rank(a, b, c), cloudy_rank(a, b) in y
const int PROBE_TAU_FROM_COVER = 2;     // optical_thickness_from_cover(a, b, c)
const int PROBE_CLOUD_TOP = 3;          // cloud_top_km(x[1], x[2]), tropopause_km(latitude) in y, cloud_thickness_km(a, b) in z
const int PROBE_CLOUD_TOP_FROM_COVER = 4;  // cloud_top_from_cover(a, latitude)
const int PROBE_COVERED_DEPTH = 5;         // covered_optical_depth(a, b)
const int PROBE_SUBTEXEL_CLOUD = 6;        // subtexel_cloud(x[1].xyz, a, b, c): (cover, relief, field, undulation)
const int PROBE_SUBTEXEL_TAU = 7;          // subtexel_optical_thickness(a, a detail of undulation b and share x[1].x, c)
const int PROBE_SUBTEXEL_SHARE = 8;        // subtexel_cloud(x[1].xyz, a, b, c).undulation_share
const int PROBE_SHALLOW_TRADES = 9;  // organised_cloud(x[1], a), trades_belt(latitude) in y, shallow_trades_weight(x[1], latitude, a, b) in z,
                                     // trade_moat(a, b, c) in w
const int PROBE_CUMULUS_ORGANISATION = 10;  // cumulus_organisation(a)
const int PROBE_SUBTEXEL_CARVING = 11;      // subtexel_carving(a, b)
#ifndef __cplusplus
#include "../lib/cloud_properties.glsl"
#endif
// The cloud types' weights of x[1].
CloudTypes probe_cloud_types(mat4 x) {
  CloudTypes types;
  types.frontal = x[1].x;
  types.deep_convection = x[1].y;
  types.cumulus = x[1].z;
  types.cirrus = x[1].w;
  types.anvil = x[2].w;
  return types;
}
vec4 probe_cloud_properties(mat4 x) {
  int f = int(x[0].x);
  float a = x[0].y, b = x[0].z, c = x[0].w;
  float latitude = x[2].x;
  if (f == PROBE_NORMAL_QUANTILE) return vec4(normal_quantile(a), normal_cdf(a), 0.0f, 0.0f);
  if (f == PROBE_TAU_FROM_RANK) return vec4(optical_thickness_from_rank(a, b, c), cloudy_rank(a, b), 0.0f, 0.0f);
  if (f == PROBE_TAU_FROM_COVER) return vec4(optical_thickness_from_cover(a, b, c), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_CLOUD_TOP) {
    CloudTypes types = probe_cloud_types(x);
    return vec4(cloud_top_km(types, latitude, x[2].y, x[2].z), tropopause_km(latitude), cloud_thickness_km(a, b), 0.0f);
  }
  if (f == PROBE_SHALLOW_TRADES) {
    CloudTypes types = probe_cloud_types(x);
    return vec4(organised_cloud(types, a), trades_belt(latitude), shallow_trades_weight(types, latitude, a, b),
                trade_moat(a, b, c));
  }
  if (f == PROBE_CUMULUS_ORGANISATION) return vec4(cumulus_organisation(a), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SUBTEXEL_CARVING) return vec4(subtexel_carving(a, b), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_COVERED_DEPTH) return vec4(covered_optical_depth(a, b), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SUBTEXEL_CLOUD) {
    SubtexelCloud cloud = subtexel_cloud(vec3(x[1]), a, b, c);
    return vec4(cloud.cover, cloud.relief, cloud.field, cloud.undulation);
  }
  if (f == PROBE_SUBTEXEL_SHARE) return vec4(subtexel_cloud(vec3(x[1]), a, b, c).undulation_share, 0.0f, 0.0f, 0.0f);
  if (f == PROBE_SUBTEXEL_TAU) {
    SubtexelCloud detail;
    detail.cover = 1.0f;
    detail.field = 0.0f;
    detail.relief = 0.0f;
    detail.undulation = b;
    detail.undulation_share = x[1].x;
    return vec4(subtexel_optical_thickness(a, detail, c), 0.0f, 0.0f, 0.0f);
  }
  return vec4(cloud_top_from_cover(a, latitude), 0.0f, 0.0f, 0.0f);  // PROBE_CLOUD_TOP_FROM_COVER
}
