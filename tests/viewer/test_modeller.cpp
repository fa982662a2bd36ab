// nephele view --model (the modeller), driven through the window's GLFW callbacks as a person
// would and read back from the window: picking, dragging, resizing, saving, and the frame
// against nephele model's headless preview. Needs an X display (ctest: xvfb-run -a).
#include <catch2/catch.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "apps/viewer/modeller.hpp"
#include "apps/viewer/viewer.hpp"
#include "cli_support.hpp"
#include "io/cloud_model_files.hpp"
#include "files/image_files.hpp"
#include "model/density_volume.hpp"
#include "render/model_preview.hpp"
#include "tolerances.hpp"

namespace nephele {
namespace {

using viewer::Viewer;

// A small window on a small volume: 64x48 pixels, 24^3 voxels (three bricks a side).
constexpr int kWidth = 64, kHeight = 48, kVolume = 24;

// Two spheres side by side at mid height and a segment below them, apart on the screen.
model::CloudModel three_primitives() {
  model::CloudModel m;
  m.description = "modeller test: two points and a segment";
  model::Primitive a, b, c;
  a.from = a.to = glsl::vec3(0.3f, 0.5f, 0.5f);
  a.radius = 0.08f;
  a.influence = 0.06f;
  b.from = b.to = glsl::vec3(0.7f, 0.55f, 0.55f);
  b.radius = 0.1f;
  b.influence = 0.05f;
  b.noise.seed = 7;
  c.segment = true;
  c.from = glsl::vec3(0.3f, 0.45f, 0.2f);
  c.to = glsl::vec3(0.7f, 0.45f, 0.25f);
  c.radius = 0.05f;
  c.influence = 0.05f;
  m.primitives = {a, b, c};
  model::validate(m, "the test model");
  return m;
}

viewer::ViewerOptions modeller_view(const model::CloudModel& m, const std::filesystem::path& file = {}) {
  viewer::ViewerOptions options;
  options.scene.width = kWidth;
  options.scene.height = kHeight;
  options.model = m;
  options.model_file = file;
  options.model_size = kVolume;
  options.visible = false;
  return options;
}

int refine(Viewer& v, int limit = 20) {
  int frames = 0;
  do {
    v.frame();
    ++frames;
  } while (!v.refined() && frames < limit);
  return frames;
}

// The camera of the state's frame (the preview's pinhole), in double.
struct Pinhole {
  glm::dvec3 origin, forward, right, up;
  double tan_half_fov;
};
Pinhole pinhole(const viewer::ViewState& s) {
  const glsl::ModelView v = render::preview_view(s.model, viewer::preview_settings(s, kWidth, kHeight));
  return {glm::dvec3(v.origin) / double(v.extent), glm::dvec3(v.forward), glm::dvec3(v.right), glm::dvec3(v.up),
          double(v.tan_half_fov)};
}

// Where `point` appears (pixels from the top-left corner) by the pinhole's own formula: x
// spans the width by tan_half_fov, y the height by the same angle per pixel.
glm::dvec2 screen_of(const Pinhole& c, glm::dvec3 point) {
  const glm::dvec3 r = point - c.origin;
  const double depth = glm::dot(r, c.forward);
  const double x = glm::dot(r, c.right) / depth / c.tan_half_fov, y = glm::dot(r, c.up) / depth / c.tan_half_fov;
  return {(x + 1) / 2 * kWidth, kHeight / 2.0 - y * kWidth / 2.0};
}

glm::dvec3 centre_of(const model::Primitive& p) { return glm::dvec3(viewer::centre(p)); }

// The opacity (alpha) of the shown radiance at the pixel holding screen point `at`.
float opacity_at(const Viewer& v, glm::dvec2 at) {
  const core::ImageData& image = v.shown_radiance();
  REQUIRE(image.channels == 4);
  const int x = std::clamp(int(at.x), 0, image.width - 1), y = std::clamp(int(at.y), 0, image.height - 1);
  return image.pixels[(std::size_t(y) * image.width + x) * 4 + 3];
}

void click(GLFWwindow* window, glm::dvec2 at) {
  Viewer::on_cursor(window, at.x, at.y);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
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

std::vector<float> read_raw(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<float> values(bytes.size() / sizeof(float));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(float));
  return values;
}

}  // namespace

TEST_CASE("modeller: a click at a primitive's projected centre selects it, a click on empty sky selects none",
          "[window][modeller]") {
  Viewer v(modeller_view(three_primitives()));
  v.set_panels_visible(false);
  refine(v);
  GLFWwindow* window = v.window().handle();
  const Pinhole camera = pinhole(v.state());
  for (int i : {0, 1, 2}) {
    const glm::dvec2 at = screen_of(camera, centre_of(v.state().model.primitives[std::size_t(i)]));
    INFO("primitive " << i << " at " << at.x << ", " << at.y);
    REQUIRE(at.x > 0);
    REQUIRE(at.x < kWidth);
    // The picking's projection is the pinhole's (to float rounding of a few 1e-5 pixels).
    const glsl::vec3 projected =
        viewer::project(v.state(), viewer::centre(v.state().model.primitives[std::size_t(i)]), kWidth, kHeight);
    CHECK(projected.x == Approx(at.x).epsilon(0).margin(1e-3));
    CHECK(projected.y == Approx(at.y).epsilon(0).margin(1e-3));
    // What is picked is what the pixel shows: the cloud is opaque there.
    CHECK(opacity_at(v, at) > 0.5f);
    click(window, at);
    CHECK(v.state().selected == i);
  }
  // The top-left corner looks above every primitive: nothing there, and nothing selected.
  CHECK(opacity_at(v, {1, 1}) == 0.0f);
  click(window, {1, 1});
  CHECK(v.state().selected == -1);
  // Selecting renders nothing new (the selection is an overlay of the panels).
  const long renders = v.renders();
  v.frame();
  CHECK(v.renders() == renders);
}

TEST_CASE("modeller: a drag moves the primitive in the plane facing the camera by the ray geometry's offset",
          "[window][modeller]") {
  Viewer v(modeller_view(three_primitives()));
  v.set_panels_visible(false);
  refine(v);
  GLFWwindow* window = v.window().handle();
  const Pinhole camera = pinhole(v.state());
  const model::Primitive before = v.state().model.primitives[0];
  const glm::dvec3 c = centre_of(before);
  const glm::dvec2 start = screen_of(camera, c);
  // 6 pixels left, 4 up, in two moves (the offset counts from where the drag began).
  Viewer::on_cursor(window, start.x, start.y);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
  Viewer::on_cursor(window, start.x - 2, start.y - 3);
  Viewer::on_cursor(window, start.x - 6, start.y - 4);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
  Viewer::on_cursor(window, 1, 1);  // moves after the release move nothing
  CHECK(v.state().selected == 0);
  // The plane through the centre facing the camera lies `depth` along the view; there a pixel
  // spans 2 depth tan(fov / 2) / width along right and up alike, so that the cursor's offset
  // (dx, dy) moves the point under it by depth 2 tan / width (dx right - dy up), exactly.
  const double depth = glm::dot(c - camera.origin, camera.forward);
  const double pixel = 2 * depth * camera.tan_half_fov / kWidth;
  const glm::dvec3 expected = c + pixel * (-6.0 * camera.right + 4.0 * camera.up);
  const glm::dvec3 now = centre_of(v.state().model.primitives[0]);
  // Float rays and points (relative rounding about 1e-7 on lengths below 2) are far inside a
  // thousandth of a pixel's footprint.
  for (int a = 0; a < 3; ++a) CHECK(now[a] == Approx(expected[a]).epsilon(0).margin(1e-3 * pixel));
  CHECK(v.state().model.primitives[0].radius == before.radius);
  CHECK(v.state().model.primitives[1] == three_primitives().primitives[1]);
  // The volume follows in the next frames (edited, not computed again), and the cloud is under
  // the cursor's end, gone from where it started.
  v.frame();
  const auto& timings = v.last_render().timings_ms;
  CHECK(std::any_of(timings.begin(), timings.end(), [](const auto& t) { return t.first == "volume_edit"; }));
  refine(v);
  REQUIRE(v.model_volume() != nullptr);
  CHECK(v.model_volume()->model().primitives[0] == v.state().model.primitives[0]);
  CHECK(opacity_at(v, {start.x - 6, start.y - 4}) > 0.5f);
  CHECK(opacity_at(v, start) < 0.1f);
}

TEST_CASE("modeller: Shift + scroll resizes the selected primitive by 1.1 per notch, and a drag on the sky orbits",
          "[window][modeller]") {
  Viewer v(modeller_view(three_primitives()));
  v.set_panels_visible(false);
  refine(v);
  GLFWwindow* window = v.window().handle();
  const model::Primitive before = v.state().model.primitives[1];
  click(window, screen_of(pinhole(v.state()), centre_of(before)));
  REQUIRE(v.state().selected == 1);
  const double fov = v.state().camera.fov_deg;
  Viewer::on_key(window, GLFW_KEY_LEFT_SHIFT, 0, GLFW_PRESS, GLFW_MOD_SHIFT);
  Viewer::on_scroll(window, 0, 2);
  Viewer::on_key(window, GLFW_KEY_LEFT_SHIFT, 0, GLFW_RELEASE, 0);
  const model::Primitive& after = v.state().model.primitives[1];
  // r 1.1^2, to the float the product rounds to (half an ulp, 6e-8 relative).
  CHECK(after.radius == Approx(before.radius * 1.21).epsilon(1.2e-7));
  CHECK(after.influence == Approx(before.influence * 1.21).epsilon(1.2e-7));
  CHECK(after.from == before.from);
  CHECK(v.state().camera.fov_deg == fov);  // with Shift the wheel does not zoom
  refine(v);
  CHECK(v.model_volume()->model().primitives[1] == after);
  // Without Shift it zooms; down a notch shrinks back by one factor.
  Viewer::on_scroll(window, 0, 1);
  CHECK(v.state().camera.fov_deg == Approx(fov * viewer::zoom_per_notch).epsilon(1e-15));
  Viewer::on_key(window, GLFW_KEY_RIGHT_SHIFT, 0, GLFW_PRESS, GLFW_MOD_SHIFT);
  Viewer::on_scroll(window, 0, -1);
  Viewer::on_key(window, GLFW_KEY_RIGHT_SHIFT, 0, GLFW_RELEASE, 0);
  CHECK(v.state().model.primitives[1].radius == Approx(before.radius * 1.1).epsilon(2.4e-7));
  // A drag from the sky turns the camera half a turn per window width and moves no primitive.
  const model::CloudModel edited = v.state().model;
  const double heading = v.state().camera.heading_deg, pitch = v.state().camera.pitch_deg;
  Viewer::on_cursor(window, 1, 1);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
  Viewer::on_cursor(window, 9, 3);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
  CHECK(v.state().selected == -1);
  CHECK(v.state().camera.heading_deg == Approx(heading + 8 * 180.0 / kWidth).epsilon(0).margin(1e-12));
  CHECK(v.state().camera.pitch_deg == Approx(pitch - 2 * 180.0 / kWidth).epsilon(0).margin(1e-12));
  for (std::size_t i = 0; i < edited.primitives.size(); ++i)
    CHECK(v.state().model.primitives[i] == edited.primitives[i]);
}

TEST_CASE("modeller: N adds a copy beside the selected primitive and Delete removes it, down to one primitive",
          "[window][modeller]") {
  const model::CloudModel original = three_primitives();
  Viewer v(modeller_view(original));
  v.set_panels_visible(false);
  refine(v);
  GLFWwindow* window = v.window().handle();
  const core::ImageData three = v.shown_radiance();
  const std::vector<float> three_volume = v.model_volume()->read();
  const model::Primitive source = original.primitives[0];
  click(window, screen_of(pinhole(v.state()), centre_of(source)));
  REQUIRE(v.state().selected == 0);

  Viewer::on_key(window, GLFW_KEY_N, 0, GLFW_PRESS, 0);
  REQUIRE(v.state().model.primitives.size() == 4);
  CHECK(v.state().selected == 3);
  const model::Primitive added = v.state().model.primitives[3];
  // Beside it along the camera's right axis by its diameter plus influence (0.22 model units),
  // to float rounding of the sum (a few ulp of 0.5).
  const Pinhole camera = pinhole(v.state());
  const glm::dvec3 offset = centre_of(added) - centre_of(source);
  CHECK(glm::length(offset) == Approx(2 * source.radius + source.influence).margin(1e-6));
  CHECK(glm::dot(offset, camera.right) == Approx(glm::length(offset)).margin(1e-6));
  CHECK(added.radius == source.radius);
  CHECK(added.influence == source.influence);
  CHECK(added.weight == source.weight);
  CHECK(added.noise.seed == 8);  // one above the largest seed in use (7)
  refine(v);
  REQUIRE(v.model_volume()->model().primitives.size() == 4);
  CHECK(opacity_at(v, screen_of(camera, centre_of(added))) > 0.5f);

  Viewer::on_key(window, GLFW_KEY_DELETE, 0, GLFW_PRESS, 0);
  CHECK(v.state().selected == -1);
  REQUIRE(v.state().model.primitives.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) CHECK(v.state().model.primitives[i] == original.primitives[i]);
  CHECK(v.model_status() == "removed primitive 3");
  refine(v);
  // Computed again from the same three primitives: the same voxels and frame, to the bit.
  CHECK(v.model_volume()->read() == three_volume);
  CHECK(largest_difference(v.shown_radiance(), three) == 0.0);

  // With nothing selected, Delete removes nothing and N adds a point at the cube's centre.
  Viewer::on_key(window, GLFW_KEY_BACKSPACE, 0, GLFW_PRESS, 0);
  CHECK(v.state().model.primitives.size() == 3);
  CHECK(v.model_status() == "select a primitive to remove");
  Viewer::on_key(window, GLFW_KEY_INSERT, 0, GLFW_PRESS, 0);
  REQUIRE(v.state().model.primitives.size() == 4);
  const model::Primitive centred = v.state().model.primitives[3];
  CHECK_FALSE(centred.segment);
  CHECK(centred.from == glsl::vec3(0.5f));
  CHECK(centred.radius == model::Primitive{}.radius);
  CHECK(centred.noise.seed == 8);

  // The last primitive stays.
  for (int i = 0; i < 3; ++i) {
    v.state().selected = 0;
    Viewer::on_key(window, GLFW_KEY_DELETE, 0, GLFW_PRESS, 0);
  }
  REQUIRE(v.state().model.primitives.size() == 1);
  v.state().selected = 0;
  Viewer::on_key(window, GLFW_KEY_DELETE, 0, GLFW_PRESS, 0);
  CHECK(v.state().model.primitives.size() == 1);
  CHECK(v.model_status() == "a model keeps at least one primitive");
}

TEST_CASE(
    "modeller: Ctrl+S saves the edited model whole, the file reads back to it exactly, and nephele model "
    "makes the same volume and frame from it",
    "[window][modeller]") {
  test::TemporaryDirectory out(true);
  const auto file = out.path / "edited.cloud.json";
  // The file opened: the model as nephele model reads it.
  {
    std::ofstream f(file);
    f << io::write_cloud_model(three_primitives());
  }
  const model::CloudModel opened = io::read_cloud_model(file.string());
  Viewer v(modeller_view(opened, file));
  v.set_panels_visible(false);
  v.set_capture(true);
  refine(v);
  GLFWwindow* window = v.window().handle();
  // Move the segment 5 pixels right, then grow the first sphere a notch.
  const glm::dvec2 at = screen_of(pinhole(v.state()), centre_of(v.state().model.primitives[2]));
  Viewer::on_cursor(window, at.x, at.y);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
  Viewer::on_cursor(window, at.x + 5, at.y);
  Viewer::on_mouse_button(window, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);
  REQUIRE(v.state().selected == 2);
  v.frame();  // the segment's edit
  click(window, screen_of(pinhole(v.state()), centre_of(v.state().model.primitives[0])));
  REQUIRE(v.state().selected == 0);
  Viewer::on_key(window, GLFW_KEY_LEFT_SHIFT, 0, GLFW_PRESS, GLFW_MOD_SHIFT);
  Viewer::on_scroll(window, 0, 1);
  Viewer::on_key(window, GLFW_KEY_LEFT_SHIFT, 0, GLFW_RELEASE, 0);
  refine(v);
  const model::CloudModel edited = v.state().model;
  REQUIRE(edited.primitives[2] != opened.primitives[2]);
  REQUIRE(edited.primitives[0] != opened.primitives[0]);

  Viewer::on_key(window, GLFW_KEY_S, 0, GLFW_PRESS, GLFW_MOD_CONTROL);
  // Written aside and renamed: the directory holds the file and nothing else.
  int entries = 0;
  for (const auto& entry : std::filesystem::directory_iterator(out.path)) {
    ++entries;
    CHECK(entry.path().filename() == file.filename());
  }
  CHECK(entries == 1);
  const model::CloudModel saved = io::read_cloud_model(file.string());
  CHECK(saved.description == edited.description);
  CHECK(saved.blend == edited.blend);
  CHECK(saved.scale == edited.scale);
  CHECK(saved.extent_m == edited.extent_m);
  CHECK(saved.noise == edited.noise);
  REQUIRE(saved.primitives.size() == edited.primitives.size());
  for (std::size_t i = 0; i < saved.primitives.size(); ++i) CHECK(saved.primitives[i] == edited.primitives[i]);

  // nephele model on the saved file, at the window's size and the volume's: the same voxels
  // (the window's were edited twice, the headless ones computed whole) and the same frame.
  const auto dir = out.path / "headless";
  const auto r = test::run("model --scene " + file.string() + " --size " + std::to_string(kVolume) + " --preview " +
                           std::to_string(kWidth) + "x" + std::to_string(kHeight) + " --quiet --out " + dir.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  const std::vector<float> voxels = read_raw(dir / "density.raw");
  CHECK(voxels == v.model_volume()->read());
  const core::ImageData preview = files::read_image(dir / "preview.png");
  // Both 8-bit: preview.png rounds 255 v to the nearest, the framebuffer in either direction.
  CHECK(largest_difference(v.last_frame(), preview) == Approx(0).epsilon(0).margin(test::kEightBitDisplay + 1e-6));
  // The radiance itself: the preview pass in this context on the window's volume, to the bit.
  render::PreviewSettings settings = viewer::preview_settings(v.state(), kWidth, kHeight);
  CHECK(largest_difference(v.shown_radiance(), render::render_preview(*v.model_volume(), settings)) == 0);
}

TEST_CASE("nephele view --model FILE --frames N opens the modeller on a model file, and bad values exit 2",
          "[window][modeller]") {
  test::TemporaryDirectory out(true);
  const auto file = out.path / "m.cloud.json";
  {
    std::ofstream f(file);
    f << io::write_cloud_model(three_primitives());
  }
  const auto frames = out.path / "frames";
  const auto r = test::run("view --model " + file.string() + " --model-size 16 --size 48x36 --frames 2 --record " +
                           frames.string());
  INFO(r.output);
  REQUIRE(r.exit_code == 0);
  CHECK(files::read_image(frames / "frame_000001.png").width == 48);
  const auto bad = test::run("view --model " + file.string() + " --model-size 7 --frames 1");
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.output, Catch::Contains("--model-size"));
}

}  // namespace nephele
