#pragma once
// The geometry of nephele view's modeller mode (--model; docs/viewer.md, "Modeller"): the
// camera that orbits the cloud, the ray through the cursor, picking a primitive, moving it in
// the plane facing the camera and resizing it. No GL here: the tests drive it directly.
#include "apps/viewer/view_state.hpp"
#include "model/cloud_model.hpp"
#include "render/model_preview.hpp"

namespace nephele::viewer {

// The state that shows `model` in the modeller: the camera and steps of nephele model's
// preview.png (from the south, 50 degrees wide, 128 view and 8 light steps, exposure 4).
ViewState modeller_state(const model::CloudModel& model);

// The preview of the modeller's state at width x height: heading, pitch and field of view of
// the state's camera turn the orbit (render::PreviewSettings), the steps come from the panels.
render::PreviewSettings preview_settings(const ViewState& state, int width, int height);

// A ray in model units (the cube [0, 1]^3, z up) with a unit direction.
struct Ray {
  glsl::vec3 origin, direction;
};
// The ray through the cursor at (x, y) (screen units from the window's top-left corner) of a
// window width x height: the preview's pixel rays (model_ray of model_march.glsl), so that
// what is picked is what the pixel under the cursor shows.
Ray cursor_ray(const ViewState& state, double x, double y, int width, int height);
// Where a model point appears in that window (screen units; the inverse of cursor_ray); the
// third component is its depth along the view (model units), <= 0 behind the camera.
glsl::vec3 project(const ViewState& state, glsl::vec3 point, int width, int height);

// The index of the primitive that the ray enters first, its solid being the sphere of radius R
// about a point or the capsule of radius R about a segment; -1 when the ray enters none.
int pick_primitive(const model::CloudModel& model, const Ray& ray);
// The distance along the ray to where it enters the primitive's solid (0 from inside); a
// negative value when it does not.
double entry_distance(const model::Primitive& primitive, const Ray& ray);

// A point, or a segment's midpoint: where a primitive is held when it is dragged.
glsl::vec3 centre(const model::Primitive& primitive);
// Where the ray meets the plane through `anchor` that faces the camera (normal: the view's
// forward axis). A drag moves the primitive by the difference of two such points, so that the
// point under the cursor stays under it.
glsl::vec3 on_facing_plane(const ViewState& state, const Ray& ray, glsl::vec3 anchor);
// `primitive` moved by `offset` (model units), its points kept in the table's coordinate range.
model::Primitive moved(const model::Primitive& primitive, glsl::vec3 offset);

// Shift + scroll on a selected primitive: each notch up multiplies its radius and influence by
// this factor (down: divides), within the table's ranges.
constexpr double resize_per_notch = 1.1;
model::Primitive resized(const model::Primitive& primitive, double notches);

// N or Insert: a copy of the selected primitive beside it (moved along the view's right axis by
// its diameter plus its influence, within the coordinate range), or with none selected a point
// at the cube's centre with the table's radius and influence and the first primitive's weight
// and turbulence; either way with a turbulence seed of its own (one above the largest in use,
// wrapping within the seed's range), so that it does not repeat its neighbour's detail. The new
// primitive is selected. width x height: the window, for the view's axes.
void add_primitive(ViewState& state, int width, int height);
// Delete or Backspace: removes the selected primitive and selects none. False, and nothing
// changes, when none is selected or it is the model's last (a model has at least one).
bool remove_selected(ViewState& state);

// A drag with nothing selected turns the camera around the cloud so that its near side follows
// the cursor: heading += dx 180 / width, pitch -= dy 180 / width (half a turn across the window).
void orbit(ViewState& state, double dx, double dy, int width);

}  // namespace nephele::viewer
