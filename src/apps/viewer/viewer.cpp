#include "apps/viewer/viewer.hpp"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "apps/viewer/modeller.hpp"
#include "apps/viewer/panels.hpp"
#include "files/atomic_output.hpp"
#include "io/cloud_model_files.hpp"
#include "files/image_files.hpp"
#include "model/model_limits.hpp"

namespace nephele::viewer {
namespace {

Viewer* viewer_of(GLFWwindow* window) { return static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

// ImGui takes the input first when the pointer is over a panel or a text field has focus.
bool panels_take_mouse() { return ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantCaptureMouse; }
bool panels_take_keyboard() { return ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantCaptureKeyboard; }

std::string frame_name(long index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06ld.png", index);
  return name;
}

// One file written whole or not at all (the frames, screenshots and saved models).
void write_whole(const std::filesystem::path& directory, const std::string& name,
                 const std::vector<unsigned char>& bytes) {
  files::OutputSet set(directory.empty() ? "." : directory, files::OutputSet::Scope::files);
  set.write(name, bytes);
  set.commit();
}

void write_png(const std::filesystem::path& directory, const std::string& name, const core::ImageData& image) {
  write_whole(directory, name, files::encode_image(image, files::png_encoding(8), name));
}

bool shift_held(GLFWwindow* window) {
  return glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
         glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
}

// The selected primitive's outline over the image: its sphere's circle, or the circles of a
// capsule's ends joined at their sides (ImGui's foreground list, so the render is untouched).
void draw_selection(const ViewState& state, int width, int height) {
  if (state.selected < 0 || state.selected >= int(state.model.primitives.size())) return;
  const model::Primitive& p = state.model.primitives[std::size_t(state.selected)];
  ImDrawList* list = ImGui::GetForegroundDrawList();
  const ImU32 colour = IM_COL32(255, 190, 40, 255);
  const float tan_half = float(std::tan(0.5 * state.camera.fov_deg * M_PI / 180.0));
  auto circle = [&](glsl::vec3 point) {
    const glsl::vec3 at = project(state, point, width, height);
    if (at.z <= 0) return ImVec4(0, 0, 0, -1);
    // The sphere's apparent radius: R at depth z spans R / (z tan) of the half width.
    const float r = std::max(2.0f, p.radius / (at.z * tan_half) * 0.5f * float(width));
    list->AddCircle(ImVec2(at.x, at.y), r, colour, 48, 2.0f);
    return ImVec4(at.x, at.y, r, 1);
  };
  const ImVec4 a = circle(p.from);
  if (!p.segment) return;
  const ImVec4 b = circle(p.to);
  if (a.w < 0 || b.w < 0) return;
  const float dx = b.x - a.x, dy = b.y - a.y, length = std::max(1e-3f, std::hypot(dx, dy));
  const float nx = -dy / length, ny = dx / length;
  for (const float side : {1.0f, -1.0f})
    list->AddLine(ImVec2(a.x + side * nx * a.z, a.y + side * ny * a.z),
                  ImVec2(b.x + side * nx * b.z, b.y + side * ny * b.z), colour, 2.0f);
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options) : options_(options) {
  if (options.model) {
    state_ = modeller_state(*options.model);
    auto source = std::make_unique<ModelSource>(options.model_size);
    model_source_ = source.get();
    source_ = std::move(source);
  } else {
    state_ = state_of_scene(options.scene);
    // Files first (a COVER_DIR that is not a cover is bad input, with or without a display).
    source_ = make_view_source(options.cover_dir, options.cache_directory);
  }
  window_ = std::make_unique<Window>(options.scene.width, options.scene.height, "nephele view", options.visible);
  // The modeller's volume must fit before it is made (in the first frame).
  if (options.model) model::check_model_fits(options.model_size, *window_, "--model-size");
  GLFWwindow* handle = window_->handle();
  glfwSetWindowUserPointer(handle, this);
  glfwSetKeyCallback(handle, on_key);
  glfwSetMouseButtonCallback(handle, on_mouse_button);
  glfwSetCursorPosCallback(handle, on_cursor);
  glfwSetScrollCallback(handle, on_scroll);
  glfwSetCharCallback(handle, ImGui_ImplGlfw_CharCallback);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsDark();
  // Our callbacks forward to ImGui's (install_callbacks = false), so that one route serves both.
  ImGui_ImplGlfw_InitForOpenGL(handle, false);
  ImGui_ImplOpenGL3_Init("#version 450 core");

  display_ = std::make_unique<ImageDisplay>();
  if (!options.record_dir.empty()) std::filesystem::create_directories(options.record_dir);
}

Viewer::~Viewer() {
  display_.reset();  // while the window's context exists
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

std::string Viewer::render_key(bool with_camera) const {
  // Everything a render reads; exposure only tone-maps.
  ViewState copy = state_;
  std::ostringstream key;
  key.precision(17);
  if (with_camera) key << copy.camera.latitude_deg << ' ' << copy.camera.longitude_deg << ' ' << copy.camera.height_m;
  for (const Binding& b : bindings(copy)) {
    if (b.parameter == &params::scene::exposure || b.parameter == &params::scene::view ||
        b.parameter == &params::run::time_step)
      continue;
    const bool camera = b.parameter == &params::scene::heading || b.parameter == &params::scene::pitch ||
                        b.parameter == &params::scene::fov;
    if (with_camera || !camera) key << ' ' << value_text(copy, *b.parameter);
  }
  for (const auto& w : copy.weather) key << ' ' << w;
  // The modeller's model, as its file would hold it (floats to the bit).
  if (copy.modeller) key << ' ' << io::write_cloud_model(copy.model);
  return key.str();
}

void Viewer::run() {
  while (!glfwWindowShouldClose(window_->handle()) && (options_.frames == 0 || frames_ < options_.frames)) frame();
}

void Viewer::refine(int width, int height) {
  // Exposure only tone-maps the last image again.
  const std::string key = render_key();
  if (refinement_.stale(key, width, height)) refinement_.restart(key, render_key(false), width, height);
  if (refinement_.step(*source_, state_) || shown_exposure_ != state_.exposure) {
    display_->upload(render::tone_map(refinement_.shown(), state_.exposure));
    shown_exposure_ = state_.exposure;
  }
}

void Viewer::frame() {
  const auto start = std::chrono::steady_clock::now();
  glfwPollEvents();
  int width = 0, height = 0;
  window_->framebuffer_size(width, height);
  if (width > 0 && height > 0) {
    refine(width, height);
    // Playing: once the current moment has been rendered (its first, coarse level), the next.
    if (state_.playing && state_.modeller == false && refinement_.renders() > renders_at_time_step_) {
      advance_time(state_, state_.time_step_hours);
      renders_at_time_step_ = refinement_.renders();
    }
    display_->draw(width, height);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (panels_) {
      if (state_.modeller) {
        draw_model_panels(state_, panel_error_, model_status_);
        int window_width = 0, window_height = 0;
        glfwGetWindowSize(window_->handle(), &window_width, &window_height);
        draw_selection(state_, window_width, window_height);
      } else {
        draw_panels(state_, panel_error_);
      }
      const std::size_t next_level = refinement_.next_level();
      const RefinementLevel level = refinement_levels()[std::min(next_level, refinement_levels().size()) - 1];
      const std::string refinement = next_level >= refinement_levels().size() ? "full size"
                                     : level.bands > 1
                                         ? "band " + std::to_string(level.band + 1) + "/" + std::to_string(level.bands)
                                         : "1/" + std::to_string(level.divisor);
      const render::RenderResult& last = refinement_.last_render();
      draw_timings(last.timings_ms, last.radiance.width, last.radiance.height, refinement, frame_ms_);
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (capture_ || !options_.record_dir.empty()) last_frame_ = ImageDisplay::read_framebuffer(width, height);
    if (!options_.record_dir.empty()) write_png(options_.record_dir, frame_name(frames_), last_frame_);
    glfwSwapBuffers(window_->handle());
  }
  ++frames_;
  frame_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  // Nothing left to refine: wait for input instead of spinning (the panels still redraw on it).
  if (refined() && options_.record_dir.empty() && options_.frames == 0) glfwWaitEventsTimeout(0.1);
}

std::filesystem::path Viewer::screenshot(const std::filesystem::path& directory) {
  std::string name;
  for (int i = 0;; ++i) {
    char text[32];
    std::snprintf(text, sizeof text, "nephele_view_%04d.png", i);
    if (!std::filesystem::exists(directory / text)) {
      name = text;
      break;
    }
  }
  write_png(directory, name, render::tone_map(refinement_.shown(), state_.exposure));
  return directory / name;
}

const model::DensityVolume* Viewer::model_volume() const { return model_source_ ? model_source_->volume() : nullptr; }

std::filesystem::path Viewer::save_model() {
  const std::filesystem::path& path = options_.model_file;
  const std::string text = io::write_cloud_model(state_.model);
  write_whole(path.parent_path(), path.filename().string(), std::vector<unsigned char>(text.begin(), text.end()));
  model_status_ = "saved " + path.string();
  return path;
}

void Viewer::on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  Viewer* viewer = viewer_of(window);
  // Shift as the key events report it (the scroll callback has no modifiers; glfwGetKey below
  // covers a Shift pressed before the window had the focus).
  if (viewer != nullptr && (key == GLFW_KEY_LEFT_SHIFT || key == GLFW_KEY_RIGHT_SHIFT))
    viewer->shift_ = action != GLFW_RELEASE;
  if (viewer == nullptr || panels_take_keyboard() || (action != GLFW_PRESS && action != GLFW_REPEAT)) return;
  const KeyMode mode = viewer->state_.modeller ? KeyMode::modeller : KeyMode::view;
  const bool control = (mods & GLFW_MOD_CONTROL) != 0;
  // The rows that need Ctrl first, so that Ctrl+S saves rather than flies.
  for (const bool with_control : {true, false})
    for (const KeyBinding& b : key_table()) {
      if (b.act == nullptr || b.control != with_control || (b.control && !control)) continue;
      if (b.mode != KeyMode::both && b.mode != mode) continue;
      if (std::find(b.keys.begin(), b.keys.end(), key) == b.keys.end()) continue;
      if (action == GLFW_PRESS || b.repeats) b.act(*viewer, window);
      return;
    }
}

void Viewer::on_mouse_button(GLFWwindow* window, int button, int action, int mods) {
  ImGui_ImplGlfw_MouseButtonCallback(window, button, action, mods);
  Viewer* viewer = viewer_of(window);
  if (viewer == nullptr || button != GLFW_MOUSE_BUTTON_LEFT) return;
  viewer->dragging_ = action == GLFW_PRESS && !panels_take_mouse();
  viewer->moving_ = false;
  ViewState& s = viewer->state_;
  if (!viewer->dragging_ || !s.modeller) return;
  // A press picks: the primitive under the cursor is selected and held, else none is selected
  // and the drag orbits.
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  const Ray ray = cursor_ray(s, viewer->cursor_x_, viewer->cursor_y_, width, height);
  s.selected = pick_primitive(s.model, ray);
  if (s.selected < 0) return;
  viewer->moving_ = true;
  viewer->grabbed_ = s.model.primitives[std::size_t(s.selected)];
  viewer->grab_point_ = on_facing_plane(s, ray, centre(viewer->grabbed_));
}

void Viewer::on_cursor(GLFWwindow* window, double x, double y) {
  Viewer* viewer = viewer_of(window);
  if (viewer == nullptr) return;
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  ViewState& s = viewer->state_;
  if (viewer->moving_ && s.selected >= 0 && s.selected < int(s.model.primitives.size())) {
    // Moved by the plane's offset from where it was grabbed: no drift over many small moves.
    const glsl::vec3 now = on_facing_plane(s, cursor_ray(s, x, y, width, height), centre(viewer->grabbed_));
    s.model.primitives[std::size_t(s.selected)] = moved(viewer->grabbed_, now - viewer->grab_point_);
  } else if (viewer->dragging_) {
    if (s.modeller)
      orbit(s, x - viewer->cursor_x_, y - viewer->cursor_y_, width);
    else
      drag(s, x - viewer->cursor_x_, y - viewer->cursor_y_, width);
  }
  viewer->cursor_x_ = x;
  viewer->cursor_y_ = y;
}

void Viewer::on_scroll(GLFWwindow* window, double dx, double dy) {
  ImGui_ImplGlfw_ScrollCallback(window, dx, dy);
  Viewer* viewer = viewer_of(window);
  if (viewer == nullptr || panels_take_mouse()) return;
  ViewState& s = viewer->state_;
  if (!viewer->shift_ && !shift_held(window))
    zoom(s, dy);
  else if (!s.modeller)
    fly(s, 0, 0, dy * flight_step_m(s));
  else if (s.selected >= 0 && s.selected < int(s.model.primitives.size()))
    s.model.primitives[std::size_t(s.selected)] = resized(s.model.primitives[std::size_t(s.selected)], dy);
}

}  // namespace nephele::viewer
