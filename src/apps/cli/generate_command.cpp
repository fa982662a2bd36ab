// nephele generate: the global cloud cover, written as cube map faces, equirect and sidecar.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <iostream>
#include <memory>
#include <optional>

#include "apps/cli/commands.hpp"
#include "apps/cli/cover_exports.hpp"
#include "core/json.hpp"
#include "core/progress.hpp"
#include "core/time.hpp"
#include "files/image_files.hpp"
#include "params/table.hpp"
#include "apps/cli/cover_options.hpp"
#include "cover/cover_limits.hpp"
#include "cover/equirect.hpp"
#include "render/render_limits.hpp"
#include "files/atomic_output.hpp"
#include "io/cover_assembly.hpp"
#include "io/cover_files.hpp"
#include "io/cover_tiles.hpp"
#include "cover/tiled_cover.hpp"
#include "io/export_presets.hpp"
#include "params/values.hpp"

namespace nephele::cli {

namespace {

constexpr int sequence_preview_fps = 8;

// generate --sequence: N covers at --time + k --interval, each a whole cover set in frame_NNNN/,
// with sequence.json listing them and sequence.gif showing their equirect maps; all of it one
// output set (it appears whole or not at all). Each frame depends on the seed and its time only.
template <class RunCover, class WriteCover>
void write_sequence(files::OutputSet& outputs, cover::GlobalCover& cover, const cover::CoverParameters& parameters,
                    int frames, double interval_hours, bool quiet, RunCover&& run_cover, WriteCover&& write_cover) {
  core::Progress progress("generate", frames, core::Progress::for_stderr(quiet));
  const double start = core::parse_utc_time(parameters.time);
  // The preview: equirect maps of at most 512 x 256, smaller for small covers.
  const int preview_width = std::min(512, 4 * parameters.size), preview_height = preview_width / 2;
  std::vector<core::ImageData> previews;
  json::Value::Array list;
  for (int k = 0; k < frames; ++k) {
    const std::string time = core::format_utc_seconds(double(std::llround(start + k * interval_hours * 3600.0)));
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d", k);
    progress.update(k, std::string(name) + " " + time);
    cover.set_time(time);
    run_cover();
    files::OutputSet frame(outputs.temporary_directory() / name, files::OutputSet::Scope::directory);
    write_cover(frame);
    core::ImageData preview{preview_width, preview_height, 3, {}};
    const std::vector<float> grey =
        cover::equirect_from_faces(parameters.size, cover.cover_field().read(), preview_width, preview_height);
    preview.pixels.reserve(grey.size() * 3);
    for (float g : grey) preview.pixels.insert(preview.pixels.end(), {g, g, g});
    previews.push_back(std::move(preview));
    json::Value entry;
    entry.set("folder", std::string(name));
    entry.set("time", time);
    entry.set("cloud_fraction", cover.calibration().achieved_fraction);
    list.push_back(std::move(entry));
  }
  progress.update(frames, "writing sequence.json and sequence.gif");
  json::Value sidecar;
  sidecar.set("frames", std::move(list));
  sidecar.set("count", double(frames));
  sidecar.set("start", core::format_utc_seconds(start));
  sidecar.set("interval_hours", interval_hours);
  sidecar.set("preview", "sequence.gif");
  sidecar.set("preview_frames_per_second", double(sequence_preview_fps));
  outputs.write("sequence.json", json::write(sidecar));
  outputs.write("sequence.gif", files::encode_animation(previews, sequence_preview_fps, "sequence.gif"));
  outputs.commit();
  progress.finish();
}

// --tile A or A-B: tiles A to B of `count`.
struct TileRange {
  int first = 0, last = 0;
};
TileRange parse_tile_range(const std::string& text, int count, const std::string& option) {
  const std::string allowed = "A or A-B with 0 <= A <= B < " + std::to_string(count) + " (--tiles)";
  const auto number = [&](const std::string& digits) {
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
      throw UsageError(option, text, allowed);
    return std::stoi(digits);
  };
  const auto dash = text.find('-');
  TileRange range;
  range.first = number(text.substr(0, dash));
  range.last = dash == std::string::npos ? range.first : number(text.substr(dash + 1));
  if (range.first > range.last || range.last >= count) throw UsageError(option, text, allowed);
  return range;
}

// generate's options, parsed and checked before any work.
struct GenerateSetup {
  cover::CoverParameters parameters;
  std::string out;
  bool verbose = false, quiet = false;
  io::CoverFileOptions file_options;
  std::vector<const io::ExportPreset*> presets;
  int sequence = 0;
  double interval = 0;
  int tiles = 0;                             // --tiles (0: as the budget needs)
  std::optional<TileRange> tile;             // --tile
  double memory_budget = 0;                  // bytes (0: the device's)
  std::vector<std::string> cover_arguments;  // the arguments without --tile and --out (tile parts record them)
};

// The arguments that define the cover: all but --tile, --out and the reporting flags. Files
// named by --profile and --surface are made absolute, so that assemble, run elsewhere, reads
// the same ones.
std::vector<std::string> cover_arguments(const std::vector<std::string>& arguments) {
  std::vector<std::string> kept;
  const std::string tile = params::run::tile.option(), out = params::run::cover_out.option();
  for (size_t k = 0; k < arguments.size(); ++k) {
    const std::string& a = arguments[k];
    const auto named = [&](const std::string& option) { return a == option || a.rfind(option + "=", 0) == 0; };
    if (named(tile) || named(out)) {
      if (a.find('=') == std::string::npos) ++k;  // its value follows
      continue;
    }
    if (a == params::run::quiet.option() || a == params::run::verbose.option()) continue;
    bool file_value = false;
    for (const params::Parameter* file_option : {&params::cover::profile, &params::cover::surface}) {
      const std::string option = file_option->option();
      const bool joined = a.rfind(option + "=", 0) == 0;
      if ((a != option || k + 1 >= arguments.size()) && !joined) continue;
      const std::string value = joined ? a.substr(option.size() + 1) : arguments[k + 1];
      std::error_code error;
      kept.push_back(option);
      kept.push_back(std::filesystem::is_regular_file(value, error) ? std::filesystem::absolute(value).string()
                                                                    : value);
      if (!joined) ++k;
      file_value = true;
      break;
    }
    if (!file_value) kept.push_back(a);
  }
  return kept;
}

// Parses generate's arguments; false when --help was given (printed).
bool parse_generate(const std::vector<std::string>& arguments, GenerateSetup& setup) {
  cover::CoverParameters& parameters = setup.parameters;
  std::string& out = setup.out;
  out = std::string(params::run::cover_out.default_text);
  bool& verbose = setup.verbose;
  bool& quiet = setup.quiet;
  Options options("generate",
                  "Generates a global cloud cover: curl-warped Worley noise on a cube map, written to\n"
                  "cover_{px,nx,py,ny,pz,nz}.exr, cover_equirect.exr, cover_equirect.png and cover.json\n"
                  "(--files chooses the images; what none asks for is not computed). Covers beyond\n"
                  "--memory-budget are computed in tiles; --tiles with --tile computes some tiles only,\n"
                  "for nephele assemble (docs/scale.md).",
                  params::generate);
  add_cover_options(options, parameters, params::generate);
  WarpOptions warp_options;
  ProfileOption profile_option;
  profile_option.add(options);
  SurfaceOption surface_option;
  surface_option.add(options);
  warp_options.add(options, parameters);
  CoverFileOption file_option;
  options.bind(params::run::cover_out, &out);
  file_option.add(options);
  std::string exports;
  options.bind(params::run::cover_exports, &exports);
  int& sequence = setup.sequence;
  double& interval = setup.interval;
  sequence = params::run::sequence.default_int();
  interval = params::run::interval.default_number;
  options.bind(params::run::sequence, &sequence);
  options.bind(params::run::interval, &interval);
  options.bind(params::run::quiet, &quiet);
  options.bind(params::run::verbose, &verbose);
  std::string tile_text;
  int budget_mib = params::run::memory_budget.default_int();
  options.bind(params::run::tiles, &setup.tiles);
  options.bind(params::run::tile, &tile_text);
  options.bind(params::run::memory_budget, &budget_mib);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return false;
  }
  setup.cover_arguments = cover_arguments(arguments);
  setup.memory_budget = budget_mib * 1048576.0;
  warp_options.apply(parameters);
  profile_option.apply(parameters);
  surface_option.apply(parameters);
  validate_cover_parameters(parameters);
  if (sequence > 0 && parameters.flow != cover::Flow::moving)
    throw UsageError(params::run::sequence.option(), std::to_string(sequence), "0 with --flow steady",
                     "is a sequence of a cover that does not move");
  if (sequence == 0 && options.given(params::run::interval))
    throw UsageError(params::run::interval.option() + ": only with --sequence");
  if (options.given(params::run::tiles)) {
    const std::string problem = cover::tile_count_problem(parameters.size, setup.tiles);
    if (!problem.empty())
      throw UsageError(params::run::tiles.option(), std::to_string(setup.tiles),
                       "a multiple of 6 from 6 to " + std::to_string(cover::max_tile_count(parameters.size)) +
                           " (6 strips of one row per face at --size " + std::to_string(parameters.size) + ")",
                       problem);
  }
  const bool tiled = setup.tiles > 0 || options.given(params::run::tile);
  if (tiled && sequence > 0)
    throw UsageError(params::run::tiles.option() +
                     ": not with --sequence (each frame is computed whole; a job "
                     "array computes frames with --time, docs/scale.md)");
  if (tiled && cover::resolved_curl_mode(parameters) == cover::CurlMode::sampled)
    throw UsageError(params::run::tiles.option() +
                     ": not with --curl-mode sampled, whose warp reads the curl map "
                     "anywhere on the sphere (procedural and spline evaluate the flow where they go)");
  if (options.given(params::run::tile)) {
    if (!options.given(params::run::tiles))
      throw UsageError(params::run::tile.option() + ": only with --tiles COUNT (the tiling the parts belong to)");
    setup.tile = parse_tile_range(tile_text, setup.tiles, params::run::tile.option());
    for (const params::Parameter* p : {&params::run::cover_files, &params::run::cover_exports, &params::run::precision,
                                       &params::run::exr_compression})
      if (options.given(*p))
        throw UsageError(p->option() + ": not with --tile, which writes tile parts; give it to nephele assemble");
  }
  io::CoverFileOptions& file_options = setup.file_options;
  file_options = file_option.file_options();
  // The presets are checked before any work: a name or a texture limit never fails late.
  if (options.given(params::run::cover_exports)) setup.presets = parse_cover_exports(exports, parameters.size);
  // --tiles: the cover is made in tiles and exported from its face files (checked again in
  // run_in_tiles for covers the budget tiles).
  if (setup.tiles > 0) check_exports_read_faces(setup.presets, file_options);
  return true;
}

void create_output_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw UsageError("--out: cannot create directory '" + directory.string() + "': " + error.message());
}

// Computes tiles `range` of `tiling` into `directory` as tile parts, skipping those complete
// there; returns how many were kept.
int compute_tile_parts(const GenerateSetup& setup, const cover::CubeTiling& tiling, TileRange range,
                       const std::filesystem::path& directory, core::Progress& progress, int progress_offset) {
  const json::Value identity = io::cover_identity(setup.cover_arguments, setup.parameters);
  std::unique_ptr<cover::TileRunner> runner;
  int kept = 0;
  for (int index = range.first; index <= range.last; ++index) {
    if (io::find_tile_part(directory, index, tiling.count, identity)) {
      ++kept;
      continue;
    }
    progress.update(progress_offset + index - range.first,
                    "tile " + std::to_string(index) + " of " + std::to_string(tiling.count));
    if (!runner) runner = std::make_unique<cover::TileRunner>(setup.parameters, tiling);
    io::write_tile_part(directory, runner->run(index), tiling.count, identity);
  }
  return kept;
}

// The budget's check of a tiling: its largest tile's passes must fit.
void check_tiles_fit(const cover::CoverParameters& p, const cover::CubeTiling& tiling, double budget) {
  const int rows = (p.size + tiling.strips_per_face() - 1) / tiling.strips_per_face() + 2;
  const double bytes = cover::tile_bytes(p.size, std::min(rows, p.size));
  if (budget > 0 && bytes > budget)
    throw UsageError(
        params::run::tiles.option(), std::to_string(tiling.count),
        "from " + std::to_string(cover::tile_count_for_budget(p.size, budget)) + " up (or a larger --memory-budget)",
        "makes tiles of " + std::to_string(static_cast<long>(std::ceil(bytes / 1048576.0))) +
            " MiB, over the memory budget of " + std::to_string(static_cast<long>(budget / 1048576.0)) + " MiB");
}

// generate --tiles COUNT --tile A-B: tile parts for nephele assemble.
int run_tile_parts(const GenerateSetup& setup, const std::filesystem::path& directory) {
  const cover::CoverParameters& p = setup.parameters;
  gpu::EglContext context;
  const cover::CubeTiling tiling{p.size, setup.tiles};
  const double budget = setup.memory_budget > 0 ? setup.memory_budget : cover::default_memory_budget_bytes(context);
  check_tiles_fit(p, tiling, budget);
  create_output_directory(directory);
  const TileRange range = *setup.tile;
  core::Progress progress("generate", range.last - range.first + 1, core::Progress::for_stderr(setup.quiet));
  const int kept = compute_tile_parts(setup, tiling, range, directory, progress, 0);
  progress.finish();
  std::cout << "wrote tiles " << range.first << " to " << range.last << " of " << tiling.count << " into "
            << directory.string();
  if (kept > 0) std::cout << " (" << kept << " already complete, kept)";
  std::cout << "\n";
  return exit_ok;
}

// generate beyond the memory budget, or with --tiles alone: every tile in turn into a folder of
// the output set, then the files assembled from them (the folder goes before the commit).
int run_in_tiles(const GenerateSetup& setup, const gpu::EglContext& context, double budget) {
  const cover::CoverParameters& p = setup.parameters;
  const int count = setup.tiles > 0 ? setup.tiles : cover::tile_count_for_budget(p.size, budget);
  const cover::CubeTiling tiling{p.size, count};
  check_tiles_fit(p, tiling, budget);
  io::check_assembly_fits(p.size, count, setup.file_options, budget);
  check_exports_read_faces(setup.presets, setup.file_options);
  const std::filesystem::path directory(setup.out);
  create_output_directory(directory);
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  const std::filesystem::path parts = outputs.temporary_directory() / "tile_parts";
  std::filesystem::create_directories(parts);
  // The tiles, then calibrate, each tile's cover, the equirect map and the files.
  core::Progress progress("generate", count + 4, core::Progress::for_stderr(setup.quiet));
  compute_tile_parts(setup, tiling, {0, count - 1}, parts, progress, 0);
  const std::vector<io::TilePart> all = io::read_all_tile_parts(parts, "--out");
  int step = count;
  const io::AssembledCover assembled = io::write_assembled_cover(outputs, all, p, context.info(), setup.file_options,
                                                                 budget, [&](const std::string& what) {
                                                                   if (what.rfind("tile ", 0) != 0)
                                                                     progress.update(std::min(step++, count + 3), what);
                                                                 });
  std::filesystem::remove_all(parts);
  write_cover_exports_from_faces(outputs, setup.presets);
  outputs.commit();
  progress.finish();
  if (setup.verbose) {
    for (const auto& t : assembled.summary.timings) std::cerr << "pass " << t.pass << ": " << t.milliseconds << " ms\n";
    for (const auto& t : assembled.exported.timings)
      std::cerr << "export " << t.pass << ": " << t.milliseconds << " ms\n";
  }
  std::cout << "wrote " << (directory / "cover.json").string() << " and "
            << io::cover_file_names(setup.file_options).size() - 1 << " images in " << count
            << " tiles; cloud fraction " << assembled.summary.calibration.achieved_fraction << " (target " << p.coverage
            << ")\n";
  return exit_ok;
}

}  // namespace

cover::CoverParameters parse_generate_parameters(const std::vector<std::string>& arguments) {
  GenerateSetup setup;
  if (!parse_generate(arguments, setup)) throw UsageError("the tile parts' arguments ask for --help");
  return setup.parameters;
}

int run_generate(const std::vector<std::string>& arguments) {
  GenerateSetup setup;
  if (!parse_generate(arguments, setup)) return exit_ok;
  cover::CoverParameters& parameters = setup.parameters;
  const std::string& out = setup.out;
  const bool verbose = setup.verbose, quiet = setup.quiet;
  const io::CoverFileOptions& file_options = setup.file_options;
  const std::vector<const io::ExportPreset*>& presets = setup.presets;
  const int sequence = setup.sequence;
  const double interval = setup.interval;
  const std::filesystem::path directory(out);
  files::check_output_directory(directory, "--out");
  if (setup.tile) return run_tile_parts(setup, directory);
  // A directory of the user's at one of the set's names is refused before the run, not after.
  files::check_output_files(directory, io::cover_file_names(file_options), "--out");

  gpu::EglContext context;
  if (verbose)
    std::cerr << "renderer: " << context.info().renderer << " (" << context.info().version << ", EGL "
              << context.info().platform << ")\n";
  const double budget = setup.memory_budget > 0 ? setup.memory_budget : cover::default_memory_budget_bytes(context);
  // Tiles where asked for, where the whole cover is over the budget, and where the driver cannot
  // allocate its cube maps (each tile's maps are strips of one face).
  if (setup.tiles > 0 || cover::cover_needs_tiles(parameters.size, parameters.flow, budget))
    return run_in_tiles(setup, context, budget);
  cover::check_cover_fits(context, parameters.size, "--size", parameters.flow);

  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw UsageError("--out: cannot create directory '" + out + "': " + error.message());

  // Opened before the passes run, so that an interrupt at any time removes its temporary directory.
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  cover::GlobalCover cover(parameters);
  // A cover's files into `set` (committed there): the images, the sidecar and the presets, each
  // preset into export/NAME inside the set's temporary directory, so that everything still
  // appears whole or not at all.
  const auto write_cover = [&](files::OutputSet& set) {
    if (!presets.empty())
      write_cover_exports(set, presets,
                          io::CoverFaces{parameters.size, cover.cover_field().read(),
                                         cover.optical_thickness_field().read(), cover.cloud_top_field().read()});
    return io::write_cover_files(set, cover, context.info(), file_options);
  };
  const auto run_cover = [&]() -> const cover::WarpDiagnostics& {
    cover.run();
    // Stiff or capped warps are reported, never silently written (docs/numerics.md).
    const cover::WarpDiagnostics& diagnostics = cover.diagnose();
    for (const auto& warning : diagnostics.warnings) std::cerr << "nephele: warning: " << warning << "\n";
    return diagnostics;
  };
  if (sequence > 0) {
    write_sequence(outputs, cover, parameters, sequence, interval, quiet, run_cover, write_cover);
    std::cout << "wrote " << sequence << " frames into " << directory.string() << " (sequence.json, sequence.gif)\n";
    return exit_ok;
  }
  // identity, (spline,) curl, warp, density, calibrate, coverage, diagnose, then the files.
  const int stages = cover::resolved_curl_mode(parameters) == cover::CurlMode::spline ? 9 : 8;
  core::Progress progress("generate", stages, core::Progress::for_stderr(quiet));
  int stages_started = 0;
  cover.on_pass([&](const std::string& pass) { progress.update(stages_started++, pass); });
  const cover::WarpDiagnostics& diagnostics = run_cover();
  progress.update(stages_started++, "writing files");
  const io::CoverExport exported = write_cover(outputs);
  progress.finish();
  if (verbose) {
    for (const auto& t : cover.timings()) std::cerr << "pass " << t.pass << ": " << t.milliseconds << " ms\n";
    double encode_ms = 0;
    for (const auto& t : exported.timings) {
      std::cerr << "export " << t.pass << ": " << t.milliseconds << " ms\n";
      if (t.pass == "encode") encode_ms = t.milliseconds;
    }
    if (encode_ms > 0)
      std::cerr << "export: " << exported.bytes / 1e6 << " MB of images, encoded at "
                << exported.bytes / 1e3 / encode_ms << " MB/s\n";
    std::cerr << "warp: " << cover::integrator_name(parameters.integrator) << ", "
              << cover::curl_mode_name(parameters.curl_mode) << " curl; stiffness h rho "
              << diagnostics.stiffness.stiffness << " (stable limit " << diagnostics.stiffness.limit << ", beyond on "
              << diagnostics.stiffness.beyond_fraction << " of the sphere); folded fraction "
              << diagnostics.folding.folded_fraction;
    if (diagnostics.adaptive)
      std::cerr << "; sub-steps per texel " << diagnostics.substeps.mean_attempts << " on average, "
                << diagnostics.substeps.max_attempts << " at most, " << diagnostics.substeps.capped_texels
                << " texels capped";
    std::cerr << "\n";
  }
  std::cout << "wrote " << (directory / "cover.json").string() << " and "
            << io::cover_file_names(file_options).size() - 1 << " images; cloud fraction "
            << cover.calibration().achieved_fraction << " (target " << parameters.coverage << ")\n";
  return exit_ok;
}

}  // namespace nephele::cli
