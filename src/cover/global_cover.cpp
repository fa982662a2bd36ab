#include "cover/global_cover.hpp"
#include "cover/weather_systems.hpp"
#include "cover/equirect.hpp"
#include "cover/moving_flow.hpp"

#include <algorithm>

#include "gpu/shader_bindings.hpp"
#include "gpu/pass_timer.hpp"
#include "shader_math/uniforms.hpp"

namespace nephele::cover {

double cover_gpu_bytes(int size, Flow flow) {
  const double texels = 6.0 * size * size;
  // Steady: identity, curl, warp, and two RGBA32F cubes the warp pass adds for long or adaptive
  // integrations (a scratch map and the adaptive state). Moving: curl, warp and the younger cloud
  // layer's warp (no identity map: its passes compute the directions, no scratch maps), and one
  // more for its warp grid's traced ends and nodes (2 x 12 x 16 x (warp_grid + 4)^2 bytes, 102
  // MiB at the default 512 nodes, about one cube of 1024) and its flow grids, 6 x 16 x
  // (curl_size + 4)^2 bytes a time node (8 nodes at the defaults: 52 MiB). Both: density, cover
  // contrast, cover, optical thickness, cloud top (R32F).
  const double cubes = texels * (16.0 * (flow == Flow::moving ? 4 : 5) + 4.0 * 5);
  // The equirect export holds one R32F tile of the 4 size x 2 size map at a time; the
  // calibration and diagnosis their tables and partial sums.
  const double equirect = std::min(8.0 * size * size, double(default_equirect_tile) * default_equirect_tile) * 4.0;
  // Curl mode spline adds its grid, at most 6 x 16 x 2 x 1030^2 bytes (200 MiB) for the
  // largest --curl-size (1024), 13 MiB for the default 256; the moving flow's warp grid, above
  // --warp-grid texels per face edge, 12 x 16 x (warp_grid + 4)^2 bytes and as much while it is
  // traced (at most 2 x 203 MiB for the largest, 1024; 2 x 51 MiB for the default 512): not counted.
  return cubes + equirect + reduction_gpu_bytes(size);
}

namespace {
bool moving(const CoverParameters& p) { return p.flow == Flow::moving; }

// The density pass's variant: two cloud layers for the moving flow, and only the cell patterns
// the cover draws (a pattern compiled in costs its search at every texel on llvmpipe).
std::vector<std::pair<std::string, std::string>> density_defines(const CoverParameters& p) {
  const CellPatterns cells = cell_patterns_drawn(p);
  return {{"MOVING_LAYERS", moving(p) ? "1" : "0"},
          {"CLOSED_CELLS_DRAWN", cells.closed ? "1" : "0"},
          {"OPEN_CELLS_DRAWN", cells.open ? "1" : "0"},
          {"STREETS_DRAWN", cells.streets ? "1" : "0"}};
}
}  // namespace

int moving_grid_limit(double step) {
  // The spline's error is mostly its grids' spacing in time (h/2): at h = 0.15 (the default) the
  // older layer's points err by 1.9e-3 rad at most with 128 nodes and 1.8e-3 with 256, at 0.0375
  // by 1.7e-4 with both, at 0.019 by 9.5e-5 and 3.5e-5 (docs/numerics.md, 8b, 2026-11-30). Finer
  // grids than 128 pay four times the evaluations for nothing until the step is below about 0.03.
  return step >= 0.03 ? 128 : 256;
}

CoverParameters resolved_curl(CoverParameters p) {
  if (p.curl_mode != CurlMode::automatic) return p;
  if (!moving(p)) {
    p.curl_mode = CurlMode::spline;
    return p;
  }
  // The grid: half the cover's texels per edge, at least 64, at most --curl-size and at most
  // the finest grid worth its cost at the step (moving_grid_limit).
  const int grid = std::min({p.curl_size, moving_grid_limit(p.step), std::max(64, p.size / 2)});
  // Curl evaluations: the spline's time nodes (a window of 3T/2, the most a frame spans), each a
  // grid of 6 grid^2, against four RK4 stages per step of each of 6 size^2 trajectories. Both
  // cost about the same per evaluation (llvmpipe: 0.6 us; docs/algorithm.md). The counts do not
  // depend on the time, so every frame of a sequence takes the same way.
  const FrameClock clock = frame_clock(p, 0.0);
  const double nodes = std::ceil(3.0 * double(p.iterations) * p.step / 2.0 / clock.node_spacing - 1e-6) + 1.0;
  const double spline = nodes * grid * grid;
  const double procedural = 4.0 * double(p.size) * p.size * (clock.young_steps + clock.older_steps);
  p.curl_mode = procedural < spline ? CurlMode::procedural : CurlMode::spline;
  if (p.curl_mode == CurlMode::spline) p.curl_size = grid;
  return p;
}

CurlMode resolved_curl_mode(const CoverParameters& p) { return resolved_curl(p).curl_mode; }

GlobalCover::GlobalCover(const CoverParameters& parameters, std::optional<CubeRegion> tile)
    : parameters_(resolved_curl(parameters)),
      region_(tile ? *tile : CubeRegion::whole(parameters.size)),
      curl_program_("cover/curl.comp", {{"CURL_FROM_SPLINE", parameters_.curl_mode == CurlMode::spline ? "1" : "0"},
                                        {"CURL_MOVING", moving(parameters) ? "1" : "0"}}),
      warp_program_("cover/warp.comp", cover::warp_defines(parameters_.integrator, parameters_.curl_mode)),
      density_program_("cover/cover_density.comp", density_defines(parameters)),
      clock_(moving(parameters) ? frame_clock(parameters, hours_since_epoch(parameters.time)) : FrameClock{}),
      coverage_(parameters_) {
  if (region_.face_size != parameters_.size)
    throw std::invalid_argument("GlobalCover: a tile of another face size than the cover's");
  // Curl mode sampled reads the curl map anywhere on the sphere: a tile does not hold it.
  if (!region_.whole_cube() && parameters_.curl_mode == CurlMode::sampled)
    throw std::invalid_argument("GlobalCover: curl mode sampled needs the whole cube map, not a tile");
  make_fields();
}

void GlobalCover::make_fields() {
  identity_field_ = gpu::Texture();
  identity_current_ = false;
  curl_field_ = make_field(GL_RGBA32F);
  warp_field_ = make_field(GL_RGBA32F);
  density_field_ = make_field(GL_R32F);
  cover_field_ = make_field(GL_R32F);
  optical_thickness_field_ = make_field(GL_R32F);
  cloud_top_field_ = make_field(GL_R32F);
  cover_contrast_field_ = make_field(GL_R32F);
  if (young_warp_field_.id()) young_warp_field_ = make_field(GL_RGBA32F);
}

void GlobalCover::set_tile(const CubeRegion& tile) {
  if (region_.whole_cube() || tile.whole_cube() || tile.face_size != region_.face_size)
    throw std::invalid_argument("GlobalCover::set_tile: not a tile of this cover's tiling");
  const bool same_shape = tile.rows == region_.rows;
  region_ = tile;
  identity_current_ = false;
  diagnostics_.reset();
  density_range_current_ = false;
  if (!same_shape) make_fields();
}

gpu::Texture GlobalCover::make_field(GLenum internal_format) const {
  if (region_.whole_cube()) return gpu::Texture::cube(region_.face_size, internal_format);
  return gpu::Texture::layered(region_.face_size, region_.rows, region_.layers, internal_format);
}

void GlobalCover::dispatch_texels(const gpu::ComputeProgram& program) const {
  program.dispatch_covering(region_.face_size, region_.rows, region_.layers);
}

template <class Work>
void GlobalCover::timed(const std::string& pass, Work&& work) {
  if (on_pass_) on_pass_(pass);
  const gpu::PassTimes times = gpu::time_pass_and_device(work);
  timings_.push_back({pass, times.wall_ms, times.device_ms});
}

void GlobalCover::run() {
  if (moving(parameters_)) {
    if (parameters_.curl_mode == CurlMode::spline) run_moving_splines();
    run_curl();
    run_moving_warp();
  } else {
    run_identity();  // the warp's start points
    // The spline's grid is the same for every tile: made for the first only.
    if (region_.whole_cube() || !spline_coefficients_.id()) run_spline();
    run_curl();
    run_warp(true);
  }
  run_density();
  if (region_.whole_cube()) run_coverage();
}

void GlobalCover::set_time(const std::string& iso_time) {
  parameters_.time = iso_time;
  clock_ = frame_clock(parameters_, hours_since_epoch(iso_time));
  splines_current_ = false;  // run_moving_splines keeps the grids of nodes the new window shares
  warp_grid_current_ = false;
  itcz_cells_current_ = false;
}

void GlobalCover::run_moving_splines() {
  const FrameClock& clock = clock_;
  timed("spline", [&] {
    const int cells = parameters_.curl_size;
    const int margin = glsl::SPLINE_MARGIN;
    const int extent = cells + 2 * margin;
    if (!moving_spline_programs_[0])
      moving_spline_programs_[0] = std::make_unique<gpu::ComputeProgram>(
          "cover/curl_spline.comp", std::vector<std::pair<std::string, std::string>>{{"CURL_SPLINE_PREFILTER", "0"},
                                                                                     {"CURL_SPLINE_MOVING", "1"}});
    // The grids of the window's nodes; those the last frame made are copied, not made again
    // (a node's grid depends on its index only: node_time).
    gpu::Texture grids = gpu::Texture::layered(extent, extent, 6 * clock.nodes, GL_RGBA32F);
    // The samples reach one node further than the coefficients: the prefilter's neighbours.
    const int samples_extent = cells + 2 * (margin + 1);
    gpu::Texture samples;
    const gpu::ComputeProgram& sampler = *moving_spline_programs_[0];
    glsl::set_uniform(sampler, "u_curl", curl_params(parameters_));
    sampler.set("u_noise_offset", potential_offset(parameters_));
    sampler.set("u_cells", cells);
    for (int k = 0; k < clock.nodes; ++k) {
      const std::int64_t node = clock.first_node + k;
      if (flow_splines_.id() && node >= splines_first_node_ && node < splines_first_node_ + splines_nodes_) {
        glCopyImageSubData(flow_splines_.id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0,
                           static_cast<GLint>(6 * (node - splines_first_node_)), grids.id(), GL_TEXTURE_2D_ARRAY, 0, 0,
                           0, 6 * k, extent, extent, 6);
        continue;
      }
      if (!samples.id()) samples = gpu::Texture::layered(samples_extent, samples_extent, 6, GL_RGBA32F);
      const NodeTime at = node_time(parameters_, node);
      glsl::set_uniform(sampler, "u_motion", at.motion);
      sampler.set("u_node_time", at.time);
      samples.bind_image(shader_bindings::cover_curl_spline::samples, GL_WRITE_ONLY);
      sampler.dispatch_covering(samples_extent, samples_extent, 6);
      gpu::image_barrier();
      prefilter_faces(samples, grids, 6 * k);
    }
    flow_splines_ = std::move(grids);
    splines_first_node_ = clock.first_node;
    splines_nodes_ = clock.nodes;
    splines_current_ = true;
  });
}

void GlobalCover::prefilter_faces(const gpu::Texture& samples, const gpu::Texture& coefficients, int first_layer) {
  if (!moving_spline_programs_[1])
    moving_spline_programs_[1] = std::make_unique<gpu::ComputeProgram>(
        "cover/curl_spline.comp",
        std::vector<std::pair<std::string, std::string>>{{"CURL_SPLINE_PREFILTER", "1"}, {"CURL_SPLINE_MOVING", "1"}});
  const gpu::ComputeProgram& prefilter = *moving_spline_programs_[1];
  samples.bind_image(shader_bindings::cover_curl_spline::samples, GL_READ_ONLY);
  coefficients.bind_image(shader_bindings::cover_curl_spline::coefficients, GL_WRITE_ONLY);
  prefilter.set("u_first_layer", first_layer);
  prefilter.dispatch_covering(coefficients.width(), coefficients.height(), 6);
  gpu::image_barrier();
}

int warp_grid_cells(const CoverParameters& p) {
  return moving(p) && p.warp_grid > 0 && p.warp_grid < p.size ? p.warp_grid : 0;
}

int noise_grid_octaves(const CoverParameters& p) {
  const int cells = warp_grid_cells(p);
  if (cells == 0 || p.noise_grid_nodes <= 0.0f) return 0;
  int octaves = 0;
  double frequency = p.density.frequency;
  while (octaves < p.density.octaves && cells / (2.0 * frequency) >= p.noise_grid_nodes) {
    ++octaves;
    frequency *= p.density.lacunarity;
  }
  return octaves;
}

void GlobalCover::run_moving_warp() {
  const FrameClock& clock = clock_;
  const bool spline = parameters_.curl_mode == CurlMode::spline;
  if (spline && !splines_current_) run_moving_splines();
  const int grid = warp_grid_cells(parameters_);
  timed("warp", [&] {
    std::unique_ptr<gpu::ComputeProgram>& made = moving_warp_programs_[grid > 0 ? 1 : 0];
    if (!made)
      made = std::make_unique<gpu::ComputeProgram>(
          "cover/moving_warp.comp", std::vector<std::pair<std::string, std::string>>{
                                        {"MOVING_SPLINE", spline ? "1" : "0"}, {"WARP_GRID", grid > 0 ? "1" : "0"}});
    if (!young_warp_field_.id()) young_warp_field_ = make_field(GL_RGBA32F);
    const gpu::ComputeProgram& program = *made;
    namespace warp = shader_bindings::cover_moving_warp;
    glsl::set_uniform(program, "u_curl", curl_params(parameters_));
    glsl::set_uniform(program, "u_motion", clock.motion);
    if (spline) {
      program.set("u_first_node_time", clock.first_node_time);
      program.set("u_node_spacing", clock.node_spacing);
      flow_splines_.bind_image(warp::flow_splines, GL_READ_ONLY);
    } else {
      program.set("u_noise_offset", potential_offset(parameters_));
    }
    program.set("u_time", clock.time);
    program.set("u_old_age", clock.old_age);
    program.set("u_young_age", clock.young_age);
    program.set("u_young_steps", clock.young_steps);
    program.set("u_older_steps", clock.older_steps);
    if (grid > 0) {
      trace_warp_grid(program, grid);
      return;
    }
    set_region(program, region_);
    warp_field_.bind_image_layers(warp::warp_field, GL_WRITE_ONLY);
    young_warp_field_.bind_image_layers(warp::young_warp_field, GL_WRITE_ONLY);
    dispatch_texels(program);
    gpu::image_barrier();
  });
}

void GlobalCover::trace_warp_grid(const gpu::ComputeProgram& tracer, int cells) {
  // The grid is the whole cube's, the same for every tile of a frame: traced once per time.
  if (!warp_grid_current_) {
    namespace warp = shader_bindings::cover_moving_warp;
    const int margin = glsl::SPLINE_MARGIN;
    const int extent = cells + 2 * margin;
    // The samples reach one node further than the coefficients: the prefilter's neighbours.
    const int samples_extent = cells + 2 * (margin + 1);
    const gpu::Texture older = gpu::Texture::layered(samples_extent, samples_extent, 6, GL_RGBA32F);
    const gpu::Texture younger = gpu::Texture::layered(samples_extent, samples_extent, 6, GL_RGBA32F);
    tracer.set("u_grid_cells", cells);
    // The noise grid: the cover noise's first octaves of both layers at the nodes' points.
    tracer.set("u_grid_octaves", noise_grid_octaves(parameters_));
    glsl::set_uniform(tracer, "u_cover",
                      layer_density_params(parameters_, clock_.young_layer - 1, clock_.layers_in_loop));
    glsl::set_uniform(tracer, "u_young_cover",
                      layer_density_params(parameters_, clock_.young_layer, clock_.layers_in_loop));
    tracer.set("u_density_offset", density_offset(parameters_));
    older.bind_image(warp::warp_field, GL_WRITE_ONLY);
    younger.bind_image(warp::young_warp_field, GL_WRITE_ONLY);
    tracer.dispatch_covering(samples_extent, samples_extent, 6);
    gpu::image_barrier();
    if (warp_grid_.width() != extent) warp_grid_ = gpu::Texture::layered(extent, extent, 12, GL_RGBA32F);
    prefilter_faces(older, warp_grid_, 0);
    prefilter_faces(younger, warp_grid_, 6);
    warp_grid_current_ = true;
  }
  if (!warp_from_grid_program_)
    warp_from_grid_program_ = std::make_unique<gpu::ComputeProgram>("cover/warp_from_grid.comp");
  namespace from_grid = shader_bindings::cover_warp_from_grid;
  set_region(*warp_from_grid_program_, region_);
  warp_grid_.bind_image(from_grid::warp_grid, GL_READ_ONLY);
  warp_field_.bind_image_layers(from_grid::warp_field, GL_WRITE_ONLY);
  young_warp_field_.bind_image_layers(from_grid::young_warp_field, GL_WRITE_ONLY);
  dispatch_texels(*warp_from_grid_program_);
  gpu::image_barrier();
}

void GlobalCover::run_identity() {
  timed("identity", [&] { dispatch_identity(); });
}

void GlobalCover::dispatch_identity() const {
  if (!identity_field_.id()) identity_field_ = make_field(GL_RGBA32F);
  identity_field_.bind_image_layers(shader_bindings::cover_identity::identity_field, GL_WRITE_ONLY);
  set_region(identity_program_, region_);
  dispatch_texels(identity_program_);
  gpu::image_barrier();
  identity_current_ = true;
}

const gpu::Texture& GlobalCover::identity_field() const {
  if (!identity_current_) dispatch_identity();
  return identity_field_;
}

void GlobalCover::run_spline() {
  if (parameters_.curl_mode != CurlMode::spline) return;
  timed("spline", [&] {
    const int cells = parameters_.curl_size;
    const int margin = glsl::SPLINE_MARGIN;
    if (!spline_samples_program_) {
      spline_samples_program_ = std::make_unique<gpu::ComputeProgram>(
          "cover/curl_spline.comp", std::vector<std::pair<std::string, std::string>>{{"CURL_SPLINE_PREFILTER", "0"}});
      spline_prefilter_program_ = std::make_unique<gpu::ComputeProgram>(
          "cover/curl_spline.comp", std::vector<std::pair<std::string, std::string>>{{"CURL_SPLINE_PREFILTER", "1"}});
      spline_coefficients_ = gpu::Texture::layered(cells + 2 * margin, cells + 2 * margin, 6, GL_RGBA32F);
    }
    // The samples reach one node further than the coefficients: the prefilter's neighbours.
    const int samples_extent = cells + 2 * (margin + 1);
    const gpu::Texture samples = gpu::Texture::layered(samples_extent, samples_extent, 6, GL_RGBA32F);
    glsl::set_uniform(*spline_samples_program_, "u_curl", curl_params(parameters_));
    spline_samples_program_->set("u_noise_offset", potential_offset(parameters_));
    spline_samples_program_->set("u_cells", cells);
    samples.bind_image(shader_bindings::cover_curl_spline::samples, GL_WRITE_ONLY);
    spline_samples_program_->dispatch_covering(samples_extent, samples_extent, 6);
    gpu::image_barrier();
    samples.bind_image(shader_bindings::cover_curl_spline::samples, GL_READ_ONLY);
    spline_coefficients_.bind_image(shader_bindings::cover_curl_spline::coefficients, GL_WRITE_ONLY);
    spline_prefilter_program_->dispatch_covering(cells + 2 * margin, cells + 2 * margin, 6);
    gpu::image_barrier();
  });
}

void GlobalCover::run_curl() {
  const bool spline = !moving(parameters_) && parameters_.curl_mode == CurlMode::spline;
  if (spline && !spline_coefficients_.id()) run_spline();
  timed("curl", [&] {
    if (moving(parameters_)) {
      const FrameClock& clock = clock_;
      curl_program_.set("u_time", clock.time);
      if (parameters_.curl_mode == CurlMode::spline) {
        if (!splines_current_) run_moving_splines();
        curl_program_.set("u_first_node_time", clock.first_node_time);
        curl_program_.set("u_node_spacing", clock.node_spacing);
        glsl::set_uniform(curl_program_, "u_curl", curl_params(parameters_));
        glsl::set_uniform(curl_program_, "u_motion", clock.motion);
        flow_splines_.bind_image(shader_bindings::cover_curl::curl_spline, GL_READ_ONLY);
      } else {
        glsl::set_uniform(curl_program_, "u_curl", curl_params(parameters_));
        curl_program_.set("u_noise_offset", potential_offset(parameters_));
        glsl::set_uniform(curl_program_, "u_motion", clock.motion);
      }
    } else if (spline) {
      spline_coefficients_.bind_image(shader_bindings::cover_curl::curl_spline, GL_READ_ONLY);
    } else {
      glsl::set_uniform(curl_program_, "u_curl", curl_params(parameters_));
      curl_program_.set("u_noise_offset", potential_offset(parameters_));
    }
    set_region(curl_program_, region_);
    curl_field_.bind_image_layers(shader_bindings::cover_curl::curl_field, GL_WRITE_ONLY);
    dispatch_texels(curl_program_);
    gpu::image_barrier();
  });
}

void GlobalCover::run_warp(bool after_curl) {
  timed("warp", [&] { dispatch_warp(identity_field(), warp_field_, after_curl); });
}

void GlobalCover::warp_points(const gpu::Texture& starts, const gpu::Texture& warped) { dispatch_warp(starts, warped); }

void GlobalCover::dispatch_warp(const gpu::Texture& starts, const gpu::Texture& warped, bool start_velocity_in_curl) {
  const CoverParameters& p = parameters_;
  const bool adaptive = p.integrator == cover::Integrator::adaptive;
  warp_program_.set("u_step_size", p.step);
  if (adaptive) {
    // The flow time in double first: K h is the physical quantity, rounded once.
    const float flow_time = static_cast<float>(static_cast<double>(p.iterations) * p.step);
    warp_program_.set("u_flow_time", flow_time);
    warp_program_.set("u_max_step", flow_time);
    warp_program_.set("u_tolerance", p.tolerance);
    warp_program_.set("u_max_substeps", p.max_substeps);
  }
  if (p.curl_mode == cover::CurlMode::procedural) {
    glsl::set_uniform(warp_program_, "u_curl", curl_params(p));
    warp_program_.set("u_noise_offset", potential_offset(p));
  }
  // The warp reads the curl map as a cube map in curl mode sampled (anywhere on the sphere),
  // else at its own texel (warp.comp).
  if (p.curl_mode == CurlMode::sampled)
    curl_field_.bind_image(shader_bindings::cover_warp::curl_field, GL_READ_ONLY);
  else
    curl_field_.bind_image_layers(shader_bindings::cover_warp::curl_field, GL_READ_ONLY);
  if (p.curl_mode == CurlMode::spline) {
    if (!spline_coefficients_.id()) run_spline();
    spline_coefficients_.bind_image(shader_bindings::cover_warp::curl_spline, GL_READ_ONLY);
  }
  // Long integrations run over several dispatches (cover::shader_loop_budget): each one
  // continues from the points of the last, alternating between `warped` and a scratch map.
  const int size = warped.width();
  const int per_dispatch = cover::steps_per_dispatch(p.integrator, p.curl_mode, p.potential.octaves);
  gpu::Texture scratch;
  auto target = [&](bool into_warped) -> const gpu::Texture& {
    if (into_warped) return warped;
    if (!scratch.id()) scratch = gpu::Texture::shaped_like(warped, GL_RGBA32F);
    return scratch;
  };
  auto dispatch = [&](const gpu::Texture& from, const gpu::Texture& to) {
    from.bind_image_layers(shader_bindings::cover_warp::identity_field, GL_READ_ONLY);
    to.bind_image_layers(shader_bindings::cover_warp::warp_field, GL_WRITE_ONLY);
    warp_program_.dispatch_covering(size, to.height(), to.layers());
    gpu::image_barrier();
  };
  if (!adaptive) {
    const int rounds = std::max(1, (p.iterations + per_dispatch - 1) / per_dispatch);
    const gpu::Texture* from = &starts;
    // In curl mode spline the curl pass stored spline_velocity at each identity texel, the
    // same function of the same point as the warp's first velocity: RK4 may start from it.
    // (Only RK4 reads it; the other schemes' programs have no such uniform.)
    const bool start_velocity = start_velocity_in_curl && p.curl_mode == CurlMode::spline;
    const bool takes_start_velocity = warp_program_.has_uniform("u_start_velocity");
    for (int round = 0; round < rounds; ++round) {
      if (takes_start_velocity) warp_program_.set("u_start_velocity", start_velocity && round == 0 ? 1 : 0);
      warp_program_.set("u_steps", std::min(per_dispatch, p.iterations - round * per_dispatch));
      const gpu::Texture& to = target((rounds - 1 - round) % 2 == 0);  // the last round writes `warped`
      dispatch(*from, to);
      from = &to;
    }
    return;
  }
  // Adaptive: each texel keeps its state between dispatches; the rounds end when no texel is
  // unfinished below its sub-step limit (a counter the shader increments).
  const gpu::Texture state = gpu::Texture::shaped_like(warped, GL_RGBA32F);
  state.bind_image_layers(shader_bindings::cover_warp::adaptive_state, GL_READ_WRITE);
  const gpu::StorageBuffer counter(sizeof(GLuint));
  counter.bind(shader_bindings::cover_warp::unfinished);
  warp_program_.set("u_chunk", per_dispatch);
  const gpu::Texture* from = &starts;
  bool in_warped = true;
  for (int round = 0; round * static_cast<long>(per_dispatch) < std::max(1, p.max_substeps); ++round) {
    const GLuint zero = 0;
    counter.write(&zero, sizeof zero);
    warp_program_.set("u_resume", round > 0 ? 1 : 0);
    in_warped = round % 2 == 0;
    const gpu::Texture& to = target(in_warped);
    dispatch(*from, to);
    from = &to;
    GLuint unfinished = 0;
    counter.read(&unfinished, sizeof unfinished);
    if (unfinished == 0) break;
  }
  if (!in_warped) {
    glCopyImageSubData(scratch.id(), scratch.target(), 0, 0, 0, 0, warped.id(), warped.target(), 0, 0, 0, 0, size,
                       warped.height(), warped.layers());
    gpu::image_barrier();
  }
}

const cover::WarpDiagnostics& GlobalCover::diagnose() {
  timed("diagnose", [&] {
    if (!gpu_diagnosis_) gpu_diagnosis_ = std::make_unique<GpuDiagnosis>(parameters_.size);
    diagnostics_ = diagnostics_from_sums(
        gpu_diagnosis_->sums(curl_field_, warp_field_, region_, parameters_.integrator, parameters_.step),
        gpu_diagnosis_->units(), parameters_.integrator, parameters_.step, moving(parameters_));
  });
  return *diagnostics_;
}

DiagnosisSums GlobalCover::diagnosis_sums() {
  DiagnosisSums sums;
  timed("diagnose", [&] {
    if (!gpu_diagnosis_) gpu_diagnosis_ = std::make_unique<GpuDiagnosis>(parameters_.size);
    sums = gpu_diagnosis_->sums(curl_field_, warp_field_, region_, parameters_.integrator, parameters_.step);
  });
  return sums;
}

std::pair<float, float> GlobalCover::density_range() const { return coverage_.calibration().read_density_range(); }

void GlobalCover::upload_surface_bias() {
  // Without a mask a 1 x 1 texture keeps the sampler complete (the weight is 0 then; all sea).
  // Its terms (deck, desert, sea) in red, green and blue: the density takes the first two's
  // difference, the decks the first, the cold air's cells the sea's share.
  if (parameters_.surface) {
    surface_bias_ = gpu::Texture::plane(surface_bias_columns, surface_bias_rows, GL_RGB32F);
    surface_bias_.write(surface_terms(*parameters_.surface));
  } else {
    surface_bias_ = gpu::Texture::plane(1, 1, GL_RGB32F);
    surface_bias_.write({0.0f, 0.0f, 1.0f});
  }
  glTextureParameteri(surface_bias_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(surface_bias_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(surface_bias_.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(surface_bias_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void GlobalCover::make_itcz_cells(const glsl::WeatherSystems& systems, const std::vector<std::uint32_t>& seeds) {
  if (!itcz_cells_current_) {
    const size_t entries = seeds.size() * static_cast<size_t>(glsl::ITCZ_TABLE_CELLS);
    gpu::reserve(itcz_cells_, entries * sizeof(glsl::vec4));
    itcz_cells_.bind(shader_bindings::cover_itcz_cells::itcz_cells);
    glsl::set_uniform(itcz_cells_program_, "u_systems", systems);
    for (size_t layer = 0; layer < seeds.size(); ++layer) {
      itcz_cells_program_.set("u_seed", seeds[layer]);
      itcz_cells_program_.set("u_layers", static_cast<int>(seeds.size()));
      itcz_cells_program_.set("u_layer", static_cast<int>(layer));
      itcz_cells_program_.dispatch_covering(glsl::ITCZ_TABLE_CELLS, 1, 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    itcz_cells_current_ = true;
  }
  itcz_cells_.bind(shader_bindings::cover_cover_density::itcz_cells);
}

void GlobalCover::run_density() {
  timed("density", [&] {
    glsl::set_uniform(density_program_, "u_cover", density_params(parameters_));
    density_program_.set("u_noise_offset", density_offset(parameters_));
    density_program_.set("u_grid_octaves", noise_grid_octaves(parameters_));
    density_program_.set("u_cyclone_cloudiness", parameters_.cyclone_cloudiness);
    density_program_.set("u_surface_weight", parameters_.surface ? parameters_.surface_weight : 0.0f);
    // The steady flow's cover does not change with the time; the moving flow's systems live on it,
    // and its two cloud layers draw their belts with their own noise (the older's in u_systems).
    glsl::WeatherSystems systems =
        weather_systems(parameters_, moving(parameters_) ? hours_since_epoch(parameters_.time) : 0.0);
    // The cloud layers' belts' seeds: the older's (the steady flow's only), then the younger's.
    std::vector<std::uint32_t> seeds{systems.seed};
    if (moving(parameters_)) {
      seeds = {layer_systems_seed(parameters_, clock_.young_layer - 1, clock_.layers_in_loop),
               layer_systems_seed(parameters_, clock_.young_layer, clock_.layers_in_loop)};
      systems.seed = seeds[0];
      density_program_.set("u_young_systems_seed", seeds[1]);
    }
    glsl::set_uniform(density_program_, "u_systems", systems);
    make_itcz_cells(systems, seeds);
    if (!surface_bias_.id()) upload_surface_bias();
    namespace density = shader_bindings::cover_cover_density;
    if (moving(parameters_)) {
      const FrameClock& clock = clock_;
      glsl::set_uniform(density_program_, "u_cover",
                        layer_density_params(parameters_, clock.young_layer - 1, clock.layers_in_loop));
      glsl::set_uniform(density_program_, "u_young_cover",
                        layer_density_params(parameters_, clock.young_layer, clock.layers_in_loop));
      density_program_.set("u_young_share", clock.young_share);
      young_warp_field_.bind_image_layers(density::young_warp_field, GL_READ_ONLY);
    }
    warp_field_.bind_image_layers(density::warp_field, GL_READ_ONLY);
    density_field_.bind_image_layers(density::density_field, GL_WRITE_ONLY);
    cloud_top_field_.bind_image_layers(density::cloud_top_field, GL_WRITE_ONLY);
    cover_contrast_field_.bind_image_layers(density::cover_contrast_field, GL_WRITE_ONLY);
    curl_field_.bind_image_layers(density::curl_field, GL_READ_ONLY);
    glBindTextureUnit(density::surface_bias, surface_bias_.id());
    // The pass also reduces the density range for the calibration; an invocation per strip of
    // reduction_strip texels of a column of the region's owned rows.
    coverage_.calibration().bind_density_range();
    set_region(density_program_, region_);
    const int strip = density_strip(parameters_.size);
    density_program_.set("u_strip", strip);
    density_program_.dispatch_covering(parameters_.size, (region_.owned_rows() + strip - 1) / strip, region_.layers);
    gpu::image_barrier();
  });
  density_range_current_ = true;
}

CoverageCalibration GlobalCover::run_coverage() {
  if (!region_.whole_cube())
    throw std::logic_error("GlobalCover::run_coverage: a tile's coverage needs every tile (cover/tiled_cover.hpp)");
  timed("calibrate", [&] {
    std::optional<std::pair<float, float>> range;
    if (density_range_current_) range = density_range();
    coverage_.calibrate(whole_cube(density_field_), range);
  });
  timed("coverage", [&] {
    coverage_.begin_remap();
    coverage_.remap(density_field_, cover_contrast_field_, {cover_field_, optical_thickness_field_, cloud_top_field_},
                    region_);
    coverage_.finish_remap();
  });
  return coverage_.result();
}

}  // namespace nephele::cover
