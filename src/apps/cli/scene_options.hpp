#pragma once
// The scene options that nephele render and nephele view share: bound once, and applied over the
// scene file (--scene) only where they were given.
#include <cstdint>
#include <string>

#include "apps/cli/options.hpp"
#include "regional/scene.hpp"

namespace nephele::cli {

class SceneOptions {
 public:
  // Binds --scene, --view, --heading, --pitch, --fov, --time, --size, --quality, --view-steps,
  // --light-steps, --exposure, --seed, --flow and --surface to `options` (whose command must take them).
  explicit SceneOptions(Options& options);
  // After options.parse: the scene file's scene (or the defaults) with each given option over
  // it, the step settings not given by name from the quality (regional::apply_render_quality).
  // `typed` records the keys an option set, so that their errors name the option.
  regional::Scene scene(regional::KeyOptions& typed) const;
  const std::string& scene_file() const { return scene_file_; }
  bool size_given() const { return !size_.empty(); }
  // The raw option values, for views that are not a regional scene (render --view orbit).
  const std::string& view() const { return view_; }
  const std::string& time() const { return time_; }
  const std::string& flow() const { return flow_; }        // empty unless given
  const std::string& surface() const { return surface_; }  // empty unless given
  const std::string& size() const { return size_; }
  double heading() const { return heading_; }
  double pitch() const { return pitch_; }
  double fov() const { return fov_; }
  double exposure() const { return exposure_; }
  std::uint32_t seed() const { return seed_; }

 private:
  const Options& options_;
  regional::Scene defaults_;
  std::string scene_file_, view_, time_, size_, quality_, flow_, surface_;
  double heading_ = 0, pitch_, fov_, exposure_;
  int view_steps_, light_steps_;
  std::uint32_t seed_;
};

}  // namespace nephele::cli
