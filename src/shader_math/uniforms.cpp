#include "shader_math/uniforms.hpp"

namespace nephele::glsl {
namespace {

template <class T>
void set_member(const gpu::ComputeProgram& program, const std::string& name, T value, Members members) {
  if (members == Members::all || program.has_uniform(name)) program.set(name, value);
}

}  // namespace

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const FbmParams& params,
                 Members members) {
  set_member(program, name + ".frequency", params.frequency, members);
  set_member(program, name + ".octaves", params.octaves, members);
  set_member(program, name + ".lacunarity", params.lacunarity, members);
  set_member(program, name + ".gain", params.gain, members);
  set_member(program, name + ".seed", static_cast<unsigned>(params.seed), members);
  set_member(program, name + ".period", params.period, Members::active);
}

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const CurlParams& params) {
  set_uniform(program, name + ".potential_north", params.potential_north);
  set_uniform(program, name + ".potential_south", params.potential_south);
  program.set(name + ".prevailing", params.prevailing);
  program.set(name + ".mix_frequency", params.mix_frequency);
  program.set(name + ".strength", params.strength);
  program.set(name + ".smoothing", params.smoothing);
  program.set(name + ".storm_tracks", params.storm_tracks);
  program.set(name + ".storm_track_shift", params.storm_track_shift);
  program.set(name + ".zonal_cells", params.zonal_cells);
}

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const FlowMotion& motion) {
  program.set(name + ".generation_time", motion.generation_time);
  program.set(name + ".origin", motion.origin);
  program.set(name + ".drift", motion.drift);
  program.set(name + ".generations", motion.generations);
}

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const WeatherSystems& systems) {
  for (int i = 0; i < MAX_CYCLONES; ++i) {
    const Cyclone& c = systems.cyclones[i];
    const std::string cyclone = name + ".cyclones[" + std::to_string(i) + "].";
    program.set(cyclone + "centre", c.centre);
    program.set(cyclone + "east", c.east);
    program.set(cyclone + "pole", c.pole);
    program.set(cyclone + "radius", c.radius);
    program.set(cyclone + "wrap", c.wrap);
    program.set(cyclone + "strength", c.strength);
  }
  program.set(name + ".cyclone_count", systems.cyclone_count);
  program.set(name + ".itcz_latitude", systems.itcz_latitude);
  program.set(name + ".itcz", systems.itcz);
  const std::string waves = name + ".itcz_waves.";
  for (int k = 0; k < LINE_WAVES; ++k) {
    program.set(waves + "meander[" + std::to_string(k) + "]", systems.itcz_waves.meander[k]);
    program.set(waves + "envelope[" + std::to_string(k) + "]", systems.itcz_waves.envelope[k]);
  }
  for (int k = 0; k < glsl::MONSOON_WAVES; ++k)
    program.set(waves + "monsoon[" + std::to_string(k) + "]", systems.itcz_waves.monsoon[k]);
  program.set(waves + "monsoon_mean", systems.itcz_waves.monsoon_mean);
  program.set(waves + "monsoon_reach", systems.itcz_waves.monsoon_reach);
  program.set(waves + "meander_z", systems.itcz_waves.meander_z);
  program.set(waves + "dormant", systems.itcz_waves.dormant);
  program.set(waves + "applies", systems.itcz_waves.applies);
  program.set(waves + "spcz", systems.itcz_waves.spcz);
  program.set(waves + "spcz_shift", systems.itcz_waves.spcz_shift);
  program.set(name + ".trade_cumulus", systems.trade_cumulus);
  program.set(name + ".cirrus", systems.cirrus);
  program.set(name + ".shallow_trades", systems.shallow_trades);
  program.set(name + ".cells", systems.cells);
  program.set(name + ".streets", systems.streets);
  program.set(name + ".seed", static_cast<unsigned>(systems.seed));
}

void set_uniform(const gpu::ComputeProgram& program, const std::string& name, const MarchParams& params) {
  for (int i = 0; i < MAX_LAYERS; ++i) {
    const LayerParams& l = params.layers[i];
    const std::string layer = name + ".layers[" + std::to_string(i) + "].";
    program.set(layer + "type", l.type);
    program.set(layer + "channel", l.channel);
    program.set(layer + "base", l.base);
    program.set(layer + "top", l.top);
    program.set(layer + "extinction", l.extinction);
    program.set(layer + "morph", l.morph);
    program.set(layer + "darkness", l.darkness);
    program.set(layer + "min_distance", l.min_distance);
    program.set(layer + "wind", l.wind);
    program.set(layer + "noise_offset", l.noise_offset);
    program.set(layer + "shadow_map", l.shadow_map);
  }
  program.set(name + ".layer_count", params.layer_count);
  program.set(name + ".earth_radius", params.earth_radius);
  program.set(name + ".camera_altitude", params.camera_altitude);
  program.set(name + ".forward", params.forward);
  program.set(name + ".right", params.right);
  program.set(name + ".up", params.up);
  program.set(name + ".tan_half_fov", params.tan_half_fov);
  program.set(name + ".panorama", params.panorama);
  program.set(name + ".heading", params.heading);
  program.set(name + ".sun", params.sun);
  program.set(name + ".ambient", params.ambient);
  program.set(name + ".ground_radiance", params.ground_radiance);
  program.set(name + ".ground_ambient", params.ground_ambient);
  program.set(name + ".detail_erosion", params.detail_erosion);
  program.set(name + ".view_steps", params.view_steps);
  program.set(name + ".light_steps", params.light_steps);
  program.set(name + ".sky_steps", params.sky_steps);
  program.set(name + ".weather_extent", params.weather_extent);
  program.set(name + ".max_distance", params.max_distance);
  program.set(name + ".pixel_angle", params.pixel_angle);
  program.set(name + ".noise_texels", params.noise_texels);
  program.set(name + ".frame", params.frame);
  program.set(name + ".shadow_extent", params.shadow_extent);
  program.set(name + ".sky_shadow_map", params.sky_shadow_map);
  program.set(name + ".sky_shadow_base", params.sky_shadow_base);
  program.set(name + ".powder", params.powder);
  program.set(name + ".terrain.enabled", params.terrain.enabled);
  program.set(name + ".terrain.extent", params.terrain.extent);
  program.set(name + ".terrain.top", params.terrain.top);
  program.set(name + ".terrain.texel", params.terrain.texel);
  program.set(name + ".terrain.reach", params.terrain.reach);
  program.set(name + ".terrain.land", params.terrain.land);
  program.set(name + ".terrain.land_near", params.terrain.land_near);
  program.set(name + ".terrain.land_far", params.terrain.land_far);
  program.set(name + ".terrain.land_texels", params.terrain.land_texels);
  program.set(name + ".terrain.snow_line", params.terrain.snow_line);
  program.set(name + ".terrain.crop_stage", params.terrain.crop_stage);
  for (int i = 0; i < MAX_CONVECTIVE; ++i) {
    const ConvectiveParams& c = params.convective[i];
    const std::string cloud = name + ".convective[" + std::to_string(i) + "].";
    program.set(cloud + "centre", c.centre);
    program.set(cloud + "axis", c.axis);
    program.set(cloud + "bottom", c.bottom);
    program.set(cloud + "extent", c.extent);
    program.set(cloud + "cloud_base", c.cloud_base);
    program.set(cloud + "cloud_top", c.cloud_top);
    program.set(cloud + "extinction", c.extinction);
  }
  program.set(name + ".convective_count", params.convective_count);
}

}  // namespace nephele::glsl
