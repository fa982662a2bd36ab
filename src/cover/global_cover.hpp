#pragma once
// The global cloud cover: identity, curl, warp, density and coverage passes over cube maps.
// Needs a current OpenGL 4.5 context.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cover/cover_parameters.hpp"
#include "cover/coverage_threshold.hpp"
#include "cover/coverage_remap.hpp"
#include "cover/cube_tiles.hpp"
#include "cover/gpu_reductions.hpp"
#include "cover/latitude_profile.hpp"
#include "cover/moving_flow.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/storage_buffer.hpp"
#include "gpu/textures.hpp"
#include "cover/stability.hpp"

namespace nephele::cover {

struct PassTiming {
  std::string pass;
  double milliseconds;             // wall clock, between two glFinish
  double device_milliseconds = 0;  // GPU time by a GL_TIME_ELAPSED query (GPU passes; else 0)
};

class GlobalCover {
 public:
  // The whole cube map, or with `tile` only that region's rows (a tile of cube_tiles.hpp): its
  // maps are then 2D arrays of the tile's rows, the same texels as the whole map's to the bit.
  explicit GlobalCover(const CoverParameters& parameters, std::optional<CubeRegion> tile = std::nullopt);

  // Moves a tiled cover to another tile of the same tiling (the programs stay compiled).
  void set_tile(const CubeRegion& tile);

  // Runs every pass in order; the result stays on the GPU in cover_field(). A tile stops after
  // the density pass: its coverage needs every tile's densities (cover/tiled_cover.hpp).
  void run();

  // The passes one by one (tests run them separately).
  // The identity map (identity_field): the steady flow's warp starts from it; the other passes
  // compute each texel's direction themselves, so the moving flow makes it only when asked.
  void run_identity();
  // The curl cube map at the texel centres: the procedural curl, or in curl mode spline the
  // spline's velocity, after the spline's grid (pass "spline", run_spline) where it is missing.
  void run_curl();
  // Curl mode spline: the procedural curl on the grid of curl_size nodes per face edge and its
  // prefiltered coefficients (pass "spline"); what the warp reads. Nothing in other modes.
  void run_spline();
  // The warp of the identity map. With `after_curl` (run() sets it, straight after run_curl)
  // RK4 in curl mode spline takes its first velocity at each texel from the curl map, which
  // holds that same spline velocity; without it (the default, and the report's timings) the
  // warp evaluates every velocity itself. The results are the same bits.
  void run_warp(bool after_curl = false);
  // --flow moving: the back-trajectories of both cloud layers at the frame's time (pass "warp";
  // warp_field() the older layer's points, young_warp_field() the younger's).
  void run_moving_warp();
  // Curl mode spline with --flow moving: the flow's spline grids at the frame's time nodes
  // (pass "spline"; FrameClock's nodes), which the curl and the moving warp read.
  void run_moving_splines();
  // Sets the cover's time (--time; --flow moving), for the frames of a sequence.
  void set_time(const std::string& iso_time);
  void run_density();
  CoverageCalibration run_coverage();  // calibrates and remaps on the GPU (scalars read back); whole map only
  // The smallest and largest density the last density pass wrote.
  std::pair<float, float> density_range() const;
  // The warp pass's computation for other start points: `starts` and `warped` are RGBA32F cube
  // maps of one size (any, independent of the cover's), the curl field is this cover's.
  void warp_points(const gpu::Texture& starts, const gpu::Texture& warped);
  // Stiffness, folding and sub-steps of the warp (GPU reductions, scalars read back; after
  // run_warp). Kept for the sidecar.
  const cover::WarpDiagnostics& diagnose();
  // The diagnosis's sums over the region's owned texels (after run_warp), for tiles to add up.
  DiagnosisSums diagnosis_sums();
  const std::optional<cover::WarpDiagnostics>& diagnostics() const { return diagnostics_; }

  // The parameters as run: the curl mode and grid resolved (resolved_curl; never automatic).
  const CoverParameters& parameters() const { return parameters_; }
  const CubeRegion& region() const { return region_; }
  // The unit direction through each texel centre (RGBA32F), made by the identity pass where it
  // is not yet (the moving flow's passes do not read it).
  const gpu::Texture& identity_field() const;
  const gpu::Texture& curl_field() const { return curl_field_; }
  // The spline's coefficients: a 2D array of 6 layers of (curl_size + 2 SPLINE_MARGIN)^2
  // RGBA32F nodes (empty before run_spline and in other curl modes).
  const gpu::Texture& curl_spline() const { return spline_coefficients_; }
  const gpu::Texture& warp_field() const { return warp_field_; }
  const gpu::Texture& young_warp_field() const { return young_warp_field_; }  // --flow moving only
  const gpu::Texture& density_field() const { return density_field_; }
  const gpu::Texture& cover_field() const { return cover_field_; }
  // The cloud's optical thickness and cloud-top height (km above sea level), 0 where clear
  // (cloud_properties.glsl; after run_coverage, the top's clear texels after it too).
  const gpu::Texture& optical_thickness_field() const { return optical_thickness_field_; }
  const gpu::Texture& cloud_top_field() const { return cloud_top_field_; }
  // The share of a cloudy texel's density excess that its cover shows (cover_density.glsl's
  // cover_contrast: below 1 in the trades' shallow cumulus), from the density pass.
  const gpu::Texture& cover_contrast_field() const { return cover_contrast_field_; }
  // The ITCZ's cells the density pass read (weather_systems.glsl's itcz_cell, a vec4 per entry):
  // entry e of the older cloud layer (the steady flow's only) at e, of the moving flow's layers at
  // 2 e (the older's) and 2 e + 1 (the younger's).
  const gpu::StorageBuffer& itcz_cells() const { return itcz_cells_; }
  const CoverageCalibration& calibration() const { return coverage_.result(); }
  // The latitude profile's calibration (absent with --profile flat, whose threshold is
  // calibration().threshold).
  const std::optional<BandCalibration>& band_calibration() const { return coverage_.bands(); }
  const std::vector<PassTiming>& timings() const { return timings_; }
  // Called with a pass's name as it starts (for progress reports).
  void on_pass(std::function<void(const std::string&)> callback) { on_pass_ = std::move(callback); }

 private:
  template <class Work>
  void timed(const std::string& pass, Work&& work);
  // The moving warp from the warp grid of `cells` nodes per face edge: the trajectories from its
  // nodes by `tracer` (moving_warp.comp's WARP_GRID variant, uniforms set), once per frame, then
  // their spline at the region's texels.
  void trace_warp_grid(const gpu::ComputeProgram& tracer, int cells);
  // curl_spline.comp's moving prefilter: six faces of `samples` into layers first_layer ..
  // first_layer + 5 of `coefficients` (2D arrays; the samples one node wider on each side).
  void prefilter_faces(const gpu::Texture& samples, const gpu::Texture& coefficients, int first_layer);
  // start_velocity_in_curl: the curl map holds the velocity at `starts` (run_warp(true) only).
  void dispatch_warp(const gpu::Texture& starts, const gpu::Texture& warped, bool start_velocity_in_curl = false);
  // A map of the region: a cube map, or a 2D array of the tile's rows; make_fields (re)makes
  // every map the passes write.
  gpu::Texture make_field(GLenum internal_format) const;
  void make_fields();
  // The identity pass into identity_field_, made first where missing.
  void dispatch_identity() const;
  // Dispatches a pass over every texel of the region's maps (owned and halo).
  void dispatch_texels(const gpu::ComputeProgram& program) const;
  void upload_surface_bias();  // the land/ocean bias grid (surface_bias.hpp), once
  // The ITCZ's cells of the frame for the cloud layers of `seeds` (1 or 2), before the density;
  // once per time (set_time), not per tile.
  void make_itcz_cells(const glsl::WeatherSystems& systems, const std::vector<std::uint32_t>& seeds);

  CoverParameters parameters_;
  CubeRegion region_;
  std::function<void(const std::string&)> on_pass_;
  gpu::ComputeProgram identity_program_{"cover/identity.comp"};
  gpu::ComputeProgram curl_program_;  // the procedural curl, or the spline's velocity
  std::unique_ptr<gpu::ComputeProgram> spline_samples_program_, spline_prefilter_program_;
  gpu::ComputeProgram warp_program_;     // the integrator's and curl mode's variant
  gpu::ComputeProgram density_program_;  // with MOVING_LAYERS for --flow moving
  gpu::ComputeProgram itcz_cells_program_{"cover/itcz_cells.comp"};
  gpu::StorageBuffer itcz_cells_;
  bool itcz_cells_current_ = false;  // itcz_cells_ holds the cover's time's cells (every tile's)
  FrameClock clock_;                 // --flow moving: the frame's clock at parameters_.time (set_time renews it)
  std::unique_ptr<gpu::ComputeProgram>
      moving_warp_programs_[2];                                  // --flow moving: per texel, from the warp grid's nodes
  std::unique_ptr<gpu::ComputeProgram> warp_from_grid_program_;  // the warp grid's spline at the texels
  std::unique_ptr<gpu::ComputeProgram> moving_spline_programs_[2];  // its samples, their prefilter
  gpu::Texture flow_splines_;            // --flow moving, curl mode spline: 6 layers per time node
  std::int64_t splines_first_node_ = 0;  // the absolute index of flow_splines_'s first node
  int splines_nodes_ = 0;
  bool splines_current_ = false;           // flow_splines_ holds the window of the cover's time
  mutable gpu::Texture identity_field_;    // made on first use (identity_field())
  mutable bool identity_current_ = false;  // it holds the region's directions
  gpu::Texture curl_field_, warp_field_, density_field_, cover_field_;
  gpu::Texture optical_thickness_field_, cloud_top_field_, cover_contrast_field_;
  gpu::Texture young_warp_field_;  // --flow moving: the younger cloud layer's warp
  // --flow moving finer than --warp-grid: the trajectories' prefiltered ends at the grid's nodes,
  // 12 layers (the older layer's faces, then the younger's), and whether they are the frame's.
  gpu::Texture warp_grid_;
  bool warp_grid_current_ = false;
  gpu::Texture spline_coefficients_;
  gpu::Texture surface_bias_;  // 720 x 360 R32F with --surface, else 1 x 1 zero
  CoverageRemap coverage_;
  bool density_range_current_ = false;           // the density pass reduced the range into coverage_'s buffers
  std::unique_ptr<GpuDiagnosis> gpu_diagnosis_;  // made at the first diagnosis
  std::vector<PassTiming> timings_;
  std::optional<cover::WarpDiagnostics> diagnostics_;
};

// Bytes of GPU memory the passes allocate for a cube face size (plus the equirect export).
// The curl mode and grid a cover runs with: `p` as given, or for curl mode automatic the spline
// (steady flow), or for the moving flow the cheaper of procedural and a spline on a grid of
// min(curl_size, moving_grid_limit(step), max(64, size / 2)) nodes per face edge, by their
// counts of curl evaluations.
CoverParameters resolved_curl(CoverParameters p);
// The moving flow's finest spline grid worth its cost at the warp step h: 128 nodes per face
// edge for h >= 0.03, where the error in time dominates, else 256.
int moving_grid_limit(double step);
// The warp grid's nodes per face edge a cover traces its back-trajectories from: --warp-grid for
// the moving flow when the cover has more texels per face edge, else 0 (from every texel).
int warp_grid_cells(const CoverParameters& p);
// The density's octaves that such a cover takes from the warp grid's spline (the noise grid;
// docs/numerics.md, 8c): the first octaves whose Worley cells, 1 / (f l^k) radians, span at least
// --noise-grid-nodes of the grid's node spacing at a face's centre, 2 / cells radians; 0 without
// a warp grid or with --noise-grid-nodes 0.
int noise_grid_octaves(const CoverParameters& p);
CurlMode resolved_curl_mode(const CoverParameters& p);
double cover_gpu_bytes(int size, Flow flow = Flow::steady);

}  // namespace nephele::cover
