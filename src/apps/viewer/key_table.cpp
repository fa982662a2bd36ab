// The keys of nephele view: one table that on_key dispatches through and the help is printed
// from (docs/viewer.md, "Keys").
#include "apps/viewer/viewer.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <iostream>
#include <string>
#include <vector>

#include "apps/viewer/modeller.hpp"

namespace nephele::viewer {

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
      {{GLFW_KEY_T},
       false,
       M::view,
       false,
       "T",
       "play or pause time: each frame moves it by --time-step hours (the sun, and with --flow moving the clouds)",
       [](Viewer& v, GLFWwindow*) { v.state_.playing = !v.state_.playing; }},
      {{GLFW_KEY_COMMA},
       false,
       M::view,
       true,
       "Comma/Period",
       "time back/forward by --time-step hours",
       [](Viewer& v, GLFWwindow*) { advance_time(v.state_, -v.state_.time_step_hours); }},
      {{GLFW_KEY_PERIOD},
       false,
       M::view,
       true,
       "",
       "",
       [](Viewer& v, GLFWwindow*) { advance_time(v.state_, v.state_.time_step_hours); }},
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

}  // namespace nephele::viewer
