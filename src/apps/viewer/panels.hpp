#pragma once
// Dear ImGui panels made from the parameter table: one widget per parameter that nephele view
// takes (params::viewer), in table order, chosen by its type and range (slider or drag within
// the range, combo of the allowed words, text checked on Enter), the help text as tooltip.
#include <string>
#include <utility>
#include <vector>

#include "apps/viewer/view_state.hpp"

namespace nephele::viewer {

// The panels' groups: parameters of the global cover, and those of the view.
bool is_cover_parameter(const params::Parameter& p);
// The parameters the panels show, in table order: the table's viewer parameters less the
// options-only ones.
std::vector<const params::Parameter*> panel_parameters();

// Sets the field of `p` from text, checked as the command line checks it (core::InputError
// naming the parameter's option): the panels' text fields and the tests use it.
void set_value(ViewState& state, const params::Parameter& p, const std::string& text);
// Text of the field of `p` ("48", "euler").
std::string value_text(ViewState& state, const params::Parameter& p);

// Draws the panels (inside an ImGui frame); edits change `state` directly. `error` keeps the
// last refused text entry's message between frames.
void draw_panels(ViewState& state, std::string& error);
// The parameters of the View panel that the modeller's preview uses (the camera's heading,
// pitch and field of view turn the orbit; the steps and exposure as in nephele model).
bool shown_in_modeller(const params::Parameter& p);
// The modeller's panels (nephele view --model): View (the parameters above), Model (blend,
// scale, global noise) and Primitives (the list, and the selected one's skeleton, radius,
// influence, weight and noise): every slider made from the parameter table through
// model::visit_primitive and visit_turbulence. An edit that the model's checks refuse is not
// applied; `error` says why. `status` is shown under them (the last save).
void draw_model_panels(ViewState& state, std::string& error, const std::string& status);
// The overlay of times: the last render's passes, its size, and the frame time.
void draw_timings(const std::vector<std::pair<std::string, double>>& timings_ms, int width, int height,
                  const std::string& refinement, double frame_ms);

}  // namespace nephele::viewer
