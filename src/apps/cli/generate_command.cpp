// nephele generate: the global cloud cover, written as cube map faces, equirect and sidecar.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <iostream>

#include "apps/cli/commands.hpp"
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
#include "io/cover_files.hpp"
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

}  // namespace

int run_generate(const std::vector<std::string>& arguments) {
  cover::CoverParameters parameters;
  std::string out(params::run::cover_out.default_text);
  bool verbose = false, quiet = false;
  Options options("generate",
                  "Generates a global cloud cover: curl-warped Worley noise on a cube map, written to\n"
                  "cover_{px,nx,py,ny,pz,nz}.exr, cover_equirect.exr, cover_equirect.png and cover.json\n"
                  "(--files chooses the images; what none asks for is not computed).",
                  params::generate);
  add_cover_options(options, parameters, params::generate);
  WarpOptions warp_options;
  ProfileOption profile_option;
  profile_option.add(options);
  SurfaceOption surface_option;
  surface_option.add(options);
  warp_options.add(options, parameters);
  std::string files(params::run::cover_files.default_text), precision(params::run::precision.default_text),
      compression(params::run::exr_compression.default_text);
  options.bind(params::run::cover_out, &out);
  options.bind(params::run::cover_files, &files);
  std::string exports;
  options.bind(params::run::cover_exports, &exports);
  options.bind(params::run::precision, &precision);
  options.bind(params::run::exr_compression, &compression);
  int sequence = params::run::sequence.default_int();
  double interval = params::run::interval.default_number;
  options.bind(params::run::sequence, &sequence);
  options.bind(params::run::interval, &interval);
  options.bind(params::run::quiet, &quiet);
  options.bind(params::run::verbose, &verbose);
  if (!options.parse(arguments)) {
    std::cout << options.help();
    return exit_ok;
  }
  warp_options.apply(parameters);
  profile_option.apply(parameters);
  surface_option.apply(parameters);
  validate_cover_parameters(parameters);
  if (sequence > 0 && parameters.flow != cover::Flow::moving)
    throw UsageError(params::run::sequence.option(), std::to_string(sequence), "0 with --flow steady",
                     "is a sequence of a cover that does not move");
  if (sequence == 0 && options.given(params::run::interval))
    throw UsageError(params::run::interval.option() + ": only with --sequence");
  io::CoverFileOptions file_options;
  io::parse_cover_files(files, file_options);
  params::check_word(params::run::precision, precision, params::run::precision.option());
  params::check_word(params::run::exr_compression, compression, params::run::exr_compression.option());
  file_options.half = precision == "half";
  file_options.compression = compression;
  // The presets are checked before any work: a name or a texture limit never fails late.
  std::vector<const io::ExportPreset*> presets;
  if (options.given(params::run::cover_exports)) {
    std::stringstream list(exports);
    for (std::string name; std::getline(list, name, ',');) {
      const auto& all = io::export_presets();
      const auto found =
          std::find_if(all.begin(), all.end(), [&](const io::ExportPreset& p) { return p.name == name; });
      if (found == all.end()) throw UsageError("--export", name, std::string(params::run::export_preset.allowed));
      if (found->volume) throw UsageError("--export", name, "a cover preset", "exports volumes, not covers");
      if (std::find(presets.begin(), presets.end(), &*found) != presets.end())
        throw UsageError("--export", exports, std::string(params::run::cover_exports.allowed),
                         "names " + name + " twice (as --files refuses faces,faces)");
      presets.push_back(&*found);
      io::check_texture_limit(*presets.back(), parameters.size);
    }
    if (presets.empty() || exports.back() == ',')
      throw UsageError("--export", exports, std::string(params::run::cover_exports.allowed),
                       "names no preset or ends with a comma");
  }
  const std::filesystem::path directory(out);
  files::check_output_directory(directory, "--out");
  // A directory of the user's at one of the set's names is refused before the run, not after.
  files::check_output_files(directory, io::cover_file_names(file_options), "--out");

  gpu::EglContext context;
  if (verbose)
    std::cerr << "renderer: " << context.info().renderer << " (" << context.info().version << ", EGL "
              << context.info().platform << ")\n";
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
    if (!presets.empty()) {
      const io::CoverFaces faces{parameters.size, cover.cover_field().read()};
      io::ExportOptions export_options;
      export_options.resample_equirect = cover::equirect_from_faces;
      for (const io::ExportPreset* preset : presets) {
        const std::filesystem::path folder = set.temporary_directory() / "export" / preset->name;
        std::filesystem::create_directories(folder);
        files::OutputSet preset_set(folder, files::OutputSet::Scope::directory);
        io::write_export(preset_set, *preset, faces, export_options);
        preset_set.commit();
      }
    }
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
