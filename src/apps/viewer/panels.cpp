#include "apps/viewer/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>

#include "core/error.hpp"
#include "core/time.hpp"
#include "params/values.hpp"

namespace nephele::viewer {
namespace {

FieldPointer field_of(ViewState& state, const params::Parameter& p) {
  for (const Binding& b : bindings(state))
    if (b.parameter == &p) return b.field;
  throw std::logic_error("nephele view: no field for parameter '" + std::string(p.key) + "'");
}

std::string tooltip(const params::Parameter& p) {
  std::string text(p.help);
  if (!p.unit.empty()) text += " [" + std::string(p.unit) + "]";
  const std::string range = p.range_text();
  if (!range.empty()) text += "\nallowed: " + range;
  text += "\noption: " + p.option();
  return text;
}

// A time as the scene's rule reads it; refused as bad input naming the option.
void check_time(const params::Parameter& p, const std::string& text) {
  try {
    core::parse_utc_time(text);
  } catch (const std::invalid_argument&) {
    throw core::InputError(p.option(), text, p.range_text(), "is not a date and time that exists");
  }
}

// Ranges wider than this many units are dragged (with clamping), narrower ones slid.
constexpr double slider_span = 4096;

// One number widget; returns true when the value changed.
template <class T>
bool number_widget(const params::Parameter& p, T& value) {
  const std::string label(p.key);
  double v = static_cast<double>(value);
  const double lo = p.min, hi = p.max;
  bool changed = false;
  if (p.type == params::Type::integer) {
    if (hi - lo <= slider_span) {
      int i = static_cast<int>(v);
      changed = ImGui::SliderInt(label.c_str(), &i, int(lo), int(hi), "%d", ImGuiSliderFlags_AlwaysClamp);
      v = i;
    } else {
      changed = ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &v, 1.0f, &lo, &hi, "%.0f",
                                  ImGuiSliderFlags_AlwaysClamp);
      v = std::floor(v);
    }
  } else {
    // Ranges over many decades (exposure 1e-6 to 1e6) on a logarithmic scale.
    const int flags = ImGuiSliderFlags_AlwaysClamp | (lo > 0 && hi / lo > 1000 ? ImGuiSliderFlags_Logarithmic : 0);
    changed = ImGui::SliderScalar(label.c_str(), ImGuiDataType_Double, &v, &lo, &hi, "%.4g", flags);
  }
  if (changed) value = static_cast<T>(v);
  return changed;
}

bool text_widget(const params::Parameter& p, std::string& value, std::string& error) {
  const std::string label(p.key);
  const std::vector<std::string> words = p.words();
  if (!words.empty()) {
    bool changed = false;
    if (ImGui::BeginCombo(label.c_str(), value.c_str())) {
      for (const std::string& w : words)
        if (ImGui::Selectable(w.c_str(), w == value)) {
          changed = w != value;
          value = w;
        }
      ImGui::EndCombo();
    }
    return changed;
  }
  // A form (a time): edited as text, applied on Enter when it is valid.
  static std::map<const params::Parameter*, std::string> drafts;
  std::string& draft = drafts.try_emplace(&p, value).first->second;
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%s", draft.c_str());
  const bool entered = ImGui::InputText(label.c_str(), buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  draft = buffer;
  if (!entered || draft == value) return false;
  try {
    if (&p == &params::scene::time) check_time(p, draft);
    value = draft;
    error.clear();
    return true;
  } catch (const core::InputError& e) {
    error = e.what();
    return false;
  }
}

// The widget of one of the state's parameters, with the table's tooltip.
void parameter_widget(ViewState& state, const params::Parameter& p, std::string& error) {
  std::visit(
      [&](auto* field) {
        using T = std::remove_pointer_t<decltype(field)>;
        if constexpr (std::is_same_v<T, std::string>) {
          if (text_widget(p, *field, error) && &p == &params::scene::view) go_to_viewpoint(state, *field);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          if (!*field) *field = p.default_number;
          number_widget(p, **field);
        } else {
          number_widget(p, *field);
        }
      },
      field_of(state, p));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(p).c_str());
}

// A model value's slider (the table's range and help); true when it changed. The ImGui id is
// the key with `scope`, so that equal keys of two groups (noise of the model and of a
// primitive) stay apart.
template <class T>
bool model_widget(const params::Parameter& p, T& value, const char* scope) {
  ImGui::PushID(scope);
  const bool changed = number_widget(p, value);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(p).c_str());
  ImGui::PopID();
  return changed;
}

// A skeleton point's three coordinates within the table's range.
bool point_widget(const char* label, glsl::vec3& point) {
  const params::Parameter& p = params::cloud_model::coordinate;
  const bool changed =
      ImGui::SliderFloat3(label, &point.x, float(p.min), float(p.max), "%.3f", ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(p).c_str());
  return changed;
}

bool turbulence_widgets(model::Turbulence& t, const char* scope) {
  bool changed = false;
  model::visit_turbulence(t,
                          [&](const params::Parameter& p, auto& field) { changed |= model_widget(p, field, scope); });
  return changed;
}

}  // namespace

bool shown_in_modeller(const params::Parameter& p) {
  namespace sc = params::scene;
  return &p == &sc::heading || &p == &sc::pitch || &p == &sc::fov || &p == &sc::view_steps || &p == &sc::light_steps ||
         &p == &sc::exposure;
}

void draw_model_panels(ViewState& state, std::string& error, const std::string& status) {
  namespace cm = params::cloud_model;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("nephele view --model");
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen))
    for (const params::Parameter* p : panel_parameters())
      if (shown_in_modeller(*p)) parameter_widget(state, *p, error);
  // Edits go to a copy, applied when the model stays valid (the Lipus blends need one weight:
  // a weight set on one primitive is set on all of them, as the table's help says).
  model::CloudModel next = state.model;
  bool changed = false;
  if (ImGui::CollapsingHeader("Model", ImGuiTreeNodeFlags_DefaultOpen)) {
    std::string blend = model::blend_name(next.blend);
    if (text_widget(cm::blend, blend, error)) {
      next.blend = model::parse_blend(blend, cm::blend.option());
      changed = true;
    }
    changed |= model_widget(cm::scale, next.scale, "model");
    changed |= model_widget(cm::base, next.base, "model");
    changed |= model_widget(cm::top, next.top, "model");
    if (ImGui::TreeNode("noise (global, eq. 5)")) {
      changed |= turbulence_widgets(next.noise, "model");
      ImGui::TreePop();
    }
  }
  if (ImGui::CollapsingHeader("Primitives", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::size_t i = 0; i < next.primitives.size(); ++i) {
      const model::Primitive& p = next.primitives[i];
      char label[96];
      // "###" keeps the id of the entry while its position moves.
      std::snprintf(label, sizeof label, "%zu %s (%.2f, %.2f, %.2f)###primitive%zu", i, p.segment ? "segment" : "point",
                    p.from.x, p.from.y, p.from.z, i);
      if (ImGui::Selectable(label, state.selected == int(i))) state.selected = int(i);
    }
    if (state.selected >= 0 && state.selected < int(next.primitives.size())) {
      model::Primitive& p = next.primitives[std::size_t(state.selected)];
      ImGui::Separator();
      ImGui::Text("primitive %d", state.selected);
      changed |= point_widget(p.segment ? "from" : "position", p.from);
      if (p.segment) changed |= point_widget("to", p.to);
      const float weight = p.weight;
      model::visit_primitive(p, [&](const params::Parameter& parameter, auto& field) {
        changed |= model_widget(parameter, field, "primitive");
      });
      if (p.weight != weight && next.blend != model::Blend::sum)
        for (model::Primitive& other : next.primitives) other.weight = p.weight;
      changed |= turbulence_widgets(p.noise, "primitive");
    }
  }
  if (changed) {
    try {
      model::validate(next, "");
      state.model = std::move(next);
      error.clear();
    } catch (const core::InputError& e) {
      error = e.what();
    }
  }
  if (!status.empty()) ImGui::TextWrapped("%s", status.c_str());
  if (!error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error.c_str());
  ImGui::End();
}

bool is_cover_parameter(const params::Parameter& p) {
  return p.used_by(params::cover_sidecar) || &p == &params::scene::cover_size || &p == &params::scene::seed;
}

std::vector<const params::Parameter*> panel_parameters() {
  std::vector<const params::Parameter*> out;
  for (const params::Parameter* p : params::all())
    if (p->used_by(params::viewer) && !option_only(*p)) out.push_back(p);
  return out;
}

void set_value(ViewState& state, const params::Parameter& p, const std::string& text) {
  std::visit(
      [&](auto* field) {
        using T = std::remove_pointer_t<decltype(field)>;
        if constexpr (std::is_same_v<T, std::string>) {
          if (!p.words().empty())
            params::check_word(p, text, p.option());
          else if (&p == &params::scene::time)
            check_time(p, text);
          *field = text;
          if (&p == &params::scene::view) go_to_viewpoint(state, text);
        } else {
          *field = static_cast<T>(params::parse_number(p, text, p.option()));
        }
      },
      field_of(state, p));
}

std::string value_text(ViewState& state, const params::Parameter& p) {
  return std::visit(
      [](auto* field) {
        using T = std::remove_pointer_t<decltype(field)>;
        if constexpr (std::is_same_v<T, std::string>) {
          return *field;
        } else {
          std::ostringstream s;
          s.precision(17);
          if constexpr (std::is_same_v<T, std::optional<double>>) {
            if (*field) s << **field;  // empty: left to the viewpoint
          } else {
            s << *field;
          }
          return s.str();
        }
      },
      field_of(state, p));
}

void draw_panels(ViewState& state, std::string& error) {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("nephele view");
  for (const bool cover_group : {false, true}) {
    if (!ImGui::CollapsingHeader(cover_group ? "Cover" : "View", ImGuiTreeNodeFlags_DefaultOpen)) continue;
    for (const params::Parameter* p : panel_parameters())
      if (is_cover_parameter(*p) == cover_group) parameter_widget(state, *p, error);
  }
  ImGui::Text("%.6f, %.6f, %.1f m", state.camera.latitude_deg, state.camera.longitude_deg, state.camera.height_m);
  if (!error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error.c_str());
  ImGui::End();
}

void draw_timings(const std::vector<std::pair<std::string, double>>& timings_ms, int width, int height,
                  const std::string& refinement, double frame_ms) {
  ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 8, 8), ImGuiCond_Always, ImVec2(1, 0));
  ImGui::SetNextWindowBgAlpha(0.5f);
  ImGui::Begin("times", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::Text("%dx%d %s", width, height, refinement.c_str());
  for (const auto& [name, ms] : timings_ms) ImGui::Text("%-14s %8.1f ms", name.c_str(), ms);
  ImGui::Text("%-14s %8.1f ms", "frame", frame_ms);
  ImGui::End();
}

}  // namespace nephele::viewer
