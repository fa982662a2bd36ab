#pragma once
// What the window shows, behind one interface: the ground renderer and the orbit renderer,
// chosen per frame by ViewSwitch (make_view_source).
#include "params/render_quality.hpp"
#include <filesystem>
#include <optional>
#include <memory>
#include <string>
#include <vector>

#include "apps/viewer/view_state.hpp"
#include "io/coastline_files.hpp"
#include "regional/weather.hpp"
#include "model/density_volume.hpp"
#include "render/cloud_renderer.hpp"
#include "render/model_preview.hpp"
#include "render/orbit_renderer.hpp"
#include "render/scene_renderer.hpp"

namespace nephele::viewer {

class ViewSource {
 public:
  virtual ~ViewSource() = default;
  virtual std::string name() const = 0;
  // The linear radiance of the view of `state` at width x height (passes and their times in
  // the result). Runs in the current GL context (the window's). Slow work that a change of the
  // state needs once (a cover, a noise volume) is kept for the next calls.
  // `first_row` and `row_count` (0: every row) select a band of rows of the width x height
  // image; the other rows of the result are undefined. `coarse`: a preview that the full size
  // will replace, which a source may render with fewer steps (the ground view: preview_steps).
  virtual render::RenderResult render(const ViewState& state, int width, int height, int first_row = 0,
                                      int row_count = 0, bool coarse = false) = 0;
  // Asks the following renders of whole images to march only one pixel of each stride x stride
  // block at `phase` (render::RenderSettings::march_stride; stride 1: all). A source that
  // cannot (the orbit view, the modeller) renders every pixel; RenderResult::march_stride says
  // which happened.
  virtual void set_march_lattice(int /*stride*/, glm::ivec2 /*phase*/) {}
};

// The ground view's steps for coarse (preview) frames: the draft quality's (8 view x 2 light,
// params/render_quality.hpp; display rms about 0.01 at 1280 x 720 with its 1/8 resolution,
// docs/rendering.md); the full-size bands keep the scene's steps, so the finished image is
// `nephele render`'s at full resolution.
struct PreviewSteps {
  int view = params::render_qualities[0].view_steps, light = params::render_qualities[0].light_steps;
};
static_assert(params::render_qualities[0].name == std::string_view("draft"));
constexpr PreviewSteps preview_steps{};
// While the camera moves, the quarter-size preview marches one pixel of each 2 x 2 block and
// reprojects the other three from the last preview (render/reprojection.hpp): a quarter of the
// clouds pass, every pixel marched again within four frames.
constexpr int preview_march_stride = 2;

// The ground view (render::prepare_scene, render_prepared): the global cover from `cover_dir`
// when given (a directory written by nephele generate), else made from the state's cover
// parameters; station weather when the state names files. The noise volume comes from the
// disk cache at `cache_directory` (empty: none).
class GroundSource : public ViewSource {
 public:
  GroundSource(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory);
  std::string name() const override { return "ground"; }
  render::RenderResult render(const ViewState& state, int width, int height, int first_row = 0, int row_count = 0,
                              bool coarse = false) override;
  void set_march_lattice(int stride, glm::ivec2 phase) override {
    march_stride_ = stride;
    march_phase_ = phase;
  }

 private:
  int march_stride_ = 1;
  glm::ivec2 march_phase_{0, 0};
  std::filesystem::path cache_directory_;
  bool cover_from_files_ = false;
  render::GlobalCoverFaces cover_;
  std::string cover_key_;  // the parameters cover_ was made with
  std::vector<regional::WeatherSeries> stations_;
  std::vector<std::string> station_files_;
  std::unique_ptr<render::NoiseVolume> noise_;
  // The ground's height grid is centred on the camera: made again only when the camera moved.
  std::shared_ptr<const regional::TerrainGrid> terrain_;
  std::string terrain_key_;
  std::shared_ptr<render::ShadowMapCache> shadow_maps_ = std::make_shared<render::ShadowMapCache>();
};

// The orbit view (render::OrbitRenderer): the planet's maps of io::read_planet_textures (the
// xplanet maps, else a procedural planet with a warning) and the cover of `cover_dir`, else made
// from the state's cover parameters. The camera's height is the altitude above the sphere.
// From low orbit, with the default maps, the coasts and lakes in view come from GSHHG's
// shorelines as in `nephele render` (io::view_coast_window): a window with a margin around the
// ground in view, rastered again only when the ground in view leaves it or the camera has come
// down far enough to need texels twice as fine (in the frame that needs it: a frame depends on
// its camera and the window, never on a thread's timing), and dropped only where the nearest
// pixels are coarser than the water map's texel (four times coarser than where one is wanted).
class OrbitSource : public ViewSource {
 public:
  // `cache_directory`: the generated covers' disk cache (io/cover_cache.hpp; empty: none).
  OrbitSource(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory);
  ~OrbitSource() override;
  std::string name() const override { return "orbit"; }
  // Renders the tiles that hold rows [first_row, first_row + row_count) (all with row_count 0);
  // `coarse` is ignored (the orbit pass's steps follow the pixel's footprint).
  render::RenderResult render(const ViewState& state, int width, int height, int first_row = 0, int row_count = 0,
                              bool coarse = false) override;
  // The coast window the renders use now (none: the water map alone).
  std::optional<io::GeoWindow> coast_window() const { return coast_window_; }

 private:
  // Rasters a window where the camera's view needs one the current one does not give.
  void update_coast(const render::OrbitCamera& camera, std::vector<std::pair<std::string, double>>& setup_ms);

  std::filesystem::path cover_dir_;
  std::filesystem::path cache_directory_;
  std::unique_ptr<render::OrbitRenderer> renderer_;
  std::string cover_key_;
  bool sea_colour_ = false;  // the default maps: the sea's own colour, coasts from GSHHG
  int water_width_ = 0;
  std::optional<io::GeoWindow> coast_window_;  // uploaded
};

// The view nephele view shows: the orbit renderer where orbit_share(state) is 1, the ground's
// where it is 0, and between (12 to 20 km) both with their radiance mixed by the share. In
// that band a frame costs both renders.
class ViewSwitch : public ViewSource {
 public:
  ViewSwitch(const std::filesystem::path& cover_dir, const std::filesystem::path& cache_directory);
  std::string name() const override { return "ground or orbit"; }
  render::RenderResult render(const ViewState& state, int width, int height, int first_row = 0, int row_count = 0,
                              bool coarse = false) override;
  void set_march_lattice(int stride, glm::ivec2 phase) override { ground_.set_march_lattice(stride, phase); }

 private:
  GroundSource ground_;
  OrbitSource orbit_;
};

// The modeller's view (nephele view --model): the density volume of the state's cloud model
// (model::DensityVolume, size^3) through the model preview (render::PreviewRenderer), the
// camera orbiting the cloud. Each render brings the volume up to the state's model first: one
// primitive changed is the incremental edit (only the bricks of its old and new footprints),
// anything else a whole recompute. Bands of rows are marched alone, as the ground view's.
class ModelSource : public ViewSource {
 public:
  explicit ModelSource(int size);
  ~ModelSource() override;
  std::string name() const override { return "model"; }
  render::RenderResult render(const ViewState& state, int width, int height, int first_row = 0, int row_count = 0,
                              bool coarse = false) override;
  // The volume as of the last render (nullptr before the first).
  const model::DensityVolume* volume() const { return volume_.get(); }

 private:
  int size_;
  std::unique_ptr<model::DensityVolume> volume_;
  std::unique_ptr<render::PreviewRenderer> preview_;
};

std::unique_ptr<ViewSource> make_view_source(const std::filesystem::path& cover_dir,
                                             const std::filesystem::path& cache_directory);

}  // namespace nephele::viewer
