#pragma once
// Every parameter of nephele, declared once. Structs take their defaults from here, the
// command line (src/apps/cli) and scene files (src/regional/scene.cpp) take names, ranges and
// help from here, and the sidecars write their keys from here. docs/architecture.md explains.
#include <vector>

#include "params/parameter.hpp"
#include "params/render_quality.hpp"

namespace nephele::params {

// Commands that make a global cover, and the sidecar that records it.
constexpr unsigned cover_commands = generate | bench_cover | report | cover_sidecar;

namespace cover {
inline constexpr Parameter size =
    integer("size", 512, 1, 16384, "texels", "texels per cube face edge", generate | cover_sidecar);
inline constexpr Parameter seed = integer("seed", 1, 0, 4294967295.0, "", "seed of all noise layers", cover_commands);
inline constexpr Parameter iterations =
    integer("iterations", 2, 0, 100000, "steps", "warp steps K", cover_commands | viewer);
inline constexpr Parameter step =
    real("step", 0.15, 0.0, 10.0, "radians", "warp step size h (flow time T = K h)", cover_commands | viewer);
inline constexpr Parameter coverage = real("coverage", 0.67, 0.0, 1.0, "fraction",
                                           "cloudy fraction of the sphere, by solid angle", cover_commands | viewer);
inline constexpr Parameter profile =
    text("profile", "earth", "earth|flat|FILE",
         "target cloudy fraction by latitude: earth (zonal-mean climatology), flat (one threshold for the sphere), or "
         "a CSV of latitude_deg,fraction rows; its area-weighted mean is rescaled to --coverage (docs/climate.md)",
         cover_commands);
inline constexpr Parameter month = integer(
    "month", 0, 0, 12, "",
    "month of the profile's seasonal shift of the ITCZ and storm tracks (1 January .. 12 December; 0 the annual mean)",
    cover_commands | viewer);
inline constexpr Parameter curl_frequency =
    real("curl_frequency", 2.0, 0.01, 4096.0, "cells per radius",
         "Worley cells per unit radius of the flow's potential", cover_commands, "potential.frequency");
inline constexpr Parameter curl_octaves =
    integer("curl_octaves", 2, 0, 16, "", "octaves of the potential", cover_commands, "potential.octaves");
inline constexpr Parameter curl_lacunarity = real(
    "curl_lacunarity", 2.0, 1.0, 8.0, "", "frequency ratio between octaves", cover_commands, "potential.lacunarity");
inline constexpr Parameter curl_gain =
    real("curl_gain", 0.2, 0.0, 1.0, "", "amplitude ratio between octaves", cover_commands, "potential.gain");
inline constexpr Parameter prevailing =
    real("prevailing", 0.5, -100.0, 100.0, "", "strength of the zonal wind bands (> 0: easterly trade winds)",
         cover_commands);
inline constexpr Parameter mix_frequency = real(
    "mix_frequency", 3.0, 0.0, 10.0, "",
    "a in the hemisphere mix m = sin(a lat); odd a is smooth at the poles (3: sfsim, the default; 2.5: the original)",
    cover_commands);
inline constexpr Parameter curl_smoothing =
    real("curl_smoothing", 0.3, 0.0, 10.0, "",
         "lambda of the smooth Worley potential (0: classic 1 - F1, whose gradient jumps; below 0.02 counts as 0.02)",
         cover_commands);
inline constexpr Parameter zonal_cells = integer(
    "zonal_cells", 3, 0, 3, "",
    "circulation cells per hemisphere of the zonal winds: 3 (Earth: trade easterlies, westerlies from 30 degrees, "
    "polar easterlies beyond 60), 2, 1, or 0 (the winds follow the hemisphere mix sin(a lat), as sfsim)",
    cover_commands);
inline constexpr Parameter storm_tracks =
    real("storm_tracks", 0.6, 0.0, 1.0, "",
         "focus of the flow's vortices on the storm tracks near 50 N and 50 S: their strength there times 1 - "
         "storm_tracks at the equator (0: the same everywhere; docs/climate.md)",
         cover_commands);
inline constexpr Parameter cyclone_cloudiness =
    real("cyclone_cloudiness", 0.5, 0.0, 100.0, "",
         "k in density * (1 + k c), c the flow's cyclonic depth (0 .. about 0.6): cyclones cloudy, anticyclones clear "
         "(0: off; docs/climate.md)",
         cover_commands);
inline constexpr Parameter cyclones =
    integer("cyclones", 6, 0, 15, "per hemisphere",
            "extratropical cyclones with comma cloud, cold-front band, dry slot and warm-front shield, each living 5 "
            "days in the storm track (0: none; docs/climate.md, \"Weather systems\")",
            cover_commands, "systems.cyclones");
inline constexpr Parameter itcz =
    real("itcz", 1.0, 0.0, 1.0, "",
         "strength of the ITCZ's broken line of convective clusters near 5 N, following --month (0: none)",
         cover_commands, "systems.itcz");
inline constexpr Parameter spcz =
    real("spcz", 1.0, 0.0, 1.0, "",
         "strength of the South Pacific Convergence Zone's band of deep cloud and convective clusters from the "
         "Solomon Islands east-south-east towards 25 S 120 W, strongest in February (with --surface: Earth's map; 0: "
         "none)",
         cover_commands, "systems.spcz");
inline constexpr Parameter trade_cumulus =
    real("trade_cumulus", 1.0, 0.0, 1.0, "",
         "strength of the fields of small trade cumulus between 6 and 30 degrees (0: none)", cover_commands,
         "systems.trade_cumulus");
inline constexpr Parameter cirrus = real(
    "cirrus", 1.0, 0.0, 1.0, "", "strength of the thin cirrus streaks along the westerlies, 35-65 degrees (0: none)",
    cover_commands, "systems.cirrus");
inline constexpr Parameter shallow_trades =
    real("shallow_trades", 1.0, 0.0, 1.0, "",
         "strength of the trades' shallow cumulus: within 30 degrees of the equator the cloud no system organises is "
         "thin and grey between the bright systems (0: as bright as the systems)",
         cover_commands, "systems.shallow_trades");
inline constexpr Parameter stratocumulus_cells =
    real("stratocumulus_cells", 1.0, 0.0, 1.0, "",
         "strength of the convective cells: closed in the stratocumulus decks' cores, open at their fringes and in "
         "the cold air behind the cyclones' cold fronts; drawn where the cover resolves them (from 1024 per face "
         "for the closed, 512 for the open; 0: none)",
         cover_commands, "systems.stratocumulus_cells");
inline constexpr Parameter cloud_streets =
    real("cloud_streets", 1.0, 0.0, 1.0, "",
         "strength of the cloud streets, rows of separate cumulus along the wind 12 km apart in the cold air furthest "
         "behind the cyclones' cold fronts, upstream of its open cells; drawn where the cover resolves them (from "
         "about 2700 per face; 0: none)",
         cover_commands, "systems.cloud_streets");
inline constexpr Parameter cover_softness =
    real("cover_softness", 0.05, 0.0, 10.0, "density",
         "cover = 1 - exp(-(density - threshold) / softness): thick cloud saturates to a bright, sharp-edged 1 and "
         "thin cloud stays grey (0: the linear ramp to the largest density of earlier versions)",
         cover_commands, "remap.softness");
inline constexpr Parameter tau_median =
    real("tau_median", 4.0, 0.1, 100.0, "",
         "median optical thickness of the cloudy texels, log-normal by their rank in density (ISCCP: about half of "
         "the cloud thinner than 3.6; docs/climate.md)",
         cover_commands, "optical_thickness.median");
inline constexpr Parameter tau_spread =
    real("tau_spread", 1.2, 0.0, 3.0, "",
         "standard deviation of the natural logarithm of the optical thickness (0: every cloudy texel at the median)",
         cover_commands, "optical_thickness.spread");
inline constexpr Parameter curl_strength =
    real("curl_strength", 0.2, 0.0, 100.0, "", "scale of the flow's potential (velocity = strength * n x grad phi)",
         cover_commands);
inline constexpr Parameter density_frequency =
    real("density_frequency", 3.0, 0.01, 4096.0, "cells per radius",
         "Worley cells per unit radius of the cloud density", cover_commands, "density.frequency");
inline constexpr Parameter density_octaves =
    integer("density_octaves", 8, 0, 16, "", "octaves of the cloud density", cover_commands, "density.octaves");
inline constexpr Parameter density_lacunarity = real(
    "density_lacunarity", 2.0, 1.0, 8.0, "", "frequency ratio between octaves", cover_commands, "density.lacunarity");
inline constexpr Parameter density_gain =
    real("density_gain", 0.75, 0.0, 1.0, "", "amplitude ratio between octaves", cover_commands, "density.gain");
inline constexpr Parameter surface =
    text("surface", "etopo5", "none|etopo5|FILE",
         "land/ocean mask that moves clouds from the subtropical deserts to the stratocumulus decks off the west "
         "coasts: etopo5 (ferret-datasets; none with a warning where it is not installed), none (an Earth without "
         "continents), an ETOPO5 netCDF file (.cdf, .nc), or an equirect image whose first channel is the land "
         "fraction (longitude -180 at the left, north up; docs/climate.md)",
         generate | cover_sidecar | render | scene_file | viewer);
inline constexpr Parameter surface_weight =
    real("surface_weight", 0.4, 0.0, 1.0, "",
         "k in density * (1 + k b), b the land/ocean bias in [-1, 1] (with --surface)", generate | cover_sidecar);
inline constexpr Parameter integrator = text("integrator", "rk4", "euler|heun|rk4|geodesic|adaptive",
                                             "warp stepping rule", generate | cover_sidecar | viewer);
inline constexpr Parameter curl_mode =
    text("curl_mode", "auto", "auto|sampled|procedural|spline",
         "velocity of the warp: sampled (bilinear from the curl cube map), procedural (exact point) or spline (C2 "
         "cubic B-spline of a curl grid of --curl-size per face); auto: spline for the steady flow, and for the "
         "moving flow the cheaper of procedural and a spline on min(--curl-size, max(64, size / 2)) nodes, at most "
         "128 for steps from 0.03 (finer grids gain nothing there), by their count of curl evaluations (procedural "
         "up to 48 texels per face)",
         generate | bench_cover | cover_sidecar);
inline constexpr Parameter warp_grid =
    integer("warp_grid", 512, 0, 1024, "nodes",
            "--flow moving: covers of more texels per face edge than this trace the back-trajectories from a grid of "
            "this many nodes per face edge and interpolate them to every texel by a cubic spline (0: from every "
            "texel; docs/numerics.md, 8b)",
            cover_commands);
inline constexpr Parameter noise_grid_nodes =
    real("noise_grid_nodes", 8.0, 0.0, 1024.0, "nodes per cell",
         "covers traced from a warp grid: the density's octaves whose Worley cells span at least this many of the "
         "grid's node spacings (at a face's centre) are evaluated at the grid's nodes and taken from its cubic spline "
         "instead of at every texel (0: none; docs/numerics.md, 8c)",
         cover_commands);
inline constexpr Parameter curl_size =
    integer("curl_size", 256, 4, 1024, "nodes",
            "curl mode spline: curl samples per cube face edge that the spline interpolates (independent of --size)",
            cover_commands);
inline constexpr Parameter tolerance =
    real("tolerance", 1e-4, 1e-7, 1.0, "radians",
         "adaptive: largest error estimate per step (the flow time is iterations * step)", generate | cover_sidecar);
inline constexpr Parameter max_substeps = integer(
    "max_substeps", 4096, 1, 1000000, "steps", "adaptive: attempted steps per texel at most", generate | cover_sidecar);
inline constexpr Parameter noise_offset =
    real("noise_offset", 0.0, -1e9, 1e9, "sphere radii",
         "shift of every noise layer by (d, d, d); precision is kept by a periodic lattice",
         generate | report | cover_sidecar);
inline constexpr Parameter flow =
    text("flow", "moving", "steady|moving",
         "steady: one flow, one warp (a still map); moving: vortices that are born, drift with the zonal wind and "
         "die, and clouds carried along them: a cover for any --time (docs/algorithm.md, \"The moving flow\"); render "
         "and view show the cover of their scene's --time",
         generate | bench_cover | cover_sidecar | render | scene_file | viewer);
inline constexpr Parameter time =
    text("time", "2000-01-01T00:00Z", "YYYY-MM-DDTHH:MM[:SS]Z",
         "moment of the cover (--flow moving), ISO 8601 UTC; the default is the flow's time 0",
         generate | bench_cover | cover_sidecar);
inline constexpr Parameter vortex_lifetime =
    real("vortex_lifetime", 96, 6, 2400, "hours",
         "--flow moving: life of a generation of vortices, from birth through its peak to death (cyclones: 2-5 days)",
         generate | bench_cover | cover_sidecar);
inline constexpr Parameter loop =
    real("loop", 0, 0, 87600, "hours",
         "--flow moving: the cover repeats after this time, seamlessly (0: never); the vortices' and the clouds' "
         "lifetimes and the flow's time nodes are rounded so that whole numbers of them fit",
         generate | bench_cover | cover_sidecar);
}  // namespace cover

namespace scene {
constexpr unsigned render_and_scene = render | scene_file;
constexpr unsigned render_scene_view = render_and_scene | viewer;  // also options and panels of nephele view
inline constexpr Parameter view = text("view", "gurten", "gurten|bantiger|orbit",
                                       "viewpoint: gurten (towards Solothurn), bantiger (towards Fribourg), or orbit "
                                       "(the planet from --lat, --lon, --altitude-km; docs/orbit_view.md)",
                                       render_scene_view | bench_view);
inline constexpr Parameter at =
    text("at", "", "LAT,LON,HEIGHT",
         "camera position (WGS84 degrees, degrees, metres above the ellipsoid) instead of a view", render);
inline constexpr Parameter latitude =
    real("latitude", 0, -90, 90, "degrees", "camera latitude (scene key at.latitude)", scene_file);
inline constexpr Parameter longitude =
    real("longitude", 0, -180, 180, "degrees", "camera longitude (scene key at.longitude)", scene_file);
inline constexpr Parameter height =
    real("height", 0, -400, 20000, "metres", "camera height above the ellipsoid (scene key at.height)", scene_file);
inline constexpr Parameter heading = Parameter{"heading",
                                               Type::real,
                                               "degrees",
                                               0,
                                               "towards the view's city",
                                               -360,
                                               360,
                                               "",
                                               "view heading, clockwise from north",
                                               render_scene_view};
inline constexpr Parameter pitch =
    real("pitch", 5, -90, 90, "degrees", "view pitch above the horizon", render_scene_view);
inline constexpr Parameter fov = real("fov", 70, 1, 179, "degrees", "horizontal field of view", render_scene_view);
inline constexpr Parameter time =
    text("time", "2026-06-21T16:00Z", "YYYY-MM-DDTHH:MM[:SS]Z", "date and time, ISO 8601 UTC", render_scene_view);
inline constexpr Parameter size =
    text("size", "1280x720", "WIDTHxHEIGHT", "image size (panorama: 2048x1024 unless given)", render_scene_view);
inline constexpr Parameter panorama =
    flag("panorama", "render the full 360 x 180 view sphere (equirectangular)", render_and_scene);
inline constexpr Parameter weather =
    list("weather", "FILE", "Open-Meteo or meteoblue JSON of a station", render_and_scene);
// The step settings: their numbers are those of the final quality (what regional::Scene{} and
// the library render); the command line, scene files and the viewer take them from --quality
// unless they are given (regional::apply_render_quality).
inline constexpr Parameter quality =
    text("quality", "default", "draft|default|final",
         "view steps, light steps, frames and resolution divisor from a measured display error target: draft about "
         "0.02, default 0.01 (seconds on two CPU cores), final 0.003 (full resolution); those given by name override "
         "it (docs/rendering.md, Qualities)",
         render_scene_view);
inline constexpr std::string_view from_quality = "from --quality";
inline constexpr Parameter view_steps = {"view_steps",
                                         Type::integer,
                                         "samples",
                                         render_qualities[2].view_steps,
                                         from_quality,
                                         1,
                                         4096,
                                         "",
                                         "samples per layer along each view ray",
                                         render_scene_view};
inline constexpr Parameter light_steps = {"light_steps",
                                          Type::integer,
                                          "samples",
                                          render_qualities[2].light_steps,
                                          from_quality,
                                          0,
                                          256,
                                          "",
                                          "samples towards the sun per cloud sample",
                                          render_scene_view};
inline constexpr Parameter frames = {
    "frames",
    Type::integer,
    "frames",
    render_qualities[2].frames,
    from_quality,
    1,
    1024,
    "",
    "frames averaged, each with its own jitter of the march start (temporal accumulation)",
    render_and_scene};
inline constexpr Parameter resolution_divisor = {
    "resolution_divisor",
    Type::integer,
    "",
    render_qualities[2].resolution_divisor,
    from_quality,
    1,
    8,
    "",
    "render at 1/N of the width and height and upsample, guided by where the full-size rays meet the ground (sharp "
    "horizon and hills): about N^2 times cheaper, clouds blurred (docs/rendering.md)",
    render_and_scene};
inline constexpr Parameter sky_steps =
    integer("sky_steps", 16, 1, 1024, "samples", "samples of the clear-sky integral", scene_file);
inline constexpr Parameter powder =
    real("powder", 0, 0, 1, "",
         "strength k of the powder term P = 1 - k (1 - nu)/2 exp(-2 tau), which darkens the sun-facing surfaces of "
         "clouds seen with the sun behind (Schneider 2015; art-directed, 0: off; docs/rendering.md)",
         render_and_scene);
inline constexpr Parameter shadow_map_size = integer("shadow_map_size", 512, 0, 4096, "texels",
                                                     "texels per side of the shadow maps that let higher layers shade "
                                                     "lower ones (0: no such shadows; docs/rendering.md)",
                                                     scene_file);
inline constexpr Parameter fog_top =
    real("fog_top", 800, 300, 3000, "metres",
         "top of the ground fog (sea of fog) above sea level when the weather brings fog; 800 m: the Swiss Plateau's "
         "winter inversion, below Gurten and Bantiger (docs/terrain.md)",
         render_and_scene);
inline constexpr Parameter terrain = text("terrain", "etopo5", "etopo5|flat|FILE",
                                          "ground relief: ETOPO5 of ferret-datasets (bare sphere with a warning when "
                                          "absent), flat (the bare sphere), or an ETOPO5 netCDF file (docs/terrain.md)",
                                          render_and_scene);
inline constexpr Parameter terrain_detail =
    real("terrain_detail", 1, 0, 3, "",
         "strength of the fractal relief added below the elevation data's 9 km cells, its amplitudes continuing the "
         "data's structure function (0: the data's smooth surface; docs/terrain.md)",
         render_and_scene);
inline constexpr Parameter land_cover =
    text("land_cover", "swiss-maps", "swiss-maps|none|FILE",
         "lakes and towns on the ground: swiss-maps' TopoJSON as scripts/install-data.sh installs it (none with a "
         "warning when absent), none, or a swiss-maps TopoJSON file; forest, fields and snow are drawn either way "
         "(docs/terrain.md)",
         render_and_scene);
inline constexpr Parameter exposure =
    real("exposure", 4.0, 1e-6, 1e6, "",
         "exposure before tone mapping (PNG); without it --view orbit meters the frame's highlights, never "
         "brighter than a sunlit white surface in view needs (docs/orbit_view.md)",
         render_scene_view);
inline constexpr Parameter seed =
    integer("seed", 1, 0, 4294967295.0, "", "seed of the global cover and the cloud noise", render_scene_view);
inline constexpr Parameter cover_size = integer(
    "cover_size", 128, 4, 4096, "texels", "global cover size per face when no weather is given", scene_file | viewer);
inline constexpr Parameter outputs = list("outputs", "NAME.png|NAME.exr", "file names written into --out", scene_file);
inline constexpr Parameter description = text("description", "", "", "free text for people", scene_file);
inline constexpr Parameter scene_path =
    text("scene", "", "FILE", "scene file (JSON, see scenes/); options override it", render | viewer);
inline constexpr Parameter out =
    text("out", "", "FILE.png|FILE.exr|DIR", "output file (.png or .exr), or a directory with --scene", render);
// The orbit view (render --view orbit; docs/orbit_view.md).
inline constexpr Parameter lat = real("lat", 46.9, -90, 90, "degrees", "orbit view: latitude below the camera", render);
inline constexpr Parameter lon =
    real("lon", 7.4, -180, 180, "degrees", "orbit view: longitude below the camera", render);
inline constexpr Parameter altitude_km =
    real("altitude_km", 2000, 0.001, 40000, "km",
         "orbit view: camera altitude above the planet's sphere (1 m to 40000 km)", render);
inline constexpr Parameter cover = text("cover", "", "DIR",
                                        "orbit view: cover directory written by nephele generate (default: a cover "
                                        "generated with --seed, 128 texels per face)",
                                        render);
inline constexpr Parameter earth_texture = text("earth_texture", "", "FILE",
                                                "orbit view: equirect day map, longitude -180 at the left, north up "
                                                "(default /usr/share/xplanet/images/earth.jpg, else procedural)",
                                                render);
inline constexpr Parameter night_texture =
    text("night_texture", "", "FILE",
         "orbit view: equirect city-light map (default /usr/share/xplanet/images/night.jpg with the default day map)",
         render);
inline constexpr Parameter planet_radius_km =
    real("planet_radius_km", 6371, 1, 1e6, "km", "orbit view: radius of the planet's sphere", render);
inline constexpr Parameter cloud_base_km =
    real("cloud_base_km", 0.3, 0, 90, "km",
         "orbit view: the lowest cloud base; each cloud's slab comes from the cover's tau and cloud_top "
         "(docs/orbit_view.md)",
         render);
inline constexpr Parameter cloud_thickness_km =
    real("cloud_thickness_km", 15.7, 0.01, 90, "km",
         "orbit view: the shell the clouds lie in above the lowest base, which clips their tops (base + thickness "
         "below 100 km)",
         render);
inline constexpr Parameter cloud_detail =
    real("cloud_detail", 1, 0, 1, "",
         "orbit view: the clouds below the cover's texels, fractal edges and relief of their tops (1), or the texels "
         "as smooth slabs (0)",
         render);
inline constexpr Parameter cloud_tau_spread =
    real("cloud_tau_spread", 0.84, 0, 2, "",
         "orbit view: the deviation of ln tau inside a cover texel's cloud of medium and thick optical thickness "
         "(tau from 3.6; faded in from 1), drawn with the sub-texel cloud (0.84: the plane-parallel albedo bias of "
         "marine stratocumulus, Cahalan et al. 1994; 0: uniform)",
         render);
}  // namespace scene

namespace noise_texture {
inline constexpr Parameter preset =
    text("preset", "", "shape|erosion",
         "shape (128^3 RGBA Perlin-Worley + Worley fBm) or erosion (32^3 RGB Worley fBm)", noise);
inline constexpr Parameter type =
    text("type", "worley", "worley|inverted-worley|perlin|perlin-worley", "noise type of every channel", noise);
inline constexpr Parameter width = integer("width", 32, 1, 65536, "texels", "texels along x", noise);
inline constexpr Parameter height = integer("height", 32, 1, 65536, "texels", "texels along y", noise);
inline constexpr Parameter depth = integer("depth", 32, 1, 65536, "texels", "texels along z (slices)", noise);
inline constexpr Parameter size =
    integer("size", 32, 1, 65536, "texels", "texels along every axis (instead of --width, --height, --depth)", noise);
inline constexpr Parameter cells =
    integer("cells", 4, 1, 1048576, "cells",
            "cells per period along the width at octave 0; the other axes follow the aspect", noise);
inline constexpr Parameter octaves = integer("octaves", 1, 1, 8, "", "fBm octaves", noise);
inline constexpr Parameter lacunarity =
    real("lacunarity", 2.0, 1.0, 8.0, "", "frequency ratio between octaves (whole cells)", noise);
inline constexpr Parameter gain =
    real("gain", 0.5, 0.0, 2.0, "", "amplitude ratio between octaves (persistence)", noise);
inline constexpr Parameter worley_cells =
    integer("worley_cells", 0, 0, 1048576, "cells", "perlin-worley: cells of the Worley fBm (0: as --cells)", noise);
inline constexpr Parameter worley_octaves =
    integer("worley_octaves", 3, 1, 8, "", "perlin-worley: octaves of the Worley fBm", noise);
inline constexpr Parameter channels = text("channels", "r", "r|rg|rgb|rgba", "channel layout", noise);
inline constexpr Parameter r =
    text("r", "", "key=value,...",
         "settings of channel r: keys type, cells, octaves, lacunarity, gain, worley-cells, worley-octaves", noise);
inline constexpr Parameter g = text("g", "", "key=value,...", "settings of channel g (keys as for --r)", noise);
inline constexpr Parameter b = text("b", "", "key=value,...", "settings of channel b (keys as for --r)", noise);
inline constexpr Parameter a = text("a", "", "key=value,...", "settings of channel a (keys as for --r)", noise);
inline constexpr Parameter seed = integer("seed", 1, 0, 4294967295.0, "", "seed of every channel", noise);
inline constexpr Parameter bits = integer("bits", 8, 8, 16, "bits", "bits per PNG sample: 8 or 16", noise);
inline constexpr Parameter out = text("out", "", "FILE.png|FILE.exr|FILE.raw",
                                      "output file: .png or .exr (slice atlas) or .raw (float32 volume)", noise);
inline constexpr Parameter stretch =
    flag("stretch", "map each channel's range linearly onto [0, 1] (the range before goes to the sidecar)", noise);
}  // namespace noise_texture

// The implicit cloud modeller (nephele model, scenes/*.cloud.json; docs/model.md). Positions,
// radii and influences are in model units: the volume is the unit cube, z up.
namespace cloud_model {
constexpr unsigned command_and_file = model | model_file;
inline constexpr Parameter example = text("example", "", "fair-weather|towering|cumulonimbus|stratocumulus",
                                          "a built-in cloud instead of --scene", model);
inline constexpr Parameter scene_path =
    text("scene", "", "FILE", "cloud model file (JSON, see scenes/*.cloud.json); options override it", model);
inline constexpr Parameter size =
    integer("size", 256, 8, 2048, "voxels", "voxels along each edge of the density volume", model | bench_model);
inline constexpr Parameter out = text("out", "model", "DIR", "output directory (created if missing)", model);
inline constexpr Parameter blend =
    text("blend", "per-primitive", "sum|lipus|global|per-primitive",
         "blend: sum (eq. 2), lipus (eq. 3), global turbulence after Lipus (eq. 5), turbulence per primitive (eq. 6)",
         command_and_file);
inline constexpr Parameter scale =
    real("scale", 0.02, 1e-4, 1e4, "", "noise coordinates are model coordinates divided by this (0.02 in the paper)",
         command_and_file);
inline constexpr Parameter base =
    real("base", 0, 0, 1, "model units", "height of the flat base, the condensation level (0: none; docs/model.md)",
         command_and_file);
inline constexpr Parameter top = real(
    "top", 1, 0, 1, "model units", "height of the flat top, the tropopause under an anvil (1: none)", command_and_file);
inline constexpr Parameter extent = real(
    "extent", 2000, 1, 1e6, "metres", "edge of the modelled cube (the voxel size is extent / size)", command_and_file);
inline constexpr Parameter description = text("description", "", "", "free text for people", model_file);
inline constexpr Parameter preview =
    text("preview", "384x384", "WIDTHxHEIGHT",
         "size of preview.png, the volume lit by the sun from the south-west and seen from the south", model);
inline constexpr Parameter no_preview = flag("no_preview", "write no preview.png", model);
inline constexpr Parameter kind = text("type", "point", "point|segment|polyline",
                                       "skeleton of a primitive: a point (key position), a segment (keys from, to) or "
                                       "a polyline (key points: its segments)",
                                       model_file);
inline constexpr Parameter coordinate =
    real("position", 0.5, -1, 2, "model units",
         "a skeleton point's coordinate (position, from, to: [x, y, z], the cube is [0, 1]^3)", model_file);
inline constexpr Parameter radius =
    real("radius", 0.1, 0, 1, "model units", "skeleton radius R: the field is 1 within it", model_file);
inline constexpr Parameter influence = real("influence", 0.1, 1e-3, 2, "model units",
                                            "influence I: the field falls from 1 at R to 0 at R + I", model_file);
inline constexpr Parameter weight =
    real("weight", 1, 1e-3, 1, "", "weight w of every primitive (Lipus's blend needs one w for all)", model_file);
inline constexpr Parameter octaves = integer("octaves", 4, 0, 8, "", "turbulence octaves", model_file);
inline constexpr Parameter frequency =
    real("frequency", 0.2, 0, 64, "", "turbulence frequency fr (noise coordinates)", model_file);
inline constexpr Parameter amplitude = real("amplitude", 1.0, 0, 4, "", "turbulence amplitude a", model_file);
inline constexpr Parameter gain = real("gain", 0.5, 0, 1, "", "amplitude ratio ga between octaves", model_file);
inline constexpr Parameter lacunarity =
    real("lacunarity", 2.0, 1, 4, "", "frequency ratio lc between octaves", model_file);
inline constexpr Parameter fraction = real("fraction", 0.5, 0, 1, "", "noise fraction np", model_file);
inline constexpr Parameter erosion =
    real("erosion", 0.5, 0, 1, "",
         "how deep the turbulence erodes the field's edge into lobes (Nubis's remap; 0: the paper's eq. 5 and 6 alone)",
         model_file);
inline constexpr Parameter seed = integer("seed", 1, 0, 16777215, "", "seed of the turbulence", model_file);
inline constexpr Parameter view_model =
    text("model", "", "FILE|EXAMPLE",
         "open the modeller on a cloud model file (*.cloud.json) or a built-in example (fair-weather, towering, "
         "cumulonimbus, stratocumulus) instead of the ground view; Ctrl+S saves it to FILE (an example: "
         "EXAMPLE.cloud.json in the working directory)",
         viewer | bench_view);
inline constexpr Parameter view_model_size =
    integer("model_size", 128, 8, 1024, "voxels",
            "voxels along each edge of the modeller's density volume, a preview size made again on every edit (nephele "
            "model --size N writes the same volume at N)",
            viewer | bench_view);
}  // namespace cloud_model

// Options of the runs themselves: where files go, how much is printed, how long to measure.
namespace run {
inline constexpr Parameter cover_out =
    text("out", "cubemaps", "DIR", "output directory (created if missing)", generate);
inline constexpr Parameter sequence =
    integer("sequence", 0, 0, 100000, "frames",
            "--flow moving: write this many frames from --time on, each a whole cover set in OUT/frame_NNNN/, with "
            "OUT/sequence.json listing them and OUT/sequence.gif showing them (0: one cover in OUT)",
            generate);
inline constexpr Parameter interval =
    real("interval", 3, 0.01, 8760, "hours", "--sequence: time between frames", generate);
inline constexpr Parameter cover_files = text(
    "files", "faces,equirect,png", "faces,equirect,png",
    "comma-separated images to write (cover.json always); what none asks for is not computed", generate | assemble);
inline constexpr Parameter tiles =
    integer("tiles", 0, 0, 6.0 * 16384, "tiles",
            "compute the cube map in this many tiles, strips of rows of each face (a multiple of 6), one after "
            "another; 0: as few as --memory-budget allows (docs/scale.md)",
            generate);
inline constexpr Parameter tile =
    text("tile", "", "A or A-B",
         "with --tiles: compute only tiles A to B (from 0) into --out as tile parts for nephele assemble, skipping "
         "parts already complete there; for the tasks of a job array (docs/scale.md)",
         generate);
inline constexpr Parameter memory_budget =
    integer("memory_budget", 0, 0, 16777216, "MiB",
            "memory the cover's passes may take, GPU and host; larger covers are computed in tiles (0: the GPU's free "
            "memory, with a software renderer half the host's available memory)",
            generate | assemble);
inline constexpr Parameter assemble_out =
    text("out", "cubemaps", "DIR", "output directory of the assembled cover (created if missing)", assemble);
inline constexpr Parameter cover_exports =
    text("export", "", "NAME,NAME,...",
         "export presets (docs/export.md) run on the new cover, each into DIR/export/NAME of the same output set",
         generate | assemble);
inline constexpr Parameter precision =
    text("precision", "float", "float|half",
         "EXR samples: 32-bit float, or 16-bit half (11 significant bits, half the bytes)", generate | assemble);
inline constexpr Parameter exr_compression =
    text("exr_compression", "zip", "none|rle|zips|zip|piz|pxr24|b44|dwaa",
         "EXR compression: zip (OpenEXR's default), none, rle, zips, piz lose nothing; pxr24, b44, dwaa round values",
         generate | assemble);
inline constexpr Parameter export_preset =
    text("preset", "",
         "equirect|gl-faces|ktx2|dds|celestia|exr-cube|flightgear|eve|unity|godot|unreal|blender|atlas|openvdb",
         "the target's files (docs/export.md)", export_cover);
inline constexpr Parameter export_out =
    text("out", "", "DIR", "output directory (created if missing; the set appears whole or not at all)", export_cover);
inline constexpr Parameter export_format =
    text("format", "r16f", "r16f|r32f|r8|bc4",
         "texel format of the ktx2 preset: half float, float, 8-bit unsigned normalised, BC4 blocks", export_cover);
inline constexpr Parameter export_name =
    text("name", "nephele_clouds", "NAME",
         "add-on folder and file name of the celestia and eve presets (letters, digits, _ and -)", export_cover);
inline constexpr Parameter stats_out =
    text("out", "", "DIR",
         "output directory of stats.json and stats.png (default COVER_DIR/stats; created if missing, replaced whole)",
         stats);
inline constexpr Parameter report_out = text("out", "report", "DIR", "output directory (created if missing)", report);
inline constexpr Parameter quiet =
    flag("quiet", "no progress reports on stderr (they appear for work of more than a second)",
         generate | report | render | noise | model | assemble);
inline constexpr Parameter no_cache = flag("no_cache",
                                           "neither read nor write the cache of generated covers, noise volumes and "
                                           "the orbit view's maps ($XDG_CACHE_HOME/nephele, else ~/.cache/nephele)",
                                           render | viewer);
inline constexpr Parameter verbose = flag("verbose", "print the renderer, the passes that ran and their times",
                                          generate | render | noise | model | assemble);
inline constexpr Parameter bench_cover_sizes =
    text("sizes", "256,512,1024", "N,N,... (1 to 16384)", "comma-separated cube face sizes", bench_cover);
inline constexpr Parameter bench_cover_repeat =
    integer("repeat", 3, 1, 100, "runs",
            "timed runs per size, after a first run that compiles the shaders; the median is printed", bench_cover);
inline constexpr Parameter bench_noise_size =
    integer("size", 128, 8, 1024, "texels", "grid edge of the point-rate figures", bench_noise);
inline constexpr Parameter bench_noise_repeat =
    integer("repeat", 7, 1, 1000, "runs", "runs per figure after a first, warming run", bench_noise);
inline constexpr Parameter bench_render_size = text("size", "1280x720", "WIDTHxHEIGHT", "frame size", bench_render);
inline constexpr Parameter bench_render_sweep_size =
    text("sweep_size", "320x180", "WIDTHxHEIGHT", "frame size of the error sweep", bench_render);
inline constexpr Parameter bench_render_repeat =
    integer("repeat", 2, 1, 20, "frames", "frames timed; the median is printed", bench_render);
inline constexpr Parameter bench_render_no_sweep = flag("no_sweep", "time frames only", bench_render);
inline constexpr Parameter bench_model_repeat = integer(
    "repeat", 3, 1, 100, "runs", "runs per figure after a first, warming run; the median is printed", bench_model);
inline constexpr Parameter report_quick =
    flag("quick", "a short sweep for CI (size 32, 1, 2, 4, 8 and 50 steps, 96 points; render 32x18)", report);
inline constexpr Parameter report_sizes = text(
    "sizes", "", "N,N,... (1 to 16384)", "comma-separated cube face sizes (default 128,256,512; quick 32)", report);
inline constexpr Parameter report_steps =
    text("steps", "", "N,N,... (1 to 100000)",
         "comma-separated step counts of the fixed-step schemes (default 1,2,4,8,16,32,50,100,200)", report);
inline constexpr Parameter report_tolerances =
    text("tolerances", "", "X,X,... (1e-9 to 1)",
         "comma-separated tolerances of the adaptive scheme (default 1e-2..1e-6)", report);
inline constexpr Parameter report_samples =
    integer("samples", 0, 0, 64, "", "sample grid m: 6 m^2 sample points (0: 20, quick 4)", report);
inline constexpr Parameter report_repeat =
    integer("repeat", 0, 0, 20, "runs", "timed runs per configuration, the fastest counts (0: 3, quick 1)", report);
inline constexpr Parameter report_render_size =
    text("render_size", "", "WIDTHxHEIGHT", "frame size of the render sweep (default 160x90; quick 32x18)", report);
inline constexpr Parameter report_no_render = flag("no_render", "skip the render sweep", report);
inline constexpr Parameter view_record =
    text("record", "", "DIR", "write every displayed frame as DIR/frame_NNNNNN.png (created if missing)", viewer);
inline constexpr Parameter time_step =
    real("time_step", 1, 0.01, 240, "hours",
         "how far the keys , and . move the time, and T's playback per frame (the sun and, with --flow moving, the "
         "clouds)",
         viewer);
inline constexpr Parameter view_frames =
    integer("frames", 0, 0, 1e9, "frames",
            "close the window after this many frames (0: when it is closed); for scripts", viewer);
inline constexpr Parameter bench_view_size =
    text("size", "640x360", "WIDTHxHEIGHT",
         "window size (the full-size render; the preview is a quarter of it each way)", bench_view);
inline constexpr Parameter bench_view_repeat = integer(
    "repeat", 3, 1, 100, "changes", "view changes timed, each refined to full size; the median is printed", bench_view);
inline constexpr Parameter report_budget_ms =
    real("budget_ms", 0.0, 0.0, 1e7, "ms", "skip runs predicted to take longer (0: 20000, quick 2000)", report);
}  // namespace run

// Every parameter above, in declaration order (for documentation, panels and the tests).
const std::vector<const Parameter*>& all();

}  // namespace nephele::params
