#include "apps/viewer/view_state.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>

#include "core/time.hpp"
#include "cover/integrators.hpp"
#include "io/surface_files.hpp"
#include "regional/sites.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::viewer {

std::vector<Binding> bindings(ViewState& s) {
  namespace sc = params::scene;
  namespace co = params::cover;
  std::vector<Binding> out = render::field_bindings(s.camera);  // position, heading, pitch, fov
  out.insert(out.end(), {{&sc::view, &s.viewpoint},
                         {&sc::time, &s.time},
                         {&sc::view_steps, &s.view_steps},
                         {&sc::light_steps, &s.light_steps},
                         {&sc::shadow_map_size, &s.shadow_map_size},
                         {&sc::exposure, &s.exposure},
                         {&sc::seed, &s.seed},
                         {&sc::cover_size, &s.cover_size},
                         {&co::coverage, &s.coverage},
                         {&co::month, &s.month},
                         {&co::iterations, &s.iterations},
                         {&co::step, &s.step},
                         {&co::integrator, &s.integrator},
                         {&co::flow, &s.flow},
                         {&co::surface, &s.surface},
                         {&params::run::time_step, &s.time_step_hours}});
  return out;
}

bool option_only(const params::Parameter& p) {
  // --quality sets the steps the panels then show (regional::apply_render_quality).
  return &p == &params::scene::size || &p == &params::scene::scene_path || &p == &params::scene::quality ||
         &p == &params::run::view_record || &p == &params::run::view_frames || &p == &params::run::no_cache ||
         &p == &params::cloud_model::view_model || &p == &params::cloud_model::view_model_size ||
         &p == &params::cover::surface;  // a file, read and checked before the window opens
}

void go_to_viewpoint(ViewState& state, const std::string& name) {
  if (name == "orbit") {
    state.viewpoint = name;
    state.camera.height_m = params::scene::altitude_km.default_number * 1000.0;
    state.camera.pitch_deg = -90;
    return;
  }
  if (!regional::find_viewpoint(name)) return;
  // The viewpoint's place and heading; the pitch and fov stay the state's.
  regional::Scene scene = scene_of(state, state.camera.width, state.camera.height);
  scene.view = name;
  scene.latitude_deg = scene.longitude_deg = scene.height_m = scene.heading_deg = std::nullopt;
  state.viewpoint = name;
  state.camera = render::scene_camera(scene);
}

ViewState state_of_scene(const regional::Scene& scene) {
  ViewState state;
  // Time, seed, cover size, steps, shadow maps and exposure through the table's bindings of both structs;
  // the camera below (scene_camera, or the orbit viewpoint's) replaces the pitch and fov.
  regional::Scene source = scene;
  params::copy_bound_fields(regional::field_bindings(source), bindings(state));
  if (!scene.latitude_deg && scene.view == "orbit") {
    // Above the orbit view's default point (render --view orbit without --lat, --lon).
    regional::Scene ground = scene;
    ground.latitude_deg = params::scene::lat.default_number;
    ground.longitude_deg = params::scene::lon.default_number;
    ground.height_m = 0.0;
    state.camera = render::scene_camera(ground);
    go_to_viewpoint(state, "orbit");
  } else {
    state.viewpoint = scene.latitude_deg ? "" : scene.view;
    state.camera = render::scene_camera(scene);
  }
  state.weather = scene.weather;
  return state;
}

regional::Scene scene_of(const ViewState& state, int width, int height) {
  regional::Scene scene;
  scene.view.clear();
  scene.width = width;
  scene.height = height;
  scene.weather = state.weather;
  // Position, heading, pitch, fov, time, seed, steps, shadow maps, exposure, cover size through the table.
  ViewState source = state;
  params::copy_bound_fields(bindings(source), regional::field_bindings(scene));
  return scene;
}

cover::CoverParameters cover_of(const ViewState& state) {
  // The mask as nephele view read it at the start (io's store; "none" where etopo5 was missing).
  std::string unused_warning;
  cover::CoverParameters p = render::view_cover_parameters(state.cover_size, state.seed, state.flow, state.time,
                                                           io::surface_from_option(state.surface, &unused_warning));
  p.coverage = state.coverage;
  p.month = state.month;
  p.iterations = state.iterations;
  p.step = state.step;
  p.integrator = cover::parse_integrator(state.integrator).value_or(p.integrator);
  return p;
}

void advance_time(ViewState& state, double hours) {
  const double seconds = core::parse_utc_time(state.time) + hours * 3600.0;
  state.time = core::format_utc_seconds(std::max(seconds, 0.0));
}

void turn(ViewState& state, double heading_deg, double pitch_deg) {
  const double heading = std::fmod(state.camera.heading_deg + heading_deg, 360.0);
  state.camera.heading_deg = heading < 0 ? heading + 360.0 : heading;
  state.camera.pitch_deg =
      std::clamp(state.camera.pitch_deg + pitch_deg, params::scene::pitch.min, params::scene::pitch.max);
}

void drag(ViewState& state, double dx, double dy, int width) {
  const double degrees_per_pixel = state.camera.fov_deg / std::max(width, 1);
  turn(state, -dx * degrees_per_pixel, dy * degrees_per_pixel);
}

void zoom(ViewState& state, double notches) {
  state.camera.fov_deg = std::clamp(state.camera.fov_deg * std::pow(zoom_per_notch, notches), params::scene::fov.min,
                                    params::scene::fov.max);
}

double orbit_share(const ViewState& state) {
  const double top = params::scene::height.max;
  if (state.viewpoint == "orbit" || state.camera.height_m >= top) return 1.0;
  const double t = std::clamp((state.camera.height_m - orbit_fade_bottom_m) / (top - orbit_fade_bottom_m), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

bool shows_orbit(const ViewState& state) { return orbit_share(state) >= 1.0; }

double flight_step_m(const ViewState& state) { return std::max(50.0, 0.1 * std::abs(state.camera.height_m)); }

void fly(ViewState& state, double forward_m, double right_m, double up_m) {
  render::Camera& c = state.camera;
  const double heading = c.heading_deg * M_PI / 180.0;
  // East and north of the forward and right directions (heading clockwise from north).
  const double east = forward_m * std::sin(heading) + right_m * std::cos(heading);
  const double north = forward_m * std::cos(heading) - right_m * std::sin(heading);
  const GeographicLib::LocalCartesian frame(c.latitude_deg, c.longitude_deg, c.height_m);
  double latitude = 0, longitude = 0, height = 0;
  frame.Reverse(east, north, 0.0, latitude, longitude, height);
  c.latitude_deg = std::clamp(latitude, params::scene::latitude.min, params::scene::latitude.max);
  c.longitude_deg = longitude;
  // Level flight: the height stays as it was, whatever the curvature under the move. The range
  // is the viewer's whole one, ground to orbit: clamping to the ground views' ceiling would drop
  // a camera in orbit to 20 km at its first move.
  c.height_m = std::clamp(c.height_m + up_m, params::scene::height.min, params::scene::altitude_km.max * 1000.0);
  state.viewpoint.clear();
}

}  // namespace nephele::viewer
