// Reduced-rate marching and temporal reprojection (render/reprojection.hpp): the strided march
// gives the whole render's pixels, the phases cycle through every pixel, and the reprojection
// of a turned camera's previous frame finds the same directions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "gl_support.hpp"
#include "io/weather_files.hpp"
#include "render/reprojection.hpp"
#include "render/scene_renderer.hpp"
#include "render_scenes.hpp"

using namespace nephele;

namespace {

// A perspective camera of the given size and angles (degrees).
render::Camera camera_of(int width, int height, double heading, double pitch, double fov) {
  render::Camera camera;
  camera.width = width;
  camera.height = height;
  camera.heading_deg = heading;
  camera.pitch_deg = pitch;
  camera.fov_deg = fov;
  return camera;
}

// A smooth field of the view direction, drawn into a camera's pixels (RGBA, alpha 1).
glm::dvec4 field(glm::dvec3 d) { return {0.5 + 0.4 * d.x, 0.5 + 0.3 * d.y * d.z, 0.5 + 0.4 * d.z, 1.0}; }
core::ImageData drawn(const render::Camera& camera) {
  core::ImageData image{camera.width, camera.height, 4, {}};
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const glm::dvec4 v = field(render::pixel_direction(camera, x, y));
      for (int c = 0; c < 4; ++c) image.pixels.push_back(static_cast<float>(v[c]));
    }
  return image;
}

}  // namespace

TEST_CASE("the march phases visit every pixel of a block once per cycle", "[fast][reprojection]") {
  for (int stride : {2, 3, 4}) {
    std::set<std::pair<int, int>> seen;
    for (long frame = 0; frame < stride * stride; ++frame) {
      const glm::ivec2 p = render::march_phase(frame, stride);
      REQUIRE(p.x >= 0);
      REQUIRE(p.y >= 0);
      REQUIRE(p.x < stride);
      REQUIRE(p.y < stride);
      seen.insert({p.x, p.y});
    }
    CHECK(seen.size() == static_cast<std::size_t>(stride * stride));
    CHECK(render::march_phase(stride * stride + 1, stride) == render::march_phase(1, stride));
  }
  CHECK(render::march_phase(1, 2) == glm::ivec2(1, 1));  // the diagonal next: far from the last
}

TEST_CASE("pixel_direction is the marcher's view direction", "[fast][reprojection]") {
  // The centre pixel of an odd image looks along the heading and pitch.
  render::Camera camera = camera_of(33, 19, 30, 10, 70);
  const glm::dvec3 d = render::pixel_direction(camera, 16, 9);
  const double h = 30 * M_PI / 180, p = 10 * M_PI / 180;
  CHECK(glm::length(d - glm::dvec3(std::sin(h) * std::cos(p), std::cos(h) * std::cos(p), std::sin(p))) < 1e-12);
  // The left and right edges of the centre row are fov/2 either side of it (at pitch 0).
  camera.pitch_deg = 0;
  const glm::dvec3 left = render::pixel_direction(camera, -0.5, 9), right = render::pixel_direction(camera, 32.5, 9);
  CHECK(std::acos(glm::dot(left, right)) == Approx(70 * M_PI / 180).epsilon(1e-12));
}

TEST_CASE("reprojecting a turned camera's previous frame finds each direction's value", "[fast][reprojection]") {
  // The previous frame draws a smooth field of the direction; the camera turns by 2 degrees
  // and marches (draws) a quarter of its pixels. Every other pixel inside the old view comes
  // from bilinear interpolation of the old one: the field changes by at most 0.5 per radian and
  // a pixel spans 70 deg / 64 = 0.019 rad, so the interpolation errs by less than
  // 0.5 x (0.019)^2 x (3 / 8) (its curvature along the pixel grid, perspective included,
  // below 3 per radian^2) = 7e-5; 2e-4 is allowed. Outside it (the 2-degree strip the turn
  // uncovers) pixels take their block's marched pixel.
  const render::Camera before = camera_of(64, 36, 300, 8, 70), after = camera_of(64, 36, 302, 9, 70);
  const render::FrameHistory history{drawn(before), before};
  const core::ImageData truth = drawn(after);
  const glm::ivec2 phase(1, 0);
  core::ImageData image = truth;
  for (int y = 0; y < after.height; ++y)  // what the lattice did not march is undefined
    for (int x = 0; x < after.width; ++x)
      if (x % 2 != phase.x || y % 2 != phase.y)
        for (int c = 0; c < 4; ++c) image.pixels[(y * after.width + x) * 4 + c] = std::nanf("");
  const long reprojected = render::fill_unmarched(image, after, 2, phase, &history);
  // 3/4 of the pixels are filled; those within the old view are reprojected (the turn uncovers
  // about 2/70 of the columns and 1/45 of the rows: some 5 % of the image).
  const long unmarched = 64 * 36 * 3 / 4;
  CHECK(reprojected > 0.9 * unmarched);
  CHECK(reprojected < unmarched);
  double worst_inside = 0, worst_outside = 0;
  for (int y = 0; y < after.height; ++y)
    for (int x = 0; x < after.width; ++x) {
      const std::size_t k = (static_cast<std::size_t>(y) * after.width + x) * 4;
      for (int c = 0; c < 4; ++c) {
        REQUIRE(std::isfinite(image.pixels[k + c]));
        const double error = std::abs(image.pixels[k + c] - truth.pixels[k + c]);
        (x >= 4 && x < after.width - 4 && y >= 4 && y < after.height - 4 ? worst_inside : worst_outside) = std::max(
            x >= 4 && x < after.width - 4 && y >= 4 && y < after.height - 4 ? worst_inside : worst_outside, error);
      }
    }
  INFO("largest error inside " << worst_inside << ", near the edges " << worst_outside);
  CHECK(worst_inside < 2e-4);
  // Near the edges the nearest marched pixel: one pixel away, 0.5 x 0.019 x sqrt 2 = 0.014.
  CHECK(worst_outside < 0.02);
  // Without a history every unmarched pixel is its block's marched one.
  core::ImageData alone = truth;
  CHECK(render::fill_unmarched(alone, after, 2, phase, nullptr) == 0);
  CHECK(alone.pixels[(0 * 64 + 0) * 4] == truth.pixels[(0 * 64 + 1) * 4]);
}

TEST_CASE(
    "a strided march gives the whole render's values at its pixels, and the same camera's previous frame fills the "
    "rest",
    "[reprojection][render]") {
  test::test_context();
  const regional::Scene scene = test::small_summer_scene(32, 18);
  const auto stations = io::read_scene_weather(scene);
  const render::PreparedScene prepared = render::prepare_scene(scene, stations, nullptr);
  render::RenderSettings settings = render::render_settings(scene);
  const core::ImageData whole = render::render_prepared(prepared, settings).render.radiance;
  settings.march_stride = 2;
  settings.march_phase = {1, 1};
  const render::SceneRender strided = render::render_prepared(prepared, settings);
  const core::ImageData& part = strided.render.radiance;
  int compared = 0;
  for (int y = 1; y < scene.height; y += 2)
    for (int x = 1; x < scene.width; x += 2)
      for (int c = 0; c < 4; ++c) {
        const std::size_t k = (static_cast<std::size_t>(y) * scene.width + x) * 4 + c;
        REQUIRE(part.pixels[k] == whole.pixels[k]);  // the same marcher on the same pixel
        ++compared;
      }
  CHECK(compared == 16 * 9 * 4);
  CHECK(std::find(strided.passes.begin(), strided.passes.end(), "march 1 of 4 pixels") != strided.passes.end());
  // With the same camera's whole frame as the history the filled image is the whole render.
  core::ImageData filled = part;
  const render::FrameHistory same{whole, strided.camera};
  render::fill_unmarched(filled, strided.camera, 2, settings.march_phase, &same);
  double worst = 0;
  for (std::size_t k = 0; k < filled.pixels.size(); ++k)
    worst = std::max(worst, double(std::abs(filled.pixels[k] - whole.pixels[k])));
  // Bilinear at exactly the pixel centres: the centre itself, to float rounding of 1 x v.
  CHECK(worst <= 1e-6 * 10);
  // A band or a divisor with a stride is refused.
  settings.resolution_divisor = 2;
  CHECK_THROWS_AS(render::render_prepared(prepared, settings), std::logic_error);
}
