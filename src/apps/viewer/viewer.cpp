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

// The display pass: the tone-mapped image stretched over the framebuffer (rows of the image
// from the top, of GL textures from the bottom: the flip is here).
const char* const vertex_shader = R"(#version 450 core
void main() {
  vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
  gl_Position = vec4(2.0 * corner - 1.0, 0.0, 1.0);
})";
const char* const fragment_shader = R"(#version 450 core
uniform sampler2D u_image;
uniform vec2 u_viewport;
out vec4 colour;
void main() {
  vec2 uv = gl_FragCoord.xy / u_viewport;
  colour = vec4(texture(u_image, vec2(uv.x, 1.0 - uv.y)).rgb, 1.0);
})";

unsigned compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("nephele view: display shader: ") + log);
  }
  return shader;
}

Viewer* viewer_of(GLFWwindow* window) { return static_cast<Viewer*>(glfwGetWindowUserPointer(window)); }

// ImGui takes the input first when the pointer is over a panel or a text field has focus.
bool panels_take_mouse() { return ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantCaptureMouse; }
bool panels_take_keyboard() { return ImGui::GetCurrentContext() != nullptr && ImGui::GetIO().WantCaptureKeyboard; }

// `image` at width x height by the nearest pixel: the rows that the bands have not reached yet.
core::ImageData upsampled(const core::ImageData& image, int width, int height) {
  core::ImageData out{width, height, image.channels, std::vector<float>(std::size_t(width) * height * image.channels)};
  if (image.width == 0 || image.height == 0) return out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(image.width - 1, x * image.width / width),
                sy = std::min(image.height - 1, y * image.height / height);
      std::copy_n(&image.pixels[(std::size_t(sy) * image.width + sx) * image.channels], image.channels,
                  &out.pixels[(std::size_t(y) * width + x) * image.channels]);
    }
  return out;
}

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

const std::vector<Viewer::KeyBinding>& Viewer::key_table() {
  using M = KeyMode;
  static const std::vector<KeyBinding> table = {
      {{}, false, M::view, false, "drag (left button)", "turn the view: the scene follows the cursor", nullptr},
      {{}, false, M::view, false, "scroll", "zoom (field of view); with Shift: climb or descend", nullptr},
      {{GLFW_KEY_W, GLFW_KEY_UP},
       false,
       M::view,
       true,
       "W/S or Up/Down",
       "fly forward/back along the heading",
       [](Viewer& v, GLFWwindow*) { fly(v.state_, flight_step_m(v.state_), 0, 0); }},
      {{GLFW_KEY_S, GLFW_KEY_DOWN},
       false,
       M::view,
       true,
       "",
       "",
       [](Viewer& v, GLFWwindow*) { fly(v.state_, -flight_step_m(v.state_), 0, 0); }},
      {{GLFW_KEY_A, GLFW_KEY_LEFT},
       false,
       M::view,
       true,
       "A/D or Left/Right",
       "fly left/right",
       [](Viewer& v, GLFWwindow*) { fly(v.state_, 0, -flight_step_m(v.state_), 0); }},
      {{GLFW_KEY_D, GLFW_KEY_RIGHT},
       false,
       M::view,
       true,
       "",
       "",
       [](Viewer& v, GLFWwindow*) { fly(v.state_, 0, flight_step_m(v.state_), 0); }},
      {{GLFW_KEY_PAGE_UP},
       false,
       M::view,
       true,
       "PageUp/PageDown",
       "climb/descend (a key press flies a tenth of the height, at least 50 m)",
       [](Viewer& v, GLFWwindow*) { fly(v.state_, 0, 0, flight_step_m(v.state_)); }},
      {{GLFW_KEY_PAGE_DOWN},
       false,
       M::view,
       true,
       "",
       "",
       [](Viewer& v, GLFWwindow*) { fly(v.state_, 0, 0, -flight_step_m(v.state_)); }},
      {{GLFW_KEY_F12, GLFW_KEY_P},
       false,
       M::both,
       false,
       "F12 or P",
       "screenshot: nephele_view_NNNN.png in the working directory",
       [](Viewer& v, GLFWwindow*) { std::cerr << "nephele view: wrote " << v.screenshot().string() << "\n"; }},
      {{GLFW_KEY_TAB},
       false,
       M::both,
       false,
       "Tab",
       "hide or show the panels and the times",
       [](Viewer& v, GLFWwindow*) { v.panels_ = !v.panels_; }},
      {{GLFW_KEY_ESCAPE},
       false,
       M::both,
       true,
       "Escape",
       "close the window",
       [](Viewer&, GLFWwindow* w) { glfwSetWindowShouldClose(w, GLFW_TRUE); }},
      {{}, false, M::modeller, false, "click", "select the primitive under the cursor (none: deselect)", nullptr},
      {{},
       false,
       M::modeller,
       false,
       "drag a primitive",
       "move it in the plane facing the camera through its centre",
       nullptr},
      {{},
       false,
       M::modeller,
       false,
       "drag elsewhere",
       "orbit the camera around the cloud (half a turn across the window)",
       nullptr},
      {{},
       false,
       M::modeller,
       false,
       "Shift + scroll",
       "resize the selected primitive (radius and influence x1.1 per notch)",
       nullptr},
      {{GLFW_KEY_N, GLFW_KEY_INSERT},
       false,
       M::modeller,
       false,
       "N or Insert",
       "add a primitive: a copy beside the selected one, else a point at the centre",
       [](Viewer& v, GLFWwindow* w) {
         int width = 0, height = 0;
         glfwGetWindowSize(w, &width, &height);
         add_primitive(v.state_, std::max(width, 1), std::max(height, 1));
         v.model_status_ = "added primitive " + std::to_string(v.state_.selected);
       }},
      {{GLFW_KEY_DELETE, GLFW_KEY_BACKSPACE},
       false,
       M::modeller,
       false,
       "Delete or Backspace",
       "remove the selected primitive (a model keeps at least one)",
       [](Viewer& v, GLFWwindow*) {
         const int selected = v.state_.selected;
         v.model_status_ = remove_selected(v.state_) ? "removed primitive " + std::to_string(selected)
                           : selected < 0            ? "select a primitive to remove"
                                                     : "a model keeps at least one primitive";
       }},
      {{}, false, M::modeller, false, "scroll", "zoom (field of view)", nullptr},
      {{GLFW_KEY_S},
       true,
       M::modeller,
       false,
       "Ctrl+S",
       "save the model to the --model file (an example: NAME.cloud.json here)",
       [](Viewer& v, GLFWwindow*) {
         try {
           std::cerr << "nephele view: wrote " << v.save_model().string() << "\n";
         } catch (const std::exception& e) {
           // The window stays open: the edits are still there to save elsewhere.
           v.model_status_ = e.what();
           std::cerr << "nephele view: " << e.what() << "\n";
         }
       }},
  };
  return table;
}

const std::string& key_help() {
  static const std::string help = [] {
    std::string out;
    const auto section = [&](Viewer::KeyMode mode, const char* title) {
      out += title;
      const auto& table = Viewer::key_table();
      for (std::size_t k = 0; k < table.size(); ++k) {
        const Viewer::KeyBinding& b = table[k];
        if (b.mode != mode && !(mode == Viewer::KeyMode::view && b.mode == Viewer::KeyMode::both)) continue;
        if (*b.label == '\0') continue;  // the second half of a pair the row before names
        char line[256];
        std::snprintf(line, sizeof line, "  %-23s %s\n", b.label, b.help);
        out += line;
      }
    };
    section(Viewer::KeyMode::view, "keys and mouse in the window:\n");
    section(Viewer::KeyMode::modeller, "with --model (the modeller; F12 or P, Tab and Escape as above):\n");
    return out;
  }();
  return help;
}

const std::vector<RefinementLevel>& refinement_levels() {
  // Eight bands: the rows of sky and cloud cost most (the ground's rays end at once), so the
  // bands of the upper half take most of the time; eight keep each under about a quarter of a
  // whole full-size render (docs/viewer.md).
  static const std::vector<RefinementLevel> levels = [] {
    std::vector<RefinementLevel> out = {{4, 0, 1}, {2, 0, 1}};
    for (int band = 0; band < 8; ++band) out.push_back({1, band, 8});
    return out;
  }();
  return levels;
}

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

  program_ = glCreateProgram();
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_shader), fs = compile(GL_FRAGMENT_SHADER, fragment_shader);
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  glCreateVertexArrays(1, &vertex_array_);
  if (!options.record_dir.empty()) std::filesystem::create_directories(options.record_dir);
}

Viewer::~Viewer() {
  glDeleteTextures(1, &texture_);
  glDeleteProgram(program_);
  glDeleteVertexArrays(1, &vertex_array_);
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
    if (b.parameter == &params::scene::exposure || b.parameter == &params::scene::view) continue;
    const bool camera = b.parameter == &params::scene::heading || b.parameter == &params::scene::pitch ||
                        b.parameter == &params::scene::fov;
    if (with_camera || !camera) key << ' ' << value_text(copy, *b.parameter);
  }
  for (const auto& w : copy.weather) key << ' ' << w;
  // The modeller's model, as its file would hold it (floats to the bit).
  if (copy.modeller) key << ' ' << io::write_cloud_model(copy.model);
  return key.str();
}

bool Viewer::changed() const { return render_key() != shown_key_; }

void Viewer::run() {
  while (!glfwWindowShouldClose(window_->handle()) && (options_.frames == 0 || frames_ < options_.frames)) frame();
}

void Viewer::refine(int width, int height) {
  const bool resized = width != target_width_ || height != target_height_;
  if (changed() || resized) {
    camera_moving_ = !resized && render_key(false) == shown_scene_key_;
    if (!camera_moving_) preview_history_ = {};
    shown_key_ = render_key();
    shown_scene_key_ = render_key(false);
    target_width_ = width;
    target_height_ = height;
    next_level_ = 0;
  }
  if (next_level_ < refinement_levels().size()) {
    const RefinementLevel level = refinement_levels()[next_level_];
    // Sizes round up, so that the preview is never empty.
    const int w = (width + level.divisor - 1) / level.divisor, h = (height + level.divisor - 1) / level.divisor;
    const int rows = (h + level.bands - 1) / level.bands, first = std::min(h, level.band * rows);
    render::Camera camera = state_.camera;
    camera.width = w;
    camera.height = h;
    // A moving camera's preview: a quarter of the pixels marched, the rest reprojected.
    const bool reduced = next_level_ == 0 && camera_moving_ && !camera.panorama && !state_.modeller &&
                         preview_history_.radiance.width == w && preview_history_.radiance.height == h;
    const glm::ivec2 phase = render::march_phase(moving_frames_, preview_march_stride);
    if (reduced) source_->set_march_lattice(preview_march_stride, phase);
    // The reduced sizes are previews the full size replaces: the source may march fewer steps.
    last_render_ =
        source_->render(state_, w, h, first, level.bands > 1 ? std::min(rows, h - first) : 0, level.divisor > 1);
    source_->set_march_lattice(1, {0, 0});
    if (last_render_.march_stride > 1) {
      ++moving_frames_;
      const auto start = std::chrono::steady_clock::now();
      const long reprojected = render::fill_unmarched(last_render_.radiance, camera, last_render_.march_stride,
                                                      last_render_.march_phase, &preview_history_);
      last_render_.timings_ms.emplace_back(
          "reproject", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      last_render_.passes.push_back("reproject " + std::to_string(reprojected) + " pixels");
    }
    if (next_level_ == 0) preview_history_ = {last_render_.radiance, camera};
    ++renders_;
    ++next_level_;
    if (level.bands == 1) {
      shown_ = last_render_.radiance;
    } else {
      if (level.band == 0) shown_ = upsampled(shown_, w, h);
      const std::size_t row = std::size_t(w) * shown_.channels;
      std::copy(last_render_.radiance.pixels.begin() + first * row,
                last_render_.radiance.pixels.begin() + std::min(h, first + rows) * row,
                shown_.pixels.begin() + first * row);
    }
    upload(render::tone_map(shown_, state_.exposure));
    shown_exposure_ = state_.exposure;
  } else if (shown_exposure_ != state_.exposure) {
    upload(render::tone_map(shown_, state_.exposure));
    shown_exposure_ = state_.exposure;
  }
}

void Viewer::upload(const core::ImageData& display) {
  if (display.width != texture_width_ || display.height != texture_height_) {
    glDeleteTextures(1, &texture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA32F, display.width, display.height);
    glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    texture_width_ = display.width;
    texture_height_ = display.height;
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture_, 0, 0, 0, display.width, display.height, GL_RGB, GL_FLOAT, display.pixels.data());
}

void Viewer::draw_image(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  if (texture_ == 0) return;
  glUseProgram(program_);
  glUniform2f(glGetUniformLocation(program_, "u_viewport"), float(width), float(height));
  glUniform1i(glGetUniformLocation(program_, "u_image"), 0);
  glBindTextureUnit(0, texture_);
  glBindVertexArray(vertex_array_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glUseProgram(0);
}

core::ImageData Viewer::read_framebuffer(int width, int height) const {
  std::vector<unsigned char> bytes(std::size_t(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  core::ImageData image{width, height, 3, std::vector<float>(std::size_t(width) * height * 3)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.pixels[(std::size_t(height - 1 - y) * width + x) * 3 + c] =
            bytes[(std::size_t(y) * width + x) * 4 + c] / 255.0f;
  return image;
}

void Viewer::frame() {
  const auto start = std::chrono::steady_clock::now();
  glfwPollEvents();
  int width = 0, height = 0;
  window_->framebuffer_size(width, height);
  if (width > 0 && height > 0) {
    refine(width, height);
    draw_image(width, height);
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
      const RefinementLevel level = refinement_levels()[std::min(next_level_, refinement_levels().size()) - 1];
      const std::string refinement = next_level_ >= refinement_levels().size() ? "full size"
                                     : level.bands > 1
                                         ? "band " + std::to_string(level.band + 1) + "/" + std::to_string(level.bands)
                                         : "1/" + std::to_string(level.divisor);
      draw_timings(last_render_.timings_ms, last_render_.radiance.width, last_render_.radiance.height, refinement,
                   frame_ms_);
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (capture_ || !options_.record_dir.empty()) last_frame_ = read_framebuffer(width, height);
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
  write_png(directory, name, render::tone_map(shown_, state_.exposure));
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
