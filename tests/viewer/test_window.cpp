// nephele view's window, driven as a person would (through its GLFW callbacks) and read back
// from its framebuffer. Needs an X display: ctest runs this executable under xvfb-run -a.
#include <catch2/catch.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <GeographicLib/Geocentric.hpp>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "apps/viewer/panels.hpp"
#include "apps/viewer/view_source.hpp"
#include "apps/viewer/viewer.hpp"
#include "cli_support.hpp"
#include "core/time.hpp"
#include "files/image_files.hpp"
#include "regional/sites.hpp"
#include "render/cloud_renderer.hpp"
#include "tolerances.hpp"

namespace nephele {
namespace {

using viewer::Viewer;

// A small, cheap view: 64x36 pixels, few steps, a small cover.
constexpr int kWidth = 64, kHeight = 36;
const char* const kAt = "46.9191,7.4397,1000";  // above the Gurten

viewer::ViewerOptions small_view() {
  viewer::ViewerOptions options;
  regional::Scene& scene = options.scene;
  scene.view.clear();
  scene.latitude_deg = 46.9191;
  scene.longitude_deg = 7.4397;
  scene.height_m = 1000;
  scene.heading_deg = 300;
  scene.pitch_deg = 8;
  scene.fov_deg = 70;
  // Morning in Bern (08:30 solar time): no afternoon convection to build volumes for, which the
  // tests here do not need (docs/convection.md).
  scene.time = "2026-06-21T08:00Z";
  scene.width = kWidth;
  scene.height = kHeight;
  scene.view_steps = 8;
  scene.light_steps = 2;
  // Shadow maps of 64^2 (the scene's 512^2 were most of each render's time); no test here looks
  // at shadows, and the one that compares with `nephele render` keeps the default.
  scene.shadow_map_size = 64;
  return options;
}

// The same with a cover of 32 texels per face, for tests that do not compare with a render of
// the default scene (a moving cover of 128 takes about 0.2 s on llvmpipe, one of 32 a tenth).
viewer::ViewerOptions small_cover_view() {
  viewer::ViewerOptions options = small_view();
  options.scene.cover_size = 32;
  return options;
}

// Frames until the full-size render of the current state is shown (at most `limit`).
int refine(Viewer& v, int limit = 20) {
  int frames = 0;
  do {
    v.frame();
    ++frames;
  } while (!v.refined() && frames < limit);
  return frames;
}

double largest_difference(const core::ImageData& a, const core::ImageData& b) {
  REQUIRE(a.width == b.width);
  REQUIRE(a.height == b.height);
  REQUIRE(a.channels == b.channels);
  double largest = 0;
  for (std::size_t k = 0; k < a.pixels.size(); ++k)
    largest = std::max(largest, double(std::abs(a.pixels[k] - b.pixels[k])));
  return largest;
}

}  // namespace

TEST_CASE("the window shows the image nephele render makes headless of the same view, to one 8-bit step", "[window]") {
  viewer::ViewerOptions options = small_view();
  options.scene.shadow_map_size = params::scene::shadow_map_size.default_int();  // render's
  Viewer v(options);
  v.set_panels_visible(false);
  v.set_capture(true);
  const int frames = refine(v);
  // A quarter, a half, then the full size in eight bands: ten renders, one per frame.
  CHECK(frames == 10);
  CHECK(v.renders() == 10);
  const core::ImageData& shown = v.last_frame();
  REQUIRE(shown.width == kWidth);
  REQUIRE(shown.height == kHeight);

  test::TemporaryDirectory out(true);
  const auto exr = out.path / "view.exr";
  const auto r =
      test::run(std::string("render --at ") + kAt + " --heading 300 --pitch 8 --fov 70 --time 2026-06-21T08:00Z " +
                "--size 64x36 --quality final --view-steps 8 --light-steps 2 --quiet --out " + exr.string());
  REQUIRE(r.exit_code == 0);
  const core::ImageData radiance = files::read_image(exr);
  // The same passes on the same driver in the window's context and the headless one, the full
  // size assembled from bands: the same radiance to the bit.
  CHECK(largest_difference(v.shown_radiance(), radiance) == 0);
  const core::ImageData headless = render::tone_map(radiance, v.state().exposure);
  CHECK(largest_difference(shown, headless) == Approx(0).epsilon(0).margin(test::kEightBitDisplay));
  // The test sees something: the sky is not black.
  double sum = 0;
  for (float p : shown.pixels) sum += p;
  CHECK(sum / shown.pixels.size() > 0.1);
}

TEST_CASE("in orbit the window shows the image render --view orbit makes headless of the same camera",
          "[window][orbit]") {
  Viewer v(small_view());
  v.set_panels_visible(false);
  viewer::go_to_viewpoint(v.state(), "orbit");
  v.state().camera.fov_deg = 60;
  CHECK(viewer::shows_orbit(v.state()));
  refine(v);
  test::TemporaryDirectory out(true);
  const auto exr = out.path / "orbit.exr";
  const auto r = test::run(
      "render --view orbit --lat 46.9191 --lon 7.4397 --altitude-km 2000 --heading 300 --pitch -90 "
      "--fov 60 --time 2026-06-21T08:00Z --size 64x36 --quiet --out " +
      exr.string());
  REQUIRE(r.exit_code == 0);
  const core::ImageData radiance = files::read_image(exr);
  // The same renderer, cover (made from the same default parameters and seed) and camera in the
  // window's context and the headless one: the same radiance to the bit.
  CHECK(largest_difference(v.shown_radiance(), radiance) == 0);
  // The planet is there: the disc's centre is lit at 16:00 UTC over Bern (sun up).
  double sum = 0;
  for (float p : v.shown_radiance().pixels) sum += p;
  CHECK(sum > 0);
}

TEST_CASE("between 12 and 20 km the view cross-fades from the ground renderer to the orbit's, without a step",
          "[window][orbit]") {
  Viewer v(small_cover_view());  // for its GL context and its state
  viewer::go_to_viewpoint(v.state(), "orbit");
  viewer::fly(v.state(), 0, 0, 0);  // flying clears the viewpoint: the height decides
  viewer::ViewState state = v.state();
  // Fewer clouds to march: the continuity does not depend on them, the run time does.
  viewer::set_value(state, params::cover::coverage, "0.3");
  viewer::ViewSwitch view("", "");
  viewer::GroundSource ground("", "");
  viewer::OrbitSource orbit("", "");
  auto mean_luminance = [](const core::ImageData& image) {
    double sum = 0;
    for (std::size_t k = 0; k + 3 < image.pixels.size(); k += 4)
      sum += 0.2126 * image.pixels[k] + 0.7152 * image.pixels[k + 1] + 0.0722 * image.pixels[k + 2];
    return sum / (image.width * image.height);
  };
  // The mix at 16 km (share 1/2 by the smoothstep): half of each renderer's radiance, to the
  // rounding of (1 - s) g + s o, exact in double, to float (half an ulp; one allowed).
  state.camera.height_m = 16000;
  REQUIRE(viewer::orbit_share(state) == Approx(0.5).epsilon(0).margin(1e-12));
  const auto g = ground.render(state, kWidth, kHeight), o = orbit.render(state, kWidth, kHeight);
  const auto mixed = view.render(state, kWidth, kHeight);
  int off = 0;
  for (std::size_t k = 0; k < mixed.radiance.pixels.size(); ++k) {
    const double expected = 0.5 * g.radiance.pixels[k] + 0.5 * o.radiance.pixels[k];
    off += std::abs(mixed.radiance.pixels[k] - expected) > test::kUlp * (std::abs(expected) + 1e-30);
  }
  CHECK(off == 0);
  auto mean_opacity = [](const core::ImageData& image) {
    double sum = 0;
    for (std::size_t k = 3; k < image.pixels.size(); k += 4) sum += image.pixels[k];
    return sum / (image.width * image.height);
  };
  // The same cloud from both at the fade's middle: the share of the view that cloud hides (the
  // mean opacity) agrees within 0.05 (issue 31's tolerance for "the same cloud": a fifth of the
  // 0.23 seen here when it was set, 0.14-0.18 now; both take the cloud from the same cover, the ground renderer through
  // its layers, the orbit renderer through the slabs and the sub-texel cloud). Their brightness differs by the ground's
  // maps and the clouds' light models (docs/viewer.md: mean luminance 0.067 and 0.048 here).
  INFO("at 16 km: ground renderer luminance " << mean_luminance(g.radiance) << ", opacity " << mean_opacity(g.radiance)
                                              << "; orbit renderer " << mean_luminance(o.radiance) << ", "
                                              << mean_opacity(o.radiance));
  CHECK(std::abs(mean_opacity(g.radiance) - mean_opacity(o.radiance)) < 0.05);
  // Outside the band one renderer alone.
  state.camera.height_m = 20000;
  CHECK(largest_difference(view.render(state, kWidth, kHeight).radiance,
                           orbit.render(state, kWidth, kHeight).radiance) == 0);
  state.camera.height_m = 12000;
  CHECK(largest_difference(view.render(state, kWidth, kHeight).radiance,
                           ground.render(state, kWidth, kHeight).radiance) == 0);
  // A descent from 24 to 8 km in steps of 1 km (the fade band of 8 km sampled 9 times): the mean
  // luminance changes by no step larger than three times the larger of its neighbours (issue
  // 11's test of the descent), above a floor of 0.2 % of the mean.
  std::vector<double> series;
  for (double height = 24000; height >= 8000; height -= 1000) {
    state.camera.height_m = height;
    series.push_back(mean_luminance(view.render(state, kWidth, kHeight).radiance));
  }
  double mean = 0;
  for (double y : series) mean += y / series.size();
  auto jumps = [&](const std::vector<double>& values) {
    std::vector<double> steps;
    for (std::size_t k = 1; k < values.size(); ++k) steps.push_back(std::abs(values[k] - values[k - 1]));
    int count = 0;
    for (std::size_t k = 1; k + 1 < steps.size(); ++k)
      count += steps[k] > std::max(3 * std::max(steps[k - 1], steps[k + 1]), 0.002 * mean);
    return count;
  };
  INFO("mean luminance from 24 to 8 km: " << [&] {
    std::string text;
    for (double y : series) text += std::to_string(y) + " ";
    return text;
  }());
  CHECK(jumps(series) == 0);
  // The check has teeth: the switch at 20 km without the fade (orbit above, ground below) is a
  // step, unless the two renderers happened to agree there.
  // Outside the band the fade's images are the one renderer's (checked above at 20 and 12 km):
  // only the ground's from 20 to 12 km are rendered again.
  std::vector<double> switched;
  for (double height = 24000; height >= 8000; height -= 1000) {
    state.camera.height_m = height;
    const bool in_band = height <= 20000 && height > 12000;
    switched.push_back(in_band ? mean_luminance(ground.render(state, kWidth, kHeight).radiance)
                               : series[switched.size()]);
  }
  INFO("ground at 20 km " << switched[4] << ", orbit at 21 km " << switched[3]);
  if (std::abs(switched[4] - switched[3]) > 0.05 * mean) CHECK(jumps(switched) > 0);
}

TEST_CASE("a change renders a quarter-size preview in the next frame, then refines to full size", "[window]") {
  Viewer v(small_cover_view());
  v.set_panels_visible(false);
  refine(v);
  const long before = v.renders();
  viewer::set_value(v.state(), params::scene::light_steps, "3");
  v.frame();
  CHECK(v.renders() == before + 1);
  CHECK(v.last_render().radiance.width == (kWidth + 3) / 4);
  CHECK(v.last_render().radiance.height == (kHeight + 3) / 4);
  CHECK_FALSE(v.refined());
  v.frame();
  CHECK(v.last_render().radiance.width == (kWidth + 1) / 2);
  // Then the full size, band by band: each frame marches an eighth of the rows.
  for (int band = 0; band < 8; ++band) {
    v.frame();
    CHECK(v.last_render().radiance.width == kWidth);
    CHECK(v.shown_radiance().width == kWidth);
  }
  CHECK(v.refined());
  // Once refined, frames render nothing more.
  const long refined_renders = v.renders();
  v.frame();
  CHECK(v.renders() == refined_renders);
}

TEST_CASE("while the camera turns the preview marches a quarter of its pixels and reprojects the rest", "[window]") {
  Viewer v(small_cover_view());
  v.set_panels_visible(false);
  refine(v);
  auto has = [](const render::RenderResult& r, const std::string& prefix) {
    return std::any_of(r.passes.begin(), r.passes.end(), [&](const std::string& p) { return p.rfind(prefix, 0) == 0; });
  };
  // A turn of 2 degrees: the next frame is the quarter-size preview, a quarter marched.
  viewer::turn(v.state(), 2.0, 0.0);
  v.frame();
  const render::RenderResult moving = v.last_render();
  CHECK(moving.radiance.width == (kWidth + 3) / 4);
  CHECK(moving.march_stride == viewer::preview_march_stride);
  CHECK(has(moving, "march 1 of 4 pixels"));
  CHECK(has(moving, "reproject"));
  // Against the whole preview of the same camera: the marched quarter is the same to the bit,
  // and the reprojected rest differs only by the turn's resampling and the uncovered strip.
  viewer::GroundSource ground("", "");
  const render::RenderResult whole =
      ground.render(v.state(), moving.radiance.width, moving.radiance.height, 0, 0, true);
  const render::Camera camera = [&] {
    render::Camera c = v.state().camera;
    c.width = moving.radiance.width;
    c.height = moving.radiance.height;
    return c;
  }();
  const core::ImageData shown = render::tone_map(moving.radiance, 4.0),
                        reference = render::tone_map(whole.radiance, 4.0);
  double sum = 0;
  int exact = 0, marched = 0;
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const std::size_t k = (static_cast<std::size_t>(y) * camera.width + x);
      if (x % 2 == moving.march_phase.x && y % 2 == moving.march_phase.y) {
        ++marched;
        exact += std::equal(&moving.radiance.pixels[4 * k], &moving.radiance.pixels[4 * k + 4],
                            &whole.radiance.pixels[4 * k]);
      }
      for (int c = 0; c < 3; ++c) sum += std::pow(shown.pixels[3 * k + c] - reference.pixels[3 * k + c], 2);
    }
  CHECK(exact == marched);
  const double rms = std::sqrt(sum / (3.0 * camera.width * camera.height));
  INFO("display rms of the moving preview against the whole one: " << rms);
  // Measured 0.029 on this 16 x 9 preview (a 2-degree turn moves it by half a pixel, and the
  // reprojection resamples by that much); unfilled or misplaced pixels would give the sky-to-
  // ground contrast, several tenths.
  CHECK(rms < 0.05);
  // At rest the refinement goes on to the full size, every pixel marched.
  refine(v);
  CHECK(v.last_render().march_stride == 1);
  CHECK(v.shown_radiance().width == kWidth);
}

TEST_CASE("the preview sizes march the preview steps and the full size the scene's", "[window]") {
  viewer::ViewerOptions options = small_cover_view();
  options.scene.view_steps = 48;
  options.scene.light_steps = 12;
  Viewer v(options);
  v.set_panels_visible(false);
  // Overcast, so that the clouds the steps march are in view whatever the cover's weather; one
  // frame makes the state's cover (the renders below need no refined window).
  viewer::set_value(v.state(), params::cover::coverage, "0.95");
  v.frame();
  const auto source = viewer::make_view_source({}, {});
  viewer::ViewState cheap = v.state();
  viewer::set_value(cheap, params::scene::view_steps, std::to_string(viewer::preview_steps.view));
  viewer::set_value(cheap, params::scene::light_steps, std::to_string(viewer::preview_steps.light));
  const auto coarse = source->render(v.state(), 16, 9, 0, 0, true);
  const auto same_steps = source->render(cheap, 16, 9, 0, 0, false);
  const auto full_steps = source->render(v.state(), 16, 9, 0, 0, false);
  // A coarse frame is the scene marched with 8 x 2 steps, to the bit; without `coarse` the
  // scene's own 48 x 12 make another image.
  CHECK(coarse.radiance.pixels == same_steps.radiance.pixels);
  CHECK(coarse.radiance.pixels != full_steps.radiance.pixels);
}

TEST_CASE("a mouse drag turns the heading by dx fov / width and the pitch by dy fov / width", "[window]") {
  Viewer v(small_cover_view());
  v.set_panels_visible(false);
  v.frame();
  GLFWwindow* window = v.window().handle();
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  REQUIRE(width == kWidth);
  const double heading = v.state().camera.heading_deg, pitch = v.state().camera.pitch_deg,
               fov = v.state().camera.fov_deg;
  Viewer::on_cursor(window, 10, 10);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
  Viewer::on_cursor(window, 18, 14);
  Viewer::on_cursor(window, 26, 12);  // 16 right, 2 down in all
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
  Viewer::on_cursor(window, 60, 30);  // moves after the release do not turn
  CHECK(v.state().camera.heading_deg == Approx(heading - 16 * fov / width).epsilon(0).margin(1e-12));
  CHECK(v.state().camera.pitch_deg == Approx(pitch + 2 * fov / width).epsilon(0).margin(1e-12));
  // The drag re-renders: the next frame is a preview of the turned view.
  const long before = v.renders();
  v.frame();
  CHECK(v.renders() == before + 1);
  CHECK_FALSE(v.refined());
}

TEST_CASE("W flies one flight step along the heading, PageUp climbs one, the scroll wheel zooms", "[window]") {
  Viewer v(small_cover_view());
  v.set_panels_visible(false);
  v.frame();
  GLFWwindow* window = v.window().handle();
  const render::Camera start = v.state().camera;
  const double step = viewer::flight_step_m(v.state());
  Viewer::on_key(window, GLFW_KEY_W, 0, GLFW_PRESS, 0);
  const render::Camera moved = v.state().camera;
  // The step is flown at the camera's height: the straight line between the two positions.
  const auto& earth = GeographicLib::Geocentric::WGS84();
  glm::dvec3 a, b;
  earth.Forward(start.latitude_deg, start.longitude_deg, start.height_m, a.x, a.y, a.z);
  earth.Forward(moved.latitude_deg, moved.longitude_deg, moved.height_m, b.x, b.y, b.z);
  CHECK(glm::length(b - a) == Approx(step).epsilon(0).margin(test::kFlightStepMetres));
  regional::Site from{"", start.latitude_deg, start.longitude_deg, 0},
      to{"", moved.latitude_deg, moved.longitude_deg, 0};
  // The azimuth of a 100 m move is the heading to the angle its end subtends at the sphere's
  // centre (1.6e-5 rad, about 1e-3 degrees).
  CHECK(std::remainder(regional::geodesic_azimuth_deg(from, to) - start.heading_deg, 360.0) ==
        Approx(0).epsilon(0).margin(1e-3));
  CHECK(moved.height_m == start.height_m);
  Viewer::on_key(window, GLFW_KEY_PAGE_UP, 0, GLFW_PRESS, 0);
  CHECK(v.state().camera.height_m == Approx(start.height_m + step).epsilon(0).margin(1e-9));
  Viewer::on_scroll(window, 0, 2);
  CHECK(v.state().camera.fov_deg ==
        Approx(start.fov_deg * viewer::zoom_per_notch * viewer::zoom_per_notch).epsilon(1e-15));
}

TEST_CASE("changing a panel's cover value makes the cover again and shows a different image", "[window]") {
  Viewer v(small_cover_view());
  v.set_panels_visible(false);
  v.set_capture(true);
  viewer::set_value(v.state(), params::cover::coverage, "0.95");  // clouds in view, whatever the weather
  refine(v);
  const core::ImageData before = v.last_frame();
  viewer::set_value(v.state(), params::cover::coverage, "0.1");
  v.frame();
  const auto& timings = v.last_render().timings_ms;
  CHECK(std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.first == "global_cover"; }));
  refine(v);
  // Less cover, other clouds: some pixel changes by far more than the display's rounding.
  CHECK(largest_difference(before, v.last_frame()) > 10 * test::kEightBitDisplay);
  // Exposure only tone-maps the last render again.
  const long renders = v.renders();
  viewer::set_value(v.state(), params::scene::exposure, "1");
  v.frame();
  CHECK(v.renders() == renders);
  CHECK(largest_difference(before, v.last_frame()) > 10 * test::kEightBitDisplay);
}

TEST_CASE("F12 writes the shown render as a PNG of its size, and --record writes every frame", "[window]") {
  test::TemporaryDirectory out(true);
  viewer::ViewerOptions options = small_cover_view();
  options.record_dir = out.path / "frames";
  Viewer v(options);
  refine(v);
  const auto shot = v.screenshot(out.path);
  const core::ImageData image = files::read_image(shot);
  CHECK(image.width == kWidth);
  CHECK(image.height == kHeight);
  int frames = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out.path / "frames"))
    frames += entry.path().extension() == ".png";
  CHECK(frames == int(viewer::refinement_levels().size()));
  CHECK(std::filesystem::exists(out.path / "frames" / "frame_000000.png"));
}

TEST_CASE("without xvfb-run the window tests are skipped", "[no-xvfb]") {
  WARN(
      "skipped: xvfb-run is missing, so nephele view's window cannot be tested "
      "(install xvfb and xauth: scripts/debian-packages.txt)");
}

}  // namespace nephele

namespace nephele {

TEST_CASE("nephele view COVER_DIR --record DIR --frames N shows a generated cover and writes N frames", "[window]") {
  test::TemporaryDirectory out(true);
  const auto cover = out.path / "cover";
  REQUIRE(test::run("generate --size 16 --iterations 2 --files faces --quiet --out " + cover.string()).exit_code == 0);
  const auto frames = out.path / "frames";
  const auto r =
      test::run("view " + cover.string() +
                " --size 48x27 --frames 3 --view-steps 4 --light-steps 1 --no-cache --record " + frames.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  for (const char* name : {"frame_000000.png", "frame_000001.png", "frame_000002.png"}) {
    const core::ImageData image = files::read_image(frames / name);
    CHECK(image.width == 48);
    CHECK(image.height == 27);
  }
  CHECK_FALSE(std::filesystem::exists(frames / "frame_000003.png"));
  // --view orbit: the planet from 2000 km, looking down. Its disc's angular radius is
  // asin(6371 / 8371) = 49.6 degrees (50.3 with the air), and with 100 degrees across the corner
  // pixels look 53 degrees off the centre: black space in the corners, a lit centre (16:00 UTC
  // over Bern, the default time), where the ground view would show sky above and ground below.
  const auto orbit_frames = out.path / "orbit";
  const auto orbit =
      test::run("view " + cover.string() + " --view orbit --fov 100 --size 48x27 --frames 1 --no-cache " + "--record " +
                orbit_frames.string());
  INFO(orbit.output);
  REQUIRE(orbit.exit_code == 0);
  const core::ImageData planet = files::read_image(orbit_frames / "frame_000000.png");
  REQUIRE(planet.width == 48);
  auto grey = [&](int x, int y) {
    const size_t k = (static_cast<size_t>(y) * planet.width + x) * planet.channels;
    return (planet.pixels[k] + planet.pixels[k + 1] + planet.pixels[k + 2]) / 3.0f;
  };
  CHECK(grey(0, 0) == 0.0f);
  CHECK(grey(47, 0) == 0.0f);
  CHECK(grey(24, 13) > 0.1f);
  // A directory that is not a cover is bad input naming COVER_DIR.
  const auto bad = test::run("view " + out.path.string() + " --size 48x27 --frames 1 --no-cache");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("COVER_DIR"));
}

TEST_CASE("T plays the time: each frame after a render moves it by the time step, the moving cover made anew",
          "[window]") {
  viewer::ViewerOptions options = small_cover_view();
  Viewer v(options);
  v.set_panels_visible(false);
  v.frame();
  GLFWwindow* window = v.window().handle();
  v.state().time_step_hours = 3;
  const std::string start = v.state().time;
  Viewer::on_key(window, GLFW_KEY_T, 0, GLFW_PRESS, 0);
  REQUIRE(v.state().playing);
  auto made_cover = [&] {
    const auto& timings = v.last_render().timings_ms;
    return std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.first == "global_cover"; });
  };
  // Each frame renders the moment shown and then moves on: three frames, nine hours. The first
  // refines the moment already shown; each later one shows a new moment, its cover made anew.
  for (int k = 0; k < 3; ++k) {
    v.frame();
    if (k > 0) CHECK(made_cover());
  }
  CHECK(core::parse_utc_time(v.state().time) - core::parse_utc_time(start) == 9 * 3600.0);
  Viewer::on_key(window, GLFW_KEY_T, 0, GLFW_PRESS, 0);
  CHECK_FALSE(v.state().playing);
  const std::string paused = v.state().time;
  v.frame();
  CHECK(v.state().time == paused);
  // Comma and period step back and forth by the time step.
  Viewer::on_key(window, GLFW_KEY_COMMA, 0, GLFW_PRESS, 0);
  CHECK(core::parse_utc_time(v.state().time) == core::parse_utc_time(paused) - 3 * 3600.0);
  Viewer::on_key(window, GLFW_KEY_PERIOD, 0, GLFW_PRESS, 0);
  CHECK(core::parse_utc_time(v.state().time) == core::parse_utc_time(paused));
  // The steady cover is one map at every time: moving the time lights it anew, it is not made again.
  v.state().flow = "steady";
  refine(v);
  Viewer::on_key(window, GLFW_KEY_PERIOD, 0, GLFW_PRESS, 0);
  v.frame();
  CHECK(v.renders() > 0);
  CHECK_FALSE(made_cover());
}

}  // namespace nephele
