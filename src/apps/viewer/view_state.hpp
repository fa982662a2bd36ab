#pragma once
// What the viewer shows: the camera (double precision on the CPU) and the values of the
// parameters its panels offer, each field tied to its declaration in the parameter table
// (src/params/table.hpp), so that panels, tooltips and ranges come from the table. No GL here:
// the tests drive it directly.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "model/cloud_model.hpp"
#include "params/field_binding.hpp"
#include "params/table.hpp"
#include "regional/scene.hpp"
#include "render/cloud_renderer.hpp"

namespace nephele::viewer {

struct ViewState {
  render::Camera camera;  // position, heading, pitch, fov; width and height are set per render
  std::string viewpoint{params::scene::view.default_text};  // choosing one moves the camera there
  std::string time{params::scene::time.default_text};
  std::uint32_t seed = params::scene::seed.default_uint32();
  int cover_size = params::scene::cover_size.default_int();
  int view_steps = params::scene::view_steps.default_int();
  int light_steps = params::scene::light_steps.default_int();
  int shadow_map_size = params::scene::shadow_map_size.default_int();  // the scene's; a panel changes it
  double exposure = params::scene::exposure.default_number;
  float coverage = params::cover::coverage.default_float();
  int month = params::cover::month.default_int();  // the Earth profile's season (0: annual mean)
  int iterations = params::cover::iterations.default_int();
  float step = params::cover::step.default_float();
  std::string integrator{params::cover::integrator.default_text};
  std::string flow{params::cover::flow.default_text};              // moving: the cover of `time`
  std::string surface{params::cover::surface.default_text};        // the cover's land/ocean mask (--surface)
  double time_step_hours = params::run::time_step.default_number;  // the time keys' and playback's step
  bool playing = false;                                            // T: the time moves by time_step_hours each frame
  std::vector<std::string> weather;  // station files of --scene (the global cover when empty)
  // nephele view --model: the cloud model being edited, shown by ModelSource (the camera's
  // heading, pitch and field of view turn the orbit around it; its position is not used).
  bool modeller = false;
  model::CloudModel model;
  int selected = -1;  // the primitive selected in the modeller, -1 for none
};

// A field of ViewState and the parameter that declares it (params/field_binding.hpp).
using FieldPointer = params::FieldPointer;
using Binding = params::FieldBinding;
// The fields of `state` that panels edit, by parameter.
std::vector<Binding> bindings(ViewState& state);
// The parameters of the table that nephele view takes only as options, not in a panel.
bool option_only(const params::Parameter& p);

// The state of a scene (flags or --scene FILE): its viewpoint or position, view, time, steps.
ViewState state_of_scene(const regional::Scene& scene);
// Moves the camera to a named viewpoint (eye 2 m above the summit, the view's heading); "orbit"
// lifts it to the orbit view's default altitude above the point where it is, looking down.
void go_to_viewpoint(ViewState& state, const std::string& name);
// The orbit renderer's share of the view: 1 where the orbit viewpoint is chosen or the camera
// is at or above the ground views' highest camera (the scene's height range, 20 km), 0 at or
// below orbit_fade_bottom_m, and a smoothstep between, where the window shows the two
// renderers' radiance mixed (a cross-fade, no visible switch; ViewSwitch).
double orbit_share(const ViewState& state);
// 12 km: above the regional cirrus (tops up to 10.5 km, docs/layers.md), so that the ground
// view has left its stratiform layers before the global shell fades in.
constexpr double orbit_fade_bottom_m = 12000.0;
// Whether the orbit renderer alone shows the state (orbit_share 1).
bool shows_orbit(const ViewState& state);
// The scene and cover of a render of `state` at width x height.
regional::Scene scene_of(const ViewState& state, int width, int height);
cover::CoverParameters cover_of(const ViewState& state);

// Moves the time by `hours` (the sun and, with the moving flow, the clouds); times before 1970
// stay at 1970-01-01T00:00Z.
void advance_time(ViewState& state, double hours);

// Inputs. A drag of (dx, dy) pixels in a window `width` pixels wide turns the view so that the
// scene follows the cursor: heading -= dx fov / width, pitch += dy fov / width (pitch kept in
// its table range, heading wrapped into [0, 360)).
void drag(ViewState& state, double dx, double dy, int width);
// Turns the camera by these angles (degrees): the pitch kept in its table range, the heading
// wrapped into [0, 360). The ground's drag and the modeller's orbit both turn through it.
void turn(ViewState& state, double heading_deg, double pitch_deg);
// Scroll: each notch up narrows the field of view by `zoom_per_notch` (within the table's range).
constexpr double zoom_per_notch = 0.9;
void zoom(ViewState& state, double notches);
// Flight: metres along the heading (forward), to its right, and up; the position is moved on
// the WGS84 ellipsoid in double (GeographicLib's local frame at the camera).
void fly(ViewState& state, double forward_m, double right_m, double up_m);
// The distance one key press flies: a tenth of the height above sea level, at least 50 m.
double flight_step_m(const ViewState& state);

}  // namespace nephele::viewer
