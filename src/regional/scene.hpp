#pragma once
// A scene: everything `nephele render` needs, from flags or from a JSON scene file.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "params/field_binding.hpp"
#include "params/table.hpp"

namespace nephele::regional {

// Bad scene input (exit code 2): names the file or flag, the key and the allowed values.
class SceneError : public core::InputError {
 public:
  using core::InputError::InputError;
};

// Defaults and ranges come from the parameter table (src/params/table.hpp, namespace scene).
struct Scene {
  std::string view{params::scene::view.default_text};           // named viewpoint, or "" when `at` is given
  std::optional<double> latitude_deg, longitude_deg, height_m;  // --at, overrides the viewpoint
  std::optional<double> heading_deg;                            // default: the viewpoint's heading
  double pitch_deg = params::scene::pitch.default_number;
  double fov_deg = params::scene::fov.default_number;
  std::string time{params::scene::time.default_text};
  int width = params::size_part(params::scene::size.default_text, false);
  int height = params::size_part(params::scene::size.default_text, true);
  bool panorama = false;             // set with make_panorama
  std::vector<std::string> weather;  // weather files (paths resolved against the scene file)
  std::uint32_t seed = params::scene::seed.default_uint32();
  // The render quality (params/render_quality.hpp) and the step settings given by name (scene
  // keys or options: "view_steps", "light_steps", "frames", "resolution_divisor"), which it
  // leaves alone. The four fields below start as the final quality's (the library's exact
  // render); apply_render_quality sets the others from `quality`, as `render`, scene files and
  // the viewer do.
  std::string quality{params::scene::quality.default_text};
  std::set<std::string> steps_given;
  // Step counts from the image-error sweep (docs/rendering.md).
  int view_steps = params::scene::view_steps.default_int();
  int light_steps = params::scene::light_steps.default_int();
  int sky_steps = params::scene::sky_steps.default_int();
  double powder = params::scene::powder.default_number;  // strength of the powder term, 0: none
  int shadow_map_size = params::scene::shadow_map_size.default_int();
  int frames = params::scene::frames.default_int();
  int resolution_divisor = params::scene::resolution_divisor.default_int();
  std::string terrain{params::scene::terrain.default_text};              // etopo5, flat or an ETOPO5 file
  std::string land_cover{params::scene::land_cover.default_text};        // swiss-maps, none or a TopoJSON file
  double terrain_detail = params::scene::terrain_detail.default_number;  // fractal relief's strength
  double fog_top_m = params::scene::fog_top.default_number;              // sea of fog's top, m above sea level
  double exposure = params::scene::exposure.default_number;
  int cover_size = params::scene::cover_size.default_int();  // global cover size when no weather is given
  // The global cover's flow (cover/flow_kind.hpp); a moving cover is that of `time`.
  std::string cover_flow{params::cover::flow.default_text};
  // Its land/ocean mask (--surface: none, etopo5 or a file), loaded by the caller (io).
  std::string cover_surface{params::cover::surface.default_text};
  std::vector<std::string> outputs;  // file names (png, exr); --scene renders into --out DIR
};

// The fields of `scene` that hold one parameter of the table each (not the view, whose meaning
// depends on the optional position; the position and heading copy from only where given): what
// copies between a scene and the structs made from it go through (params::copy_bound_fields).
std::vector<params::FieldBinding> field_bindings(Scene& scene);

// Scene files are read by src/io/scene_files.hpp.
// Which option set a scene key ("view" -> "--view"): errors about that key name the option the
// user typed instead of the key of a file they did not write. Keys: view, at, heading, pitch,
// fov, time, size, weather, view_steps, light_steps, frames, exposure, seed.
using KeyOptions = std::map<std::string, std::string>;

// A panorama's image when no size is given: the whole 360 x 180 degree view sphere as a 2:1
// equirect, 2048 x 1024 (the table's `size` help says so).
inline constexpr int panorama_width = 2048, panorama_height = 1024;
// Turns `s` into a panorama, at panorama_width x panorama_height unless its size was given.
void make_panorama(Scene& s, bool size_given);

// Checks ranges; throws SceneError naming the key ("SOURCE: 'key': ...") or, for the keys in
// `options`, the option ("--view: ...").
void validate_scene(const Scene& scene, const std::string& source_name, const KeyOptions& options = {});
// Sets the step settings that `steps_given` does not name from the quality `scene.quality`
// (params::render_qualities); throws SceneError naming `source_name` (or --quality when the
// option chose it) for an unknown quality.
void apply_render_quality(Scene& scene, const std::string& source_name, const KeyOptions& options = {});
// Sets step setting `step` (one of quality_step_keys' parameters) to `value` as given by name:
// the field through field_bindings and the key into steps_given, so that the quality leaves it.
void give_step(Scene& scene, const params::Parameter& step, int value);
// The four step keys that a quality sets, in the order sidecars list them.
const std::vector<std::string>& quality_step_keys();
// Parses "1280x720": decimal digits only on both sides, each 1 to max_image_side; throws
// SceneError starting with `name` (an option or "FILE: 'size'").
void parse_size(const std::string& text, int& width, int& height, const std::string& name);
constexpr int max_image_side = 16384;
// The most weather files of one scene (the key "weather" and --weather together): each is read
// and interpolated for every pixel's column; a scene naming one file 200000 times ran for
// minutes. Two stations bracket a view; 64 leave room for a region (docs/formats.md).
constexpr std::size_t max_weather_files = 64;

}  // namespace nephele::regional
