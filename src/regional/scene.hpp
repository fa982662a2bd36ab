#pragma once
// A scene: everything `nephele render` needs, from flags or from a JSON scene file.
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace nephele::regional {

// Bad scene input (exit code 2): names the file or flag, the key and the allowed values.
class SceneError : public core::InputError {
 public:
  using core::InputError::InputError;
};

struct Scene {
  std::string view = "gurten";              // named viewpoint, or "" when `at` is given
  std::optional<double> latitude_deg, longitude_deg, height_m;  // --at, overrides the viewpoint
  std::optional<double> heading_deg;        // default: the viewpoint's heading
  double pitch_deg = 5;
  double fov_deg = 70;
  std::string time = "2026-06-21T16:00Z";
  int width = 1280, height = 720;
  bool panorama = false;
  std::vector<std::string> weather;          // weather files (paths resolved against the scene file)
  std::uint32_t seed = 1;
  int view_steps = 48, light_steps = 12, sky_steps = 16;  // from the image-error sweep (docs/rendering.md)
  double exposure = 4.0;
  int cover_size = 128;                      // global cover size when no weather is given
  std::vector<std::string> outputs;          // file names (png, exr); --scene renders into --out DIR
};

// Reads a scene file; unknown keys and wrong types are errors naming the key.
Scene read_scene_file(const std::string& path);
Scene parse_scene(const std::string& json_text, const std::string& source_name, const std::string& base_directory);
// Which option set a scene key ("view" -> "--view"): errors about that key name the option the
// user typed instead of the key of a file they did not write. Keys: view, at, heading, pitch,
// fov, time, size, weather, view_steps, light_steps, exposure, seed.
using KeyOptions = std::map<std::string, std::string>;

// Checks ranges; throws SceneError naming the key ("SOURCE: 'key': ...") or, for the keys in
// `options`, the option ("--view: ...").
void validate_scene(const Scene& scene, const std::string& source_name, const KeyOptions& options = {});
// Parses "1280x720": decimal digits only on both sides, each 1 to max_image_side; throws
// SceneError starting with `name` (an option or "FILE: 'size'").
void parse_size(const std::string& text, int& width, int& height, const std::string& name);
constexpr int max_image_side = 16384;

}  // namespace nephele::regional
