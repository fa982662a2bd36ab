#include "apps/cli/scene_options.hpp"

#include "io/scene_files.hpp"
#include "params/table.hpp"

namespace nephele::cli {

SceneOptions::SceneOptions(Options& options)
    : options_(options),
      pitch_(defaults_.pitch_deg),
      fov_(defaults_.fov_deg),
      exposure_(defaults_.exposure),
      view_steps_(defaults_.view_steps),
      light_steps_(defaults_.light_steps),
      seed_(defaults_.seed) {
  namespace s = params::scene;
  options.bind(s::scene_path, &scene_file_);
  options.bind(s::view, &view_);
  options.bind(s::heading, &heading_);
  options.bind(s::pitch, &pitch_);
  options.bind(s::fov, &fov_);
  options.bind(s::time, &time_);
  options.bind(s::size, &size_);
  options.bind(s::quality, &quality_);
  options.bind(s::view_steps, &view_steps_);
  options.bind(s::light_steps, &light_steps_);
  options.bind(s::exposure, &exposure_);
  options.bind(s::seed, &seed_);
  options.bind(params::cover::flow, &flow_);
  options.bind(params::cover::surface, &surface_);
}

regional::Scene SceneOptions::scene(regional::KeyOptions& typed) const {
  namespace s = params::scene;
  regional::Scene scene = scene_file_.empty() ? defaults_ : io::read_scene_file(scene_file_);
  if (!view_.empty()) {
    scene.view = view_;
    scene.latitude_deg.reset();
    typed["view"] = "--view";
  }
  if (options_.given(s::heading)) {
    scene.heading_deg = heading_;
    typed["heading"] = "--heading";
  }
  if (options_.given(s::pitch)) scene.pitch_deg = pitch_;
  if (options_.given(s::fov)) scene.fov_deg = fov_;
  if (options_.given(s::exposure)) scene.exposure = exposure_;
  if (options_.given(s::quality)) {
    scene.quality = quality_;
    typed["quality"] = "--quality";
  }
  if (options_.given(s::view_steps)) regional::give_step(scene, s::view_steps, view_steps_);
  if (options_.given(s::light_steps)) regional::give_step(scene, s::light_steps, light_steps_);
  if (options_.given(s::seed)) scene.seed = seed_;
  if (!flow_.empty()) {
    scene.cover_flow = flow_;
    typed["flow"] = "--flow";
  }
  if (!surface_.empty()) {
    scene.cover_surface = surface_;
    typed["surface"] = "--surface";
  }
  if (!time_.empty()) {
    scene.time = time_;
    typed["time"] = "--time";
  }
  if (!size_.empty()) {
    regional::parse_size(size_, scene.width, scene.height, "--size");
    typed["size"] = "--size";
  }
  regional::apply_render_quality(scene, scene_file_.empty() ? "flags" : scene_file_, typed);
  return scene;
}

}  // namespace nephele::cli
