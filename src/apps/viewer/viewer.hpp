#pragma once
// nephele view: a window that shows a ViewSource's image, with panels made from the parameter
// table, mouse and keyboard flight, screenshots and frame recording (docs/viewer.md).
// The display pass is apps/viewer/image_display.hpp, the refinement of each view (preview,
// half size, bands) apps/viewer/refinement.hpp, the keys the key table below (key_table.cpp).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/viewer/image_display.hpp"
#include "apps/viewer/refinement.hpp"
#include "apps/viewer/view_source.hpp"
#include "apps/viewer/view_state.hpp"
#include "apps/viewer/window.hpp"
#include "core/image.hpp"
#include "regional/scene.hpp"

struct GLFWwindow;

namespace nephele::viewer {

struct ViewerOptions {
  regional::Scene scene;                  // the first view (its size is the window's)
  std::filesystem::path cover_dir;        // a cover of nephele generate; empty: made from the panels' values
  std::filesystem::path cache_directory;  // the noise volume cache; empty: none
  std::filesystem::path record_dir;       // every displayed frame as frame_NNNNNN.png; empty: none
  long frames = 0;                        // close after this many frames; 0: when the window is closed
  bool visible = true;                    // false: a hidden window (tests)
  // nephele view --model: the cloud model the modeller edits (shown by ModelSource instead of
  // the ground and orbit views), the file Ctrl+S writes it to, and its volume's edge in voxels.
  std::optional<model::CloudModel> model;
  std::filesystem::path model_file;
  int model_size = params::cloud_model::view_model_size.default_int();
};

// The keys and mouse gestures, made from the key table that on_key dispatches through, for
// --help and docs/viewer.md.
const std::string& key_help();

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options);  // throws WindowError when no window can be opened
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Frames until the window is closed (or options.frames are shown).
  void run();
  // One frame: input events, the next refinement render if one is due, display, panels,
  // recording, buffer swap.
  void frame();

  ViewState& state() { return state_; }
  Window& window() { return *window_; }
  // True when the image shown is the full-size render of the current state.
  bool refined() const { return refinement_.done(render_key()); }
  // The last render (a band's rows only, for a band): its radiance, passes and times.
  const render::RenderResult& last_render() const { return refinement_.last_render(); }
  long renders() const { return refinement_.renders(); }
  // Wall-clock milliseconds of the last frame (events, render, display, panels, swap).
  double frame_ms() const { return frame_ms_; }
  // The default framebuffer as shown at the end of the last frame: RGB in [0, 1] (8-bit
  // values / 255), rows from the top. Only kept while capture is on (or when recording).
  void set_capture(bool on) { capture_ = on; }
  const core::ImageData& last_frame() const { return last_frame_; }
  void set_panels_visible(bool on) { panels_ = on; }
  // The linear radiance shown: the last whole render, or the full-size image its bands have
  // filled so far (the rows not yet marched from the half-size render, nearest pixel).
  const core::ImageData& shown_radiance() const { return refinement_.shown(); }
  // Writes the tone-mapped image shown (without the panels) as a PNG (the key F12 or P, into the
  // working directory as nephele_view_NNNN.png); returns the path.
  std::filesystem::path screenshot(const std::filesystem::path& directory = ".");
  // The modeller (ViewerOptions::model): the density volume as of the last render (nullptr
  // before it, and outside the modeller); Ctrl+S: the state's model written to
  // ViewerOptions::model_file as a model file, all or nothing (files::OutputSet); returns the path.
  const model::DensityVolume* model_volume() const;
  // The modeller's last message (saved, added, removed, or why not), shown in its panel.
  const std::string& model_status() const { return model_status_; }
  std::filesystem::path save_model();

  // The window's GLFW callbacks; tests call them directly as the window would.
  static void on_key(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void on_mouse_button(GLFWwindow* window, int button, int action, int mods);
  static void on_cursor(GLFWwindow* window, double x, double y);
  static void on_scroll(GLFWwindow* window, double dx, double dy);

  // One row of the key table: the keys, when they act, and what they do; rows without keys are
  // mouse gestures, listed in the help only (the mouse callbacks handle them).
  enum class KeyMode { view, modeller, both };  // the ground and orbit views, the modeller
  struct KeyBinding {
    std::vector<int> keys;  // GLFW key codes
    bool control;           // needs Ctrl (checked before the rows without)
    KeyMode mode;
    bool repeats;       // acts on a key's repeats too (flying), else on its press only
    const char* label;  // as the help shows it
    const char* help;
    void (*act)(Viewer&, GLFWwindow*);
  };
  static const std::vector<KeyBinding>& key_table();

 private:
  // Everything a render reads (with_camera false: all but the camera's position, heading,
  // pitch and field of view).
  std::string render_key(bool with_camera = true) const;
  void refine(int framebuffer_width, int framebuffer_height);

  ViewerOptions options_;
  std::unique_ptr<Window> window_;
  std::unique_ptr<ViewSource> source_;
  ViewState state_;
  Refinement refinement_;
  double shown_exposure_ = 0;  // exposure of the image shown
  long frames_ = 0;
  long renders_at_time_step_ = 0;  // renders made when playback last moved the time
  double frame_ms_ = 0;
  bool panels_ = true, capture_ = false, dragging_ = false, shift_ = false;
  // The modeller: its source, and the primitive being moved (as it was when grabbed, and the
  // point of the facing plane under the cursor then).
  ModelSource* model_source_ = nullptr;
  bool moving_ = false;
  model::Primitive grabbed_;
  glsl::vec3 grab_point_{0.0f};
  std::string model_status_;
  double cursor_x_ = 0, cursor_y_ = 0;
  std::string panel_error_;
  core::ImageData last_frame_;
  std::unique_ptr<ImageDisplay> display_;  // made once the window's context exists
};

}  // namespace nephele::viewer
