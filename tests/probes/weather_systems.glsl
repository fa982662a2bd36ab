// Probe of lib/weather_systems.glsl (shared GLSL/C++ subset; tests/test_library_probes.cpp).
// x[0] = (function, a, b, c), x[1] = the point p (unit), x[2] = a cyclone's centre (xyz, made
// unit here) and radius (w), x[3] = (wrap, strength, ...). The functions (x[0].x):
const int PROBE_BAND_PROFILE = 0;     // band_profile(a, b)
const int PROBE_COMMA_CLOUD = 1;      // comma_cloud(vec2(a, b), c, x[3].x)
const int PROBE_CYCLONE = 2;          // cyclone_frame(p, C).xy, cyclone_cloud(p, C, a) in z
const int PROBE_CELL_CLOUDS = 3;      // cell_clouds(p, a, uint(b), 7, 0.2, 0.3, 0.3, c)
const int PROBE_BELTS = 4;            // itcz_systems(p, 0, lat, a, its waves, uint(b), c).x, trade_cumulus (texels x[1].w
                                      // across), cirrus_streaks, its .y
const int PROBE_WEATHER_DENSITY = 5;  // weather_density, cyclone_systems, belt_systems (seed b + 1): cyclone C, the ITCZ at a, seed b, edge c, texels x[1].w across
const int PROBE_BELT_FIELDS = 6;      // belt_fields(p, lat, systems (the ITCZ at a), uint(b), c, texels x[1].w across)
const int PROBE_CELLS = 7;            // closed_cells(p, uint(b)), open_cells (clumps 1), cell_border(p * 160, p, its key),
                                      // deck_strength(p, lat, uint(b), a, c)
const int PROBE_CELL_WEIGHTS = 8;     // cell_weights(a, b), deck_presence(a), cells_resolved(b * 100, c)
const int PROBE_COLD = 9;             // cold_sector(vec2(a, c)), cold_sectors(p, cyclone C), cell_modulation(p,
                                      // x[3].zw, uint(b), 1e-3), cold_air(p, C, 1).y
const int PROBE_CELL_PARTS = 10;      // closed_cell_modulation(p, a, uint(b), c), open_cell_modulation(p, a, uint(b), c)
const int PROBE_POCKETS = 11;         // open_cell_pockets(p, uint(b)), with_pockets(vec2(a, c), it) in y, z
const int PROBE_BELTS_SURFACE = 12;   // belts_over_surface(x[1], a): its y, z, w, and belt_cloud of it
const int PROBE_STREETS = 13;         // street_phasor(p, across, uint(b)), street_rows, street_modulation(p, x[3].xyz,
                                      // a, uint(b), c); across the unit tangent across the wind x[3].xyz
const int PROBE_COLD_FRONT = 14;      // behind_cold_front(vec2(a, c)), street_share(vec2(a, c))
const int PROBE_STREET_PEARLS = 15;   // street_pearls(p, uint(b)), street_clouds(p, across, uint(b)); across as PROBE_STREETS
const int PROBE_NEAR = 16;            // cyclones_near(p, cyclone C), neighbour_feature(floor(p * 160), int(c), the
                                      // closed cells' key of seed b) in yzw
const int PROBE_FRONTAL_REACH = 17;   // frontal_reach(p), cirrus_gate(a), cirrus_streak_noise(p, uint(b), 2),
                                      // cirrus_sheets(p, uint(b), 1)
const int PROBE_CLOUD_TYPES = 18;     // cloud_types(a, x[1]): (deep convection, cumulus, cirrus, anvil)
const int PROBE_CONVECTIVE = 19;      // equal_area_radius(a, b, c), convective_cloud(x[3].x, x[3].y, c),
                                      // convective_presence(p, convective_presence_of(x[3].z, x[3].w, a)), and
                                      // that presence's y in w
const int PROBE_CONVECTIVE_DISTANCES = 20;  // convective_distances(p, a, uint(b), ITCZ_LAYER, ITCZ_RADII, the ITCZ's
                                            // presence at c and its waves of seed b, the systems' anvils where
                                            // x[3].y is 1, the towers' where 2, none where 0); itcz_systems(p,
                                            // band x[3].w, lat, c, its waves, uint(b), x[3].x) in zw; no cells
                                            // searched where x[3].z > 1/2
const int PROBE_CONVECTIVE_WARP = 21;        // convective_warp(p, uint(b), 2)
const int PROBE_LINE_WAVES = 22;             // line_waves(p, probe_monsoon_waves(uint(b), a, x[2].x)),
                                             // waved_presence(p, convective_presence_of(a, c, 1), those waves, 0)
const int PROBE_LOCAL_EAST = 23;             // local_east(p)
const int PROBE_FRAYED_DECK = 24;            // frayed_deck(a, b), deck_presence of it, deck_organisation(a)
const int PROBE_CELLS_HIDDEN = 25;           // cells_hidden(cloud_types(a, x[1]))
const int PROBE_CELL_BORDERS = 26;           // cell_borders(p * OPEN_CELLS, p, the open cells' key of seed b),
                                             // open_cell_wall(a) in w
const int PROBE_TRADE_REGIMES = 27;          // trade_regimes(p, uint(b), 2)
const int PROBE_ITCZ_SWELL = 40;             // itcz_swell(p, uint(b)), itcz_beads(x[1].w)
const int PROBE_SURFACE_DISCS = 41;          // surface_disc_clouds(p, a, uint(b), FLOWERS_LAYER, FLOWER_RADII, c,
                                             // x[2] (the rims), x[3].x (the faintest), 27 cells, none where
                                             // x[3].z > 1/2) in xy; system_hashes(floor(p a), the
                                             // flowers' size key of seed b).xz in zw
const int PROBE_SPCZ = 42;                   // spcz_along(p), spcz_latitude(a, c), waved_presence(p, the ITCZ's systems'
                                             // presence at 5 N, probe_spcz_waves(uint(b), x[3].x, x[3].y), 0),
                                             // spcz_extent(a)
const int PROBE_SPCZ_BAND = 43;              // itcz_line_band(p, 0.087, probe_spcz_waves(uint(b), x[3].x, x[3].y),
                                             // x[3].z, uint(b)), spcz_near(p, those waves) as 0 or 1,
                                             // spcz_presence(p, spcz_along(p), PROBE_SPCZ's presence, those
                                             // waves, x[3].z), spcz_place(p, those waves)
const int PROBE_TRADE_CLUMPS = 28;           // gravel_clumps(p, uint(b), a, x[1].w), flower_clumps' y, fish_clumps (all
                                             // cells searched), organised_trades(trade_regimes(p, uint(b), 2), latitude, c)
const int PROBE_TANGENT_WARP = 29;           // tangent_warp(p, a, c, uint(b), FLOWERS_WARP_LAYER, 2),
                                             // trade_cumulus_belt(latitude) in w
const int PROBE_BELT_REGIMES = 31;           // belt_regimes(p, latitude, systems (trade cumulus x[3].z), uint(b))
const int PROBE_STORM_TRACK = 32;            // storm_track_cold_air(p, latitude, x[3].xyz, a, c)
const int PROBE_LINE_PARTS = 33;             // complex_product(x[3].xy, x[3].zw), line_meander(vec3(a, c, 0)),
                                             // line_shift(vec3(a, c, x[2].x), line_waves_of(uint(b), 0.1))
const int PROBE_LINE_BAND = 34;              // itcz_line_band(p, a, probe_monsoon_waves(uint(b), a, x[2].x), c),
                                             // supercluster_activity(vec3(0, c, 0)), system_growth(x[3].x,
                                             // no_line_waves()), system_growth(x[3].x, those waves)
const int PROBE_LINE_LATITUDE = 35;          // itcz_line_latitude(p, a, probe_monsoon_waves(uint(b), a, x[2].x)),
                                             // line_waves(p, without_superclusters(those waves)).y
const int PROBE_TRADE_CLUMP = 30;            // trade_clump(p, a, uint(b), FLOWERS_LAYER, (0.2, 0.45), c, x[3].y (the
                                             // rim), x[3].x, x[3].w (the texels' arc), all cells),
                                             // rimmed_cloud(x[3].z, x[3].x, 0.3, x[3].y), presence_everywhere(c)'s
                                             // y, resolved_rim(x[3].y, a, 0.325, x[3].w)
const int PROBE_ITCZ_CELL = 36;              // itcz_cell(table, floor(p * its cells per radius), a, line_waves_of(uint(b),
                                             // a), uint(b)), the towers' table where x[3].x > 1/2, the systems' else;
                                             // where x[3].y > 1/2 convective_cell of that cell with keys of layers 7
                                             // and 8, radii (0.2, 0.4), presence_everywhere(0.6) and no waves
const int PROBE_CELL_TABLES = 37;            // convective_table_index(n, floor(p * n)) and convective_table_side(n) for n
                                             // = itcz_lattice_cells(the table as PROBE_ITCZ_CELL's); itcz_table_cell(
                                             // int(c)) as x + 100 y + 10000 z + 1e6 (towers' table) and
                                             // convective_table_cell(n, int(c) % side^3) as x + 100 y + 10000 z
const int PROBE_ITCZ_DISTANCES = 38;         // itcz_distances(the table as PROBE_ITCZ_CELL's, p, a, line_waves_of(
                                             // uint(b), a), uint(b), 27), and tabled_convective_distances of its
                                             // lattice with NO_CELL_TABLE in zw
const int PROBE_NEARER_SYSTEM = 39;          // nearer_system(x[2], ivec3(x[3].xyz), fract(p), local_east(p), the
                                             // towers' anvil where x[3].w > 1/2 or none, from nearest (a, c))
#ifndef __cplusplus
#include "../lib/weather_systems.glsl"
#endif
// The line's waves of `seed` at `line` with test monsoons of `size`: wavenumber m's amplitude
// size (cos m, sin m) / m, the mean size / 2, the reach the sum of their sizes.
LineWaves probe_monsoon_waves(uint seed, float line, float size) {
  LineWaves waves = line_waves_of(seed, line);
  float reach = 0.5f * abs(size);
  for (int m = 1; m <= MONSOON_WAVES; ++m) {
    waves.monsoon[m - 1] = size * vec2(cos(float(m)), sin(float(m))) / float(m);
    reach += abs(size) / float(m);
  }
  waves.monsoon_mean = 0.5f * size;
  waves.monsoon_reach = reach;
  return waves;
}
// The line's waves of `seed` at 5 N with an SPCZ of `strength` shifted by `shift` radians.
LineWaves probe_spcz_waves(uint seed, float strength, float shift) {
  LineWaves waves = line_waves_of(seed, 0.087f);
  waves.spcz = strength;
  waves.spcz_shift = shift;
  return waves;
}
// A cyclone at x[2]'s direction with x east and y north (a northern one; the host mirrors the
// southern ones, tests/test_weather_systems.cpp).
Cyclone probe_cyclone(mat4 x) {
  Cyclone c;
  c.centre = normalize(vec3(x[2]));
  c.east = normalize(cross(vec3(0.0f, 0.0f, 1.0f), c.centre));
  c.pole = cross(c.centre, c.east);
  c.radius = x[2].w;
  c.wrap = x[3].x;
  c.strength = x[3].y;
  return c;
}
vec4 probe_weather_systems(mat4 x) {
  int f = int(x[0].x);
  vec3 p = vec3(x[1]);
  float latitude = portable_asin(clamp(p.z, -1.0f, 1.0f));
  uint seed = uint(x[0].z);
  if (f == PROBE_BAND_PROFILE) return vec4(band_profile(x[0].y, x[0].z), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_COMMA_CLOUD) return vec4(comma_cloud(vec2(x[0].y, x[0].z), x[0].w, x[3].x), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_CYCLONE) {
    Cyclone c = probe_cyclone(x);
    return vec4(cyclone_frame(p, c), cyclone_cloud(p, c, x[0].y), 0.0f);
  }
  if (f == PROBE_CELL_CLOUDS) return vec4(cell_clouds(p, x[0].y, seed, 7u, 0.2f, 0.3f, 0.3f, x[0].w, NEIGHBOUR_CELLS), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_CELLS)
    return vec4(closed_cells(p, seed, NEIGHBOUR_CELLS), open_cells(p, seed, 1.0f, NEIGHBOUR_CELLS),
                cell_border(p * CLOSED_CELLS, p, noise_key(seed, CLOSED_CELLS_LAYER), NEIGHBOUR_CELLS),
                deck_strength(p, latitude, seed, x[0].y, x[0].w));
  if (f == PROBE_CELL_PARTS)
    return vec4(closed_cell_modulation(p, x[0].y, seed, x[0].w), open_cell_modulation(p, x[0].y, seed, x[0].w), 0.0f,
                0.0f);
  if (f == PROBE_FRONTAL_REACH) return vec4(frontal_reach(p), cirrus_gate(x[0].y), cirrus_streak_noise(p, seed, CIRRUS_OCTAVES),
                cirrus_sheets(p, seed, 1));
  if (f == PROBE_CLOUD_TYPES) {
    CloudTypes types = cloud_types(x[0].y, x[1]);
    return vec4(types.deep_convection, types.cumulus, types.cirrus, types.anvil);
  }
  if (f == PROBE_CONVECTIVE)
    return vec4(equal_area_radius(x[0].y, x[0].z, x[0].w), convective_cloud(x[3].x, x[3].y, x[0].w),
                convective_presence(p, convective_presence_of(x[3].z, x[3].w, x[0].y)),
                convective_presence_of(x[3].z, x[3].w, x[0].y).y);
  if (f == PROBE_CONVECTIVE_DISTANCES)
    return vec4(convective_distances(p, x[0].y, seed, ITCZ_LAYER, ITCZ_RADII,
                                     convective_presence_of(x[0].w, 0.07f, ITCZ_FILLED),
                                     line_waves_of(seed, x[0].w),
                                     x[3].y > 1.5f ? TOWER_ANVIL : (x[3].y > 0.5f ? SYSTEM_ANVIL : NO_ANVIL),
                                     x[3].z > 0.5f ? 0 : NEIGHBOUR_CELLS),
                itcz_systems(p, x[3].w, latitude, x[0].w, line_waves_of(seed, x[0].w), seed, x[3].x));
  if (f == PROBE_CONVECTIVE_WARP) return vec4(convective_warp(p, seed, 2), 0.0f);
  int table = x[3].x > 0.5f ? ITCZ_TOWERS_TABLE : ITCZ_SYSTEMS_TABLE;
  float lattice = itcz_lattice_cells(table);
  if (f == PROBE_ITCZ_CELL) {
    ivec3 cell = ivec3(floor(p * lattice));
    if (x[3].y > 0.5f)
      return convective_cell(cell, noise_key(seed, 7u), noise_key(seed, 8u), vec2(0.2f, 0.4f), presence_everywhere(0.6f),
                             no_line_waves());
    return itcz_cell(table, cell, x[0].y, line_waves_of(seed, x[0].y), seed);
  }
  if (f == PROBE_CELL_TABLES) {
    int side = convective_table_side(lattice);
    ivec4 entry = itcz_table_cell(int(x[0].w));
    ivec3 cell = convective_table_cell(lattice, int(x[0].w) % (side * side * side));
    return vec4(float(convective_table_index(lattice, ivec3(floor(p * lattice)))), float(side),
                float(entry.x + 100 * entry.y + 10000 * entry.z + (entry.w == ITCZ_SYSTEMS_TABLE ? 0 : 1000000)),
                float(cell.x + 100 * cell.y + 10000 * cell.z));
  }
  if (f == PROBE_NEARER_SYSTEM) {
    vec2 nearest = vec2(x[0].y, x[0].w);
    nearer_system(x[2], ivec3(int(x[3].x), int(x[3].y), int(x[3].z)), fract(p), local_east(p),
                  x[3].w > 0.5f ? TOWER_ANVIL : NO_ANVIL, nearest);
    return vec4(nearest, 0.0f, 0.0f);
  }
  if (f == PROBE_ITCZ_DISTANCES) {
    LineWaves waves = line_waves_of(seed, x[0].y);
    return vec4(itcz_distances(table, p, x[0].y, waves, seed, NEIGHBOUR_CELLS),
                tabled_convective_distances(p, lattice, seed, itcz_layer(table), itcz_radii(table),
                                            itcz_presence(table, x[0].y), itcz_table_waves(table, waves),
                                            table == ITCZ_SYSTEMS_TABLE ? SYSTEM_ANVIL : TOWER_ANVIL, NEIGHBOUR_CELLS,
                                            NO_CELL_TABLE));
  }
  if (f == PROBE_LINE_PARTS)
    return vec4(complex_product(vec2(x[3].x, x[3].y), vec2(x[3].z, x[3].w)), line_meander(vec3(x[0].y, x[0].w, 0.0f)),
                line_shift(vec3(x[0].y, x[0].w, x[2].x), line_waves_of(seed, 0.1f)));
  if (f == PROBE_LINE_BAND) {
    LineWaves waves = probe_monsoon_waves(seed, x[0].y, x[2].x);
    return vec4(itcz_line_band(p, x[0].y, waves, x[0].w, seed), supercluster_activity(vec3(0.0f, x[0].w, 0.0f)),
                system_growth(x[3].x, no_line_waves()), system_growth(x[3].x, waves));
  }
  if (f == PROBE_LINE_WAVES) {
    LineWaves waves = probe_monsoon_waves(seed, x[0].y, x[2].x);
    return vec4(line_waves(p, waves), waved_presence(p, convective_presence_of(x[0].y, x[0].w, 1.0f), waves, 0.0f));
  }
  if (f == PROBE_LINE_LATITUDE) {
    LineWaves waves = probe_monsoon_waves(seed, x[0].y, x[2].x);
    return vec4(itcz_line_latitude(p, x[0].y, waves), line_waves(p, without_superclusters(waves)).y, 0.0f, 0.0f);
  }
  if (f == PROBE_LOCAL_EAST) return vec4(local_east(p), 0.0f);
  if (f == PROBE_CELLS_HIDDEN) return vec4(cells_hidden(cloud_types(x[0].y, x[1])), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_CELL_BORDERS)
    return vec4(cell_borders(p * OPEN_CELLS, p, noise_key(seed, OPEN_CELLS_LAYER), NEIGHBOUR_CELLS),
                open_cell_wall(x[0].y));
  if (f == PROBE_TRADE_REGIMES) return trade_regimes(p, seed, 2);
  if (f == PROBE_SPCZ)
    return vec4(spcz_along(p), spcz_latitude(x[0].y, x[0].w),
                waved_presence(p, convective_presence_of(0.087f, 0.07f, 1.0f), probe_spcz_waves(seed, x[3].x, x[3].y),
                               0.0f),
                spcz_extent(x[0].y));
  if (f == PROBE_SPCZ_BAND) {
    LineWaves waves = probe_spcz_waves(seed, x[3].x, x[3].y);
    return vec4(itcz_line_band(p, 0.087f, waves, x[3].z, seed), spcz_near(p, waves) ? 1.0f : 0.0f,
                spcz_presence(p, spcz_along(p), convective_presence_of(0.087f, 0.07f, 1.0f), waves, x[3].z),
                spcz_place(p, waves));
  }
  if (f == PROBE_ITCZ_SWELL) return vec4(itcz_swell(p, seed), itcz_beads(x[1].w), 0.0f, 0.0f);
  if (f == PROBE_SURFACE_DISCS) {
    vec3 h = system_hashes(ivec3(floor(p * x[0].y)), noise_key(seed, FLOWERS_LAYER + 1u));
    return vec4(surface_disc_clouds(p, x[0].y, seed, FLOWERS_LAYER, FLOWER_RADII, x[0].w, x[2], x[3].x,
                                    x[3].z > 0.5f ? 0 : NEIGHBOUR_CELLS),
                h.x, h.z);
  }
  if (f == PROBE_TANGENT_WARP)
    return vec4(tangent_warp(p, x[0].y, x[0].w, seed, FLOWERS_WARP_LAYER, 2), trade_cumulus_belt(latitude));
  if (f == PROBE_TRADE_CLUMP)
    return vec4(trade_clump(p, x[0].y, seed, FLOWERS_LAYER, vec2(0.2f, 0.45f), x[0].w, x[3].y, x[3].x, x[3].w,
                            NEIGHBOUR_CELLS),
                rimmed_cloud(x[3].z, x[3].x, 0.3f, x[3].y), presence_everywhere(x[0].w).y,
                resolved_rim(x[3].y, x[0].y, 0.325f, x[3].w));
  if (f == PROBE_TRADE_CLUMPS)
    return vec4(gravel_clumps(p, seed, x[0].y, x[1].w, NEIGHBOUR_CELLS), flower_clumps(p, seed, x[0].y, x[1].w, NEIGHBOUR_CELLS).y,
                fish_clumps(p, seed, x[0].y, x[1].w, NEIGHBOUR_CELLS),
                organised_trades(trade_regimes(p, seed, 2), latitude, x[0].w));
  if (f == PROBE_FRAYED_DECK) {
    float deck = frayed_deck(x[0].y, x[0].z);
    return vec4(deck, deck_presence(deck), deck_organisation(x[0].y), 0.0f);
  }
  if (f == PROBE_BELTS_SURFACE) {
    vec4 fields = belts_over_surface(x[1], x[0].y);
    return vec4(fields.y, fields.z, fields.w, belt_cloud(fields));
  }
  if (f == PROBE_COLD_FRONT)
    return vec4(behind_cold_front(vec2(x[0].y, x[0].w)), street_share(vec2(x[0].y, x[0].w)), 0.0f, 0.0f);
  if (f == PROBE_STREETS) {
    vec3 wind = vec3(x[3]);
    vec3 along = wind - dot(wind, p) * p;
    vec3 across = cross(p, along) / length(along);
    return vec4(street_phasor(p, across, seed), street_rows(p, across, seed),
                street_modulation(p, wind, x[0].y, seed, x[0].w));
  }
  if (f == PROBE_STREET_PEARLS) {
    vec3 wind = vec3(x[3]);
    vec3 along = wind - dot(wind, p) * p;
    vec3 across = cross(p, along) / length(along);
    return vec4(street_pearls(p, seed), street_clouds(p, across, seed), 0.0f, 0.0f);
  }
  if (f == PROBE_POCKETS) {
    float pocket = open_cell_pockets(p, seed, POCKET_OCTAVES);
    vec2 weights = with_pockets(vec2(x[0].y, x[0].w), pocket);
    return vec4(pocket, weights.x, weights.y, 0.0f);
  }
  if (f == PROBE_STORM_TRACK)
    return vec4(storm_track_cold_air(p, latitude, vec3(x[3]), x[0].y, x[0].w), 0.0f, 0.0f, 0.0f);
  if (f == PROBE_CELL_WEIGHTS)
    return vec4(cell_weights(x[0].y, x[0].z), deck_presence(x[0].y), cells_resolved(x[0].z * 100.0f, x[0].w));
  if (f == PROBE_BELTS)
    return vec4(itcz_systems(p, 0.0f, latitude, x[0].y, line_waves_of(seed, x[0].y), seed, x[0].w).x,
                trade_cumulus(p, latitude, seed, x[0].w, trade_regimes(p, seed, 2), x[1].w), cirrus_streaks(p, latitude, seed),
                itcz_systems(p, 0.0f, latitude, x[0].y, line_waves_of(seed, x[0].y), seed, x[0].w).y);
  WeatherSystems systems;
  systems.cyclones[0] = probe_cyclone(x);
  systems.cyclone_count = 1;
  systems.itcz_latitude = x[0].y;
  systems.itcz_waves = line_waves_of(seed, x[0].y);
  systems.itcz = 1.0f;
  systems.trade_cumulus = 1.0f;
  systems.cirrus = 1.0f;
  systems.cells = 1.0f;
  systems.seed = seed;
  if (f == PROBE_NEAR)
    return vec4(float(cyclones_near(p, systems)),
                neighbour_feature(ivec3(floor(p * CLOSED_CELLS)), int(x[0].w), noise_key(seed, CLOSED_CELLS_LAYER)));
  if (f == PROBE_COLD)
    return vec4(cold_sector(vec2(x[0].y, x[0].w)), cold_sectors(p, systems),
                cell_modulation(p, vec2(x[3].z, x[3].w), seed, 1.0e-3f),
                cold_air(p, systems, cyclones_near(p, systems), 1.0f).y);
  if (f == PROBE_BELT_REGIMES) {
    systems.trade_cumulus = x[3].z;
    return belt_regimes(p, latitude, systems, seed);
  }
  if (f == PROBE_BELT_FIELDS) {
    return belt_fields(p, itcz_band(p, systems, x[0].w), latitude, systems, seed, x[0].w,
                       belt_regimes(p, latitude, systems, seed), x[1].w);
  }
  return vec4(weather_density(p, p, latitude, systems, x[0].w, x[1].w),
              cyclone_systems(p, systems, cyclones_near(p, systems), x[0].w),
              belt_systems(p, p, latitude, systems, seed + 1u, x[0].w, x[1].w), 0.0f);  // PROBE_WEATHER_DENSITY
}
