#include "params/table.hpp"

namespace nephele::params {

const std::vector<const Parameter*>& all() {
  static const std::vector<const Parameter*> parameters = {
      &cover::size, &cover::seed, &cover::iterations, &cover::step, &cover::coverage, &cover::profile, &cover::month,
      &cover::curl_frequency, &cover::curl_octaves, &cover::curl_lacunarity, &cover::curl_gain,
      &cover::prevailing, &cover::mix_frequency, &cover::curl_strength, &cover::curl_smoothing, &cover::zonal_cells, &cover::storm_tracks, &cover::cyclone_cloudiness,
      &cover::density_frequency,
      &cover::density_octaves, &cover::density_lacunarity, &cover::density_gain, &cover::surface, &cover::surface_weight, &cover::integrator,
      &cover::curl_mode, &cover::tolerance, &cover::max_substeps, &cover::noise_offset,
      &scene::view, &scene::at, &scene::latitude, &scene::longitude, &scene::height, &scene::heading,
      &scene::pitch, &scene::fov, &scene::time, &scene::size, &scene::panorama, &scene::weather,
      &scene::quality, &scene::view_steps, &scene::light_steps, &scene::frames, &scene::resolution_divisor, &scene::sky_steps, &scene::powder, &scene::shadow_map_size, &scene::exposure, &scene::seed,
      &scene::cover_size, &scene::outputs, &scene::description, &scene::scene_path, &scene::out,
      &scene::lat, &scene::lon, &scene::altitude_km, &scene::cover, &scene::earth_texture, &scene::night_texture,
      &scene::planet_radius_km, &scene::cloud_base_km, &scene::cloud_thickness_km,
      &noise_texture::preset, &noise_texture::type, &noise_texture::width, &noise_texture::height,
      &noise_texture::depth, &noise_texture::size, &noise_texture::cells, &noise_texture::octaves,
      &noise_texture::lacunarity, &noise_texture::gain, &noise_texture::worley_cells,
      &noise_texture::worley_octaves, &noise_texture::channels, &noise_texture::r, &noise_texture::g,
      &noise_texture::b, &noise_texture::a, &noise_texture::seed, &noise_texture::bits, &noise_texture::out,
      &noise_texture::stretch,
      &cloud_model::example, &cloud_model::scene_path, &cloud_model::size, &cloud_model::out, &cloud_model::blend, &cloud_model::scale, &cloud_model::extent,
      &cloud_model::description, &cloud_model::preview, &cloud_model::no_preview, &cloud_model::kind, &cloud_model::coordinate, &cloud_model::radius, &cloud_model::influence, &cloud_model::weight,
      &cloud_model::octaves, &cloud_model::frequency, &cloud_model::amplitude, &cloud_model::gain, &cloud_model::lacunarity, &cloud_model::fraction,
      &cloud_model::seed,
      &run::cover_out, &run::cover_files, &run::precision, &run::exr_compression, &run::stats_out, &run::report_out, &run::quiet, &run::no_cache, &run::verbose, &run::bench_cover_sizes, &run::bench_cover_repeat,
      &run::bench_noise_size, &run::bench_noise_repeat, &run::bench_render_size, &run::bench_render_sweep_size,
      &run::bench_render_repeat, &run::bench_render_no_sweep, &run::report_quick, &run::report_sizes,
      &run::report_steps, &run::report_tolerances, &run::report_samples, &run::report_repeat,
      &run::bench_model_repeat, &run::report_render_size, &run::report_no_render, &run::report_budget_ms,
      &run::view_record, &run::view_frames, &run::bench_view_size, &run::bench_view_repeat,
  };
  return parameters;
}

}  // namespace nephele::params
