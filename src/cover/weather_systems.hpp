#pragma once
// The host's side of the weather systems (shaders/lib/weather_systems.glsl): where the
// extratropical cyclones are at a moment, how old and how strong, and the ITCZ's line. Each
// cyclone lives through its own slot of a seeded schedule, so that the systems of any moment
// follow from the seed and the time alone: frames are computed on their own, in any order
// (docs/climate.md, "Weather systems").
#include <cstdint>

#include "cover/cover_parameters.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::cover {

// The life of an extratropical cyclone from its wave to its decay, hours: 3-7 days observed
// (Hoskins and Hodges 2002, "New perspectives on the Northern Hemisphere winter storm tracks",
// J. Atmos. Sci. 59: most tracks last 2-6 days); nephele takes 5.
constexpr double cyclone_lifetime_hours = 120.0;
// Their eastward speed, m/s (Hoskins and Hodges 2002: 10-15 m/s along the tracks), and the
// poleward drift over a life, degrees (Hoskins and Hodges: 5-15 degrees).
constexpr double cyclone_speed_m_s = 12.0;
constexpr double cyclone_poleward_deg = 10.0;

// The ITCZ's waves (weather_systems.glsl's LineWaves) move along it: its meander with the easterly
// waves, west at about 8 m/s (Reed, Norquist and Recker 1977: 7-8 m/s over the Atlantic), its
// superclusters east at about 12 m/s (Nakazawa 1988: 10-15 m/s), so that every frame has its own
// line from the seed and the time alone. (Speeds at the equator: angular speeds v / 6371 km.)
constexpr double itcz_meander_speed_m_s = -8.0;
constexpr double supercluster_speed_m_s = 12.0;
// `waves` (at time 0) at `hours`: each wave of wavenumber m turned by m times its angular speed.
// With a loop (`loop_hours` > 0, --loop) each turns the whole number of times in the loop nearest
// to its speed's (none in a loop shorter than half its period), so the cover repeats after it.
glsl::LineWaves moved_line_waves(glsl::LineWaves waves, double hours, double loop_hours);

// The monsoons (docs/climate.md, "The monsoons"): over land the tropical rain belt follows the
// sun further than over the oceans, to about monsoon_land_deg into the summer hemisphere in the
// months of its extreme (August north, February south, as the profile's seasonal shift), and near
// the equator in the annual mean (--month 0). The ITCZ's line over longitude `lon` moves from the
// oceans' `line` (radians) towards that latitude by the land's share within 10 degrees of it and
// 10 degrees of longitude (about 1100 km) either side. The shift, in radians of latitude, as a
// function of longitude (radians).
constexpr double monsoon_land_deg = 15.0;
double monsoon_target(const SurfaceMask& mask, int month, double line, double lon);
// The waves `waves` with their monsoons: that target's mean and its zonal waves 1 to
// MONSOON_WAVES (Lanczos-smoothed, so that the truncation does not ring over the oceans) in
// sin(latitude) at the line, and monsoon_reach a bound of their sum's size in radians.
glsl::LineWaves with_monsoons(glsl::LineWaves waves, const SurfaceMask& mask, int month, double line);

// The South Pacific Convergence Zone (weather_systems.glsl's spcz_presence), drawn with a map of
// the Earth (its line is fixed to the map: the warm pool's and the cold tongue's sea surface
// temperatures set it, van der Wiel et al. 2016, "Why the South Pacific Convergence Zone is
// diagonal", Clim. Dyn. 46): present all year, most active in austral summer and weaker and further
// north in winter (Vincent 1994). Its strength relative to --spcz in a month, 0.75 - 0.25
// seasonal_phase: 1 in February, 0.5 in August and 0.75 for the annual mean (month 0); and its
// line moves with the profile's seasonal shift at spcz_mid_latitude_deg, its middle's latitude
// (4.1 degrees north in August).
float spcz_season(int month);
constexpr double spcz_mid_latitude_deg = -15.0;

// One cyclone's state at `age_fraction` = age / lifetime in [0, 1): its strength (grows in the
// first fifth, decays in the last third) and how far its head winds (half a turn as a wave, three
// quarters of a turn more as it occludes).
float cyclone_strength(double age_fraction);
float cyclone_wrap(double age_fraction);

// The ocean's share (1 - the mask's land fraction) along the mature life (ages 0.2-0.67 of the
// lifetime, strength 1) of a cyclone born at (genesis_lat, genesis_lon), degrees (negative
// latitudes: the south), sampled at its centre and 5 degrees around it.
double mature_ocean_share(const SurfaceMask& mask, double genesis_lat, double genesis_lon);

// The systems at `hours` since the flow's epoch (cover/moving_flow.hpp): p.cyclones per
// hemisphere on average (a Poisson-like schedule: genesis every lifetime / p.cyclones hours with
// a seeded jitter), each from its genesis place in the storm track (38 +- 6 degrees, moved with
// --month as the profile's storm tracks) drifting east and poleward. With a land mask
// (p.surface) a genesis longitude is kept with the probability mature_ocean_share, so that the
// cyclones grow and mature over the oceans' storm tracks (Hoskins and Hodges 2002) and not over
// the continents' interiors; without one, any longitude. With --loop the schedule
// repeats after the loop, so the cover does. At most n + 1 are alive per hemisphere (a slot's
// jitter is below its spacing), so the table's 15 fill MAX_CYCLONES at most.
glsl::WeatherSystems weather_systems(const CoverParameters& p, double hours);

// The convective cells' patterns a cover draws (cover_density.comp's CLOSED_CELLS_DRAWN and
// OPEN_CELLS_DRAWN): with --stratocumulus-cells above 0, those its texels resolve at a face's
// centre (weather_systems.glsl's cells_resolved above 0: the open cells from about 400 texels a
// face, the closed from about 800), and with --cloud-streets above 0 and cyclones to have cold
// air, the streets where resolved (from about 2700). The density pass is compiled without the others.
struct CellPatterns {
  bool closed = false, open = false, streets = false;
};
CellPatterns cell_patterns_drawn(const CoverParameters& p);

// The belts' noise of the moving flow's cloud layer `layer` (cover/moving_flow.hpp): its own, as
// the layer's density noise is (derived from that noise's seed), so that the ITCZ's clusters, the
// cumulus and the cirrus fade in and out with the layers instead of jumping between them.
std::uint32_t layer_systems_seed(const CoverParameters& p, std::int64_t layer, int layers_in_loop);

}  // namespace nephele::cover
