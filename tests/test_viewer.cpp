// nephele view without a window: its panels against the parameter table, the camera's input
// rules, and the exit code without a display. The window itself: tests/viewer (under Xvfb).
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <set>

#include "apps/viewer/modeller.hpp"
#include "apps/viewer/panels.hpp"
#include "apps/viewer/view_source.hpp"
#include "apps/viewer/view_state.hpp"
#include "apps/viewer/viewer.hpp"
#include "cli_support.hpp"
#include "core/error.hpp"
#include "core/time.hpp"
#include "io/planet_textures.hpp"
#include "gl_support.hpp"
#include "params/field_binding.hpp"
#include "params/table.hpp"
#include "regional/sites.hpp"
#include "render/orbit_renderer.hpp"
#include "render/scene_renderer.hpp"

namespace nephele {

TEST_CASE("the viewer's panels offer every viewer parameter of the table that is not an option only, in table order",
          "[fast][viewer]") {
  viewer::ViewState state;
  const auto panel = viewer::panel_parameters();
  std::set<const params::Parameter*> bound;
  for (const auto& b : viewer::bindings(state)) bound.insert(b.parameter);
  std::size_t last = 0;
  for (const params::Parameter* p : panel) {
    INFO(p->key);
    CHECK(bound.count(p) == 1);  // a field to edit
    const auto& all = params::all();
    const std::size_t at = std::find(all.begin(), all.end(), p) - all.begin();
    CHECK(at >= last);
    last = at;
  }
  for (const params::Parameter* p : params::all())
    if (p->used_by(params::viewer)) {
      INFO(p->key);
      CHECK((viewer::option_only(*p) || std::count(panel.begin(), panel.end(), p) == 1));
    }
  // What the brief asks of the panels is there: the cover's and the view's parameters.
  for (const params::Parameter* p : {&params::scene::seed, &params::cover::coverage, &params::cover::iterations,
                                     &params::cover::integrator, &params::cover::step, &params::scene::time,
                                     &params::scene::heading, &params::scene::exposure, &params::scene::view_steps})
    CHECK(std::count(panel.begin(), panel.end(), p) == 1);
  // The integrator is a combo of the table's words.
  CHECK(params::cover::integrator.words() == std::vector<std::string>{"euler", "heun", "rk4", "geodesic", "adaptive"});
  CHECK(params::scene::time.words().empty());
}

TEST_CASE("a panel value is checked as the command line checks it", "[fast][viewer]") {
  viewer::ViewState state;
  viewer::set_value(state, params::cover::coverage, "0.25");
  CHECK(state.coverage == 0.25f);
  CHECK(viewer::value_text(state, params::cover::coverage) == "0.25");
  CHECK_THROWS_WITH(viewer::set_value(state, params::cover::coverage, "1.5"),
                    Catch::Contains("--coverage") && Catch::Contains("0 to 1"));
  CHECK_THROWS_AS(viewer::set_value(state, params::cover::integrator, "midpoint"), core::InputError);
  CHECK_THROWS_AS(viewer::set_value(state, params::scene::time, "2026-02-30T00:00Z"), core::InputError);
  CHECK(state.coverage == 0.25f);
  viewer::set_value(state, params::scene::view, "bantiger");
  CHECK(state.viewpoint == "bantiger");
}

TEST_CASE("a drag turns by the field of view per window width, and the wheel zooms within the table's range",
          "[fast][viewer]") {
  viewer::ViewState state;
  state.camera.heading_deg = 10;
  state.camera.pitch_deg = 0;
  state.camera.fov_deg = 60;
  viewer::drag(state, 40, -20, 240);  // 10 and 5 degrees
  CHECK(state.camera.heading_deg == Approx(0).epsilon(0).margin(1e-12));
  CHECK(state.camera.pitch_deg == Approx(-5).epsilon(0).margin(1e-12));
  viewer::drag(state, 40, 0, 240);
  CHECK(state.camera.heading_deg == Approx(350).epsilon(0).margin(1e-12));  // wrapped into [0, 360)
  viewer::drag(state, 0, 100000, 240);
  CHECK(state.camera.pitch_deg == params::scene::pitch.max);
  viewer::zoom(state, 1);
  CHECK(state.camera.fov_deg == Approx(60 * viewer::zoom_per_notch).epsilon(1e-15));
  viewer::zoom(state, -1000);
  CHECK(state.camera.fov_deg == params::scene::fov.max);
}

TEST_CASE("flight keeps the camera in double: a 50 m step at 46.9 degrees north moves the latitude by 4.5e-4 degrees",
          "[fast][viewer]") {
  viewer::ViewState state;
  state.camera.latitude_deg = 46.9;
  state.camera.longitude_deg = 7.44;
  state.camera.height_m = 0;
  state.camera.heading_deg = 0;
  CHECK(viewer::flight_step_m(state) == 50);
  viewer::fly(state, 50, 0, 0);
  // A degree of latitude is about 111.2 km here: 50 m is 4.497e-4 degrees; float would keep
  // only about 3e-6 degrees (0.3 m) at this latitude.
  CHECK(state.camera.latitude_deg - 46.9 == Approx(50.0 / 111180.0).epsilon(2e-3));
  CHECK(state.camera.longitude_deg == Approx(7.44).epsilon(0).margin(1e-12));
  CHECK(state.viewpoint.empty());
}

TEST_CASE("the key table gives each key one action per mode and the help lists every row it names", "[fast][viewer]") {
  using Mode = viewer::Viewer::KeyMode;
  const auto& table = viewer::Viewer::key_table();
  const std::string& help = viewer::key_help();
  for (const Mode mode : {Mode::view, Mode::modeller})
    for (const bool control : {false, true}) {
      std::set<int> seen;
      for (const auto& row : table) {
        if (row.control != control || (row.mode != mode && row.mode != Mode::both)) continue;
        for (int key : row.keys) {
          INFO("key " << key << " in mode " << int(mode));
          CHECK(seen.insert(key).second);  // one row answers it: dispatch is unambiguous
        }
      }
    }
  for (const auto& row : table) {
    // A row with keys acts; a row without is a gesture of the mouse callbacks, help only.
    CHECK((row.keys.empty() ? row.act == nullptr : row.act != nullptr));
    if (*row.label != '\0') {
      INFO(row.label);
      CHECK_THAT(help, Catch::Contains(std::string(row.label)) && Catch::Contains(std::string(row.help)));
    } else {
      CHECK_FALSE(row.keys.empty());  // the second half of the pair the row before names
    }
  }
}

TEST_CASE("nephele view without a display exits 3 and names xvfb-run and nephele render", "[viewer][cli]") {
  const auto r = test::run_with_environment("env -u DISPLAY -u WAYLAND_DISPLAY", "view --size 32x18");
  CHECK(r.exit_code == core::exit_environment);
  CHECK_THAT(r.output, Catch::Contains("xvfb-run -a nephele view") && Catch::Contains("nephele render"));
}

TEST_CASE("nephele view --help lists the keys and the table's options, and bad options exit 2 before a window opens",
          "[viewer][cli]") {
  const auto help = test::run("view --help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.output, Catch::Contains("F12") && Catch::Contains("PageUp") && Catch::Contains("--record"));
  const auto bad = test::run_with_environment("env -u DISPLAY", "view --coverage 2");
  CHECK(bad.exit_code == core::exit_bad_input);
  CHECK_THAT(bad.output, Catch::Contains("--coverage"));
}

TEST_CASE("nephele view --help lists the modeller's keys and options, and a bad --model exits 2 before a window opens",
          "[viewer][cli][modeller]") {
  const auto help = test::run("view --help");
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.output, Catch::Contains("--model VALUE") && Catch::Contains("--model-size VALUE") &&
                              Catch::Contains("Shift + scroll") && Catch::Contains("Ctrl+S"));
  const auto missing = test::run_with_environment("env -u DISPLAY", "view --model /nonexistent/m.cloud.json");
  CHECK(missing.exit_code == core::exit_bad_input);
  CHECK_THAT(missing.output, Catch::Contains("/nonexistent/m.cloud.json"));
  const auto both =
      test::run_with_environment("env -u DISPLAY", "view --model fair-weather --scene " +
                                                       std::string(NEPHELE_SOURCE_DIR) + "/scenes/bern-gurten.json");
  CHECK(both.exit_code == core::exit_bad_input);
  CHECK_THAT(both.output, Catch::Contains("--model"));
  const auto alone = test::run_with_environment("env -u DISPLAY", "view --model-size 64");
  CHECK(alone.exit_code == core::exit_bad_input);
  CHECK_THAT(alone.output, Catch::Contains("--model-size"));
}

TEST_CASE("modeller picking: a ray enters spheres and capsules where the geometry says, and the nearest is picked",
          "[fast][viewer][modeller]") {
  using viewer::entry_distance;
  // Inputs are floats (relative rounding 6e-8), the geometry double: 1e-7 on distances near 1.
  constexpr double kFloatInputs = 1e-7;
  const viewer::Ray along_x{glsl::vec3(0.0f), glsl::vec3(1, 0, 0)};
  model::Primitive sphere;
  sphere.from = sphere.to = glsl::vec3(1, 0, 0);
  sphere.radius = 0.25f;
  CHECK(entry_distance(sphere, along_x) == Approx(0.75).epsilon(0).margin(kFloatInputs));
  CHECK(entry_distance(sphere, {glsl::vec3(1.1f, 0, 0), glsl::vec3(1, 0, 0)}) == 0);  // from inside
  sphere.from = glsl::vec3(1, 0.3f, 0);
  CHECK(entry_distance(sphere, along_x) < 0);  // passes 0.3 from the centre
  sphere.from = glsl::vec3(-1, 0, 0);
  CHECK(entry_distance(sphere, along_x) < 0);  // behind
  // A capsule across the ray (y from -0.5 to 0.5 at x = 1): its side at 1 - R; past an end, the
  // end's sphere at 1 - sqrt(R^2 - 0.05^2); beyond the end's reach, nothing.
  model::Primitive capsule;
  capsule.segment = true;
  capsule.from = glsl::vec3(1, -0.5f, 0);
  capsule.to = glsl::vec3(1, 0.5f, 0);
  capsule.radius = 0.1f;
  CHECK(entry_distance(capsule, along_x) == Approx(0.9).epsilon(0).margin(kFloatInputs));
  CHECK(entry_distance(capsule, {glsl::vec3(0, 0.55f, 0), glsl::vec3(1, 0, 0)}) ==
        Approx(1 - std::sqrt(0.01 - 0.0025)).epsilon(0).margin(kFloatInputs));
  CHECK(entry_distance(capsule, {glsl::vec3(0, 0.65f, 0), glsl::vec3(1, 0, 0)}) < 0);
  // At 45 degrees in the plane across the axis: the axis at sqrt(2), the side R before it.
  capsule.from = glsl::vec3(1, -0.5f, 1);
  capsule.to = glsl::vec3(1, 0.5f, 1);
  const viewer::Ray diagonal{glsl::vec3(0.0f), glm::normalize(glsl::vec3(1, 0, 1))};
  CHECK(entry_distance(capsule, diagonal) == Approx(std::sqrt(2.0) - 0.1).epsilon(0).margin(kFloatInputs));
  // Picking: the nearer of two primitives on the ray, whatever their order; none off the ray.
  model::CloudModel m;
  model::Primitive near_one, far_one;
  near_one.from = glsl::vec3(0.5f, 0, 0);
  far_one.from = glsl::vec3(1.5f, 0, 0);
  m.primitives = {far_one, near_one};
  CHECK(viewer::pick_primitive(m, along_x) == 1);
  CHECK(viewer::pick_primitive(m, {glsl::vec3(0, 1, 0), glsl::vec3(1, 0, 0)}) == -1);
}

TEST_CASE("the modeller's volume follows an edit of the flat base and top, not only of the primitives",
          "[viewer][modeller][gpu]") {
  test::test_context();
  viewer::ViewState state = viewer::modeller_state(model::example("towering"));
  viewer::ModelSource source(24);
  source.render(state, 16, 16);
  const auto voxels_below = [&](float level) {
    const std::vector<float> v = source.volume()->read();
    int cloudy = 0;
    for (int z = 0; (z + 0.5f) / 24 < level; ++z)
      for (int k = 0; k < 24 * 24; ++k) cloudy += v[size_t(z) * 24 * 24 + size_t(k)] > 0.0f;
    return cloudy;
  };
  REQUIRE(voxels_below(0.4f) > 0);  // the towering cumulus's column starts at 0.18
  // Raising the base is a change of the whole model: the volume is computed again, and nothing
  // is left below the new base.
  state.model.base = 0.4f;
  const render::RenderResult raised = source.render(state, 16, 16);
  CHECK(std::any_of(raised.timings_ms.begin(), raised.timings_ms.end(),
                    [](const auto& t) { return t.first == "volume"; }));
  CHECK(source.volume()->model().base == 0.4f);
  CHECK(voxels_below(0.4f) == 0);
  state.model.top = 0.6f;
  source.render(state, 16, 16);
  CHECK(source.volume()->model().top == 0.6f);
}

TEST_CASE("the viewer's orbit view takes a coast window from GSHHG in low orbit, keeps it nearby and drops it high up",
          "[viewer][orbit][gpu]") {
  test::test_context();
  if (!std::filesystem::is_regular_file(io::gshhg_shorelines_default_path)) {
    WARN("no " << io::gshhg_shorelines_default_path << " (gmt-gshhg-full): skipped");
    return;
  }
  viewer::ViewState state;
  state.cover_size = 32;  // a small cover: the coasts are the point
  state.camera.latitude_deg = 46.95, state.camera.longitude_deg = 7.45;
  state.camera.height_m = 400e3, state.camera.pitch_deg = -90, state.camera.fov_deg = 60;
  const int width = 160, height = 90;  // nearest pixels 2.9 km: finer than a quarter of 37 km
  // From 12000 km first: the water map alone.
  viewer::OrbitSource source("", "");  // a generated cover, no disk cache
  state.camera.height_m = 12000e3;
  source.render(state, width, height);
  CHECK_FALSE(source.coast_window());
  state.camera.height_m = 400e3;
  const render::RenderResult after = source.render(state, width, height);
  REQUIRE(source.coast_window());
  CHECK(std::any_of(after.timings_ms.begin(), after.timings_ms.end(),
                    [](const auto& t) { return t.first == "coast_window"; }));
  const io::GeoWindow window = *source.coast_window();
  // It holds the window render --view orbit rasters for the same camera, a quarter larger each way.
  render::OrbitCamera camera;
  camera.latitude_deg = 46.95, camera.longitude_deg = 7.45, camera.altitude_m = 400e3;
  camera.pitch_deg = -90, camera.fov_deg = 60, camera.width = width, camera.height = height;
  const double radius = render::OrbitSettings{}.planet_radius_m;
  const std::optional<io::GeoWindow> wanted = io::view_coast_window(camera, radius, 1080);
  REQUIRE(wanted);
  CHECK(window.south_deg < wanted->south_deg);
  CHECK(window.north_deg > wanted->north_deg);
  CHECK(window.west_deg < wanted->west_deg);
  CHECK(window.east_deg > wanted->east_deg);
  CHECK(window.width <= 2048);
  CHECK(window.height <= 2048);
  // The frame is the renderer's with that window: a renderer given the same window in its planet
  // images draws it to the bit, and without the window the lakes in view (Geneva, Neuchatel,
  // Thun, Brienz ...) and the coasts differ.
  const io::PlanetTextures textures = io::read_planet_textures("");
  render::GlobalCoverFaces faces = render::make_global_cover(viewer::cover_of(state));
  render::OrbitRenderer plain(textures.images, {faces.size, std::move(faces.texels), std::move(faces.optical_thickness),
                                                std::move(faces.cloud_top)});
  const double time = core::parse_utc_time(state.time);
  const render::RenderResult without = plain.render(camera, time);
  plain.set_coast(io::read_gshhg_water(io::gshhg_shorelines_default_path, window), window.south_deg, window.north_deg,
                  window.west_deg, window.east_deg);
  const render::RenderResult with = plain.render(camera, time);
  CHECK(with.radiance.pixels == after.radiance.pixels);
  CHECK(without.radiance.pixels != after.radiance.pixels);
  // Half a degree east the window still serves: nothing is rastered.
  state.camera.longitude_deg += 0.5;
  const render::RenderResult east = source.render(state, width, height);
  CHECK(std::none_of(east.timings_ms.begin(), east.timings_ms.end(),
                     [](const auto& t) { return t.first == "coast_window"; }));
  CHECK(source.coast_window()->west_deg == window.west_deg);
  // From 3000 km the nearest pixels (21.7 km) want no window, being coarser than a quarter of the
  // water map's 37 km texel, but finer than the whole texel: the window is kept (the quarter-size
  // preview of a view that wants one keeps it for the full size).
  state.camera.height_m = 3000e3;
  const render::RenderResult mid = source.render(state, width, height);
  CHECK(source.coast_window());
  CHECK(std::none_of(mid.timings_ms.begin(), mid.timings_ms.end(),
                     [](const auto& t) { return t.first == "coast_window"; }));
  // From 12000 km (nearest pixels 87 km) the water map serves and the window is dropped.
  state.camera.height_m = 12000e3;
  source.render(state, width, height);
  CHECK_FALSE(source.coast_window());
}

TEST_CASE("modeller picking: project() puts a point where cursor_ray() looks back through it",
          "[fast][viewer][modeller]") {
  viewer::ViewState state = viewer::modeller_state(model::example("fair-weather"));
  state.camera.heading_deg = 30;
  state.camera.pitch_deg = 20;
  for (const glsl::vec3 point :
       {glsl::vec3(0.5f, 0.5f, 0.45f), glsl::vec3(0.1f, 0.8f, 0.9f), glsl::vec3(0.9f, 0.2f, 0.1f)}) {
    const glsl::vec3 at = viewer::project(state, point, 160, 90);
    REQUIRE(at.z > 0);
    const viewer::Ray ray = viewer::cursor_ray(state, at.x, at.y, 160, 90);
    // The point's distance from the ray: float pixel positions and directions (6e-8 relative)
    // over distances below 3.
    const glm::dvec3 r = glm::dvec3(point) - glm::dvec3(ray.origin), d = glm::normalize(glm::dvec3(ray.direction));
    CHECK(glm::length(r - glm::dot(r, d) * d) == Approx(0).epsilon(0).margin(1e-6));
  }
}

TEST_CASE(
    "the orbit viewpoint lifts the camera to the orbit view's altitude over the same point, and above the ground "
    "views' ceiling the orbit renderer shows",
    "[fast][viewer]") {
  viewer::ViewState state;
  viewer::go_to_viewpoint(state, "gurten");
  const double latitude = state.camera.latitude_deg, longitude = state.camera.longitude_deg;
  CHECK_FALSE(viewer::shows_orbit(state));
  viewer::go_to_viewpoint(state, "orbit");
  CHECK(viewer::shows_orbit(state));
  CHECK(state.camera.height_m == params::scene::altitude_km.default_number * 1000.0);
  CHECK(state.camera.pitch_deg == -90);
  CHECK(state.camera.latitude_deg == latitude);
  CHECK(state.camera.longitude_deg == longitude);
  // Flying clears the named viewpoint; the height alone then decides: the orbit renderer alone
  // from the scene's highest camera (20 km) up, the ground's alone up to 12 km, and a
  // smoothstep of the two between (orbit_share).
  viewer::fly(state, 0, 0, 0);
  CHECK(state.camera.height_m == params::scene::altitude_km.default_number * 1000.0);  // still in orbit
  CHECK(viewer::shows_orbit(state));
  state.camera.height_m = params::scene::height.max;
  CHECK(viewer::shows_orbit(state));
  CHECK(viewer::orbit_share(state) == 1.0);
  state.camera.height_m = params::scene::height.max - 1;
  CHECK_FALSE(viewer::shows_orbit(state));
  CHECK(viewer::orbit_share(state) > 0.99);
  state.camera.height_m = 16000;
  CHECK(viewer::orbit_share(state) == Approx(0.5).epsilon(0).margin(1e-12));
  state.camera.height_m = 14000;  // t = 1/4: 3/16 - 2/64 = 0.15625
  CHECK(viewer::orbit_share(state) == Approx(0.15625).epsilon(0).margin(1e-12));
  state.camera.height_m = viewer::orbit_fade_bottom_m;
  CHECK(viewer::orbit_share(state) == 0.0);
  // A scene that asks for the orbit view starts there (render --view orbit's default point).
  regional::Scene scene;
  scene.view = "orbit";
  const viewer::ViewState from_scene = viewer::state_of_scene(scene);
  CHECK(viewer::shows_orbit(from_scene));
  CHECK(from_scene.camera.latitude_deg == Approx(params::scene::lat.default_number).epsilon(0).margin(1e-9));
}

TEST_CASE("a scene's parameters reach the viewer's state and the renderer's settings through the table's bindings",
          "[fast][viewer]") {
  regional::Scene scene;
  scene.time = "2026-01-02T03:04Z";
  scene.seed = 77;
  scene.cover_size = 64;
  scene.view_steps = 9;
  scene.light_steps = 3;
  scene.exposure = 2.5;
  scene.pitch_deg = 12;
  scene.fov_deg = 33;
  scene.powder = 0.25;
  scene.resolution_divisor = 3;
  scene.cover_flow = "steady";
  const viewer::ViewState state = viewer::state_of_scene(scene);
  CHECK(state.time == scene.time);
  CHECK(state.flow == "steady");
  CHECK(state.seed == 77u);
  CHECK(state.cover_size == 64);
  CHECK(state.view_steps == 9);
  CHECK(state.light_steps == 3);
  CHECK(state.exposure == 2.5);
  const regional::Scene back = viewer::scene_of(state, 32, 18);
  CHECK(back.time == scene.time);
  CHECK(back.seed == 77u);
  CHECK(back.view_steps == 9);
  CHECK(back.pitch_deg == 12);
  CHECK(back.fov_deg == 33);
  CHECK(back.cover_flow == "steady");
  // The renderer's settings: numbers converted to their fields' types.
  const render::RenderSettings settings = render::render_settings(scene);
  CHECK(settings.view_steps == 9);
  CHECK(settings.powder == 0.25f);
  CHECK(settings.resolution_divisor == 3);
  CHECK(settings.seed == 77u);
  // A parameter bound to a text on one side and a number on the other is a programming error.
  std::string text = "x";
  double number = 1;
  CHECK_THROWS_AS(params::copy_bound_fields({{&params::scene::seed, &text}}, {{&params::scene::seed, &number}}),
                  std::logic_error);
  CHECK(params::copy_bound_fields({{&params::scene::fov, &number}}, {{&params::scene::pitch, &number}}) == 0);
}

TEST_CASE("a camera position given or left to the viewpoint moves between scene, camera and viewer state by the table",
          "[fast][viewer]") {
  // An empty optional is not copied (the viewpoint's value stays); a given one is.
  std::optional<double> left, given = 7.5;
  double field = 3;
  CHECK(params::copy_bound_fields({{&params::scene::height, &left}}, {{&params::scene::height, &field}}) == 0);
  CHECK(field == 3);
  CHECK(params::copy_bound_fields({{&params::scene::height, &given}}, {{&params::scene::height, &field}}) == 1);
  CHECK(field == 7.5);
  CHECK(params::copy_bound_fields({{&params::scene::height, &field}}, {{&params::scene::height, &left}}) == 1);
  CHECK(left == 7.5);

  // --at and --heading reach the camera; the viewer's state goes back to a scene with them.
  regional::Scene scene;
  scene.latitude_deg = 47.25;
  scene.longitude_deg = 7.5;
  scene.height_m = 1200;
  scene.heading_deg = 135;
  scene.pitch_deg = 4;
  const render::Camera camera = render::scene_camera(scene);
  CHECK(camera.latitude_deg == 47.25);
  CHECK(camera.longitude_deg == 7.5);
  CHECK(camera.height_m == 1200);
  CHECK(camera.heading_deg == 135);
  CHECK(camera.pitch_deg == 4);
  const regional::Scene back = viewer::scene_of(viewer::state_of_scene(scene), 32, 18);
  CHECK(back.latitude_deg == scene.latitude_deg);
  CHECK(back.longitude_deg == scene.longitude_deg);
  CHECK(back.height_m == scene.height_m);
  CHECK(back.heading_deg == scene.heading_deg);

  // Choosing a viewpoint moves the camera to its summit and heading and keeps the pitch and fov.
  viewer::ViewState state = viewer::state_of_scene(scene);
  state.camera.fov_deg = 41;
  viewer::go_to_viewpoint(state, "bantiger");
  const auto bantiger = regional::find_viewpoint("bantiger");
  REQUIRE(bantiger);
  CHECK(state.camera.latitude_deg == bantiger->site.latitude_deg);
  CHECK(state.camera.height_m == bantiger->site.elevation_m + 2.0);
  CHECK(state.camera.heading_deg == bantiger->heading_deg);
  CHECK(state.camera.pitch_deg == 4);
  CHECK(state.camera.fov_deg == 41);

  // The orbit camera takes the point below it, heading, pitch and fov from the camera by the
  // same parameters (its altitude is the caller's conversion).
  render::OrbitCamera orbit;
  params::copy_bound_fields(render::field_bindings(state.camera), render::field_bindings(orbit));
  CHECK(orbit.latitude_deg == state.camera.latitude_deg);
  CHECK(orbit.longitude_deg == state.camera.longitude_deg);
  CHECK(orbit.heading_deg == state.camera.heading_deg);
  CHECK(orbit.pitch_deg == 4);
  CHECK(orbit.fov_deg == 41);
}

TEST_CASE("the viewer's time moves by whole steps, and its cover is that of its flow at its time", "[fast][viewer]") {
  viewer::ViewState state;
  state.time = "2026-06-21T16:00Z";
  CHECK(state.flow == std::string(params::cover::flow.default_text));
  cover::CoverParameters p = viewer::cover_of(state);
  CHECK(p.flow == cover::Flow::moving);
  CHECK(p.time == state.time);
  viewer::advance_time(state, 1.5);
  CHECK(state.time == "2026-06-21T17:30:00Z");
  CHECK(viewer::cover_of(state).time == state.time);
  viewer::advance_time(state, -48);
  CHECK(state.time == "2026-06-19T17:30:00Z");
  // Before 1970 the clock stops at its start rather than wrapping.
  viewer::advance_time(state, -1e9);
  CHECK(state.time == "1970-01-01T00:00:00Z");
  state.flow = "steady";
  CHECK(viewer::cover_of(state).flow == cover::Flow::steady);
}

}  // namespace nephele
