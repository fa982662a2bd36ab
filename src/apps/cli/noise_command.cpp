// nephele noise: tileable 3D noise textures (Worley, Perlin, Perlin-Worley, fBm) as a slice
// atlas (PNG, EXR) or a raw float32 volume, each with a JSON sidecar.
#include <epoxy/gl.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "apps/cli/commands.hpp"
#include "apps/cli/noise_options.hpp"
#include "apps/cli/options.hpp"
#include "core/memory.hpp"
#include "core/progress.hpp"
#include "noise/noise_limits.hpp"
#include "gpu/egl_context.hpp"
#include "files/atomic_output.hpp"
#include "io/noise_files.hpp"
#include "noise/noise_texture.hpp"
#include "params/table.hpp"
#include "params/values.hpp"

namespace nephele::cli {
namespace {

// Parses "type=worley,cells=8,octaves=3" into a channel. Each key is the global option of the
// same name and is checked against that option's row of the table (integers as integers).
noise::ChannelSpec parse_channel(const std::string& option, const std::string& text, noise::ChannelSpec c) {
  namespace n = params::noise_texture;
  const char* keys = "keys: type, cells, octaves, lacunarity, gain, worley-cells, worley-octaves";
  std::stringstream stream(text);
  std::string item;
  bool worley_cells_given = false;
  while (std::getline(stream, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) throw UsageError(option + ": '" + item + "' is not key=value (" + keys + ")");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const std::string where = option + " " + key;
    auto number = [&](const params::Parameter& p) { return params::parse_number(p, value, where); };
    if (key == "type") {
      try {
        c.type = noise::parse_type(value);
      } catch (const noise::SpecError& e) {
        throw UsageError(option + " " + e.what());
      }
    } else if (key == "cells") {
      c.cells = static_cast<int>(number(n::cells));
    } else if (key == "octaves") {
      c.octaves = static_cast<int>(number(n::octaves));
    } else if (key == "lacunarity") {
      c.lacunarity = static_cast<float>(number(n::lacunarity));
    } else if (key == "gain") {
      c.gain = static_cast<float>(number(n::gain));
    } else if (key == "worley-cells") {
      c.worley_cells = static_cast<int>(number(n::worley_cells));
      worley_cells_given = true;
    } else if (key == "worley-octaves") {
      c.worley_octaves = static_cast<int>(number(n::worley_octaves));
    } else {
      throw UsageError(option + ": unknown key '" + key + "' (" + keys + ")");
    }
  }
  // 0 means "as cells", as for --worley-cells, whichever key came first.
  if (worley_cells_given && c.worley_cells == 0) c.worley_cells = c.cells;
  return c;
}

}  // namespace

NoiseRequest parse_noise_request(const std::vector<std::string>& arguments, bool* help_shown) {
  NoiseRequest request;
  noise::ChannelSpec base;
  namespace n = params::noise_texture;
  int size = n::size.default_int(), width = n::width.default_int(), height = n::height.default_int(),
      depth = n::depth.default_int();
  std::string type(n::type.default_text), layout(n::channels.default_text), preset;
  int worley_cells = n::worley_cells.default_int();
  std::string channel_text[4];
  Options options(
      "noise",
      "Generates a tileable 3D noise texture: Worley (F1), Perlin and Perlin-Worley, each with fBm, in up\n"
      "to four channels. --out NAME.png or NAME.exr writes the slice atlas (depth slices of width x height\n"
      "side by side), NAME.raw the float32 volume; NAME.json describes it. Values lie in [0, 1].\n"
      "Channel k (r, g, b, a) has cells * 2^k cells (at most one per texel) unless --r, --g, --b or --a say otherwise.",
      params::noise);
  options.bind(n::preset, &preset);
  options.bind(n::type, &type);
  options.bind(n::width, &width);
  options.bind(n::height, &height);
  options.bind(n::depth, &depth);
  options.bind(n::size, &size);
  options.bind(n::cells, &base.cells);
  options.bind(n::octaves, &base.octaves);
  options.bind(n::lacunarity, &base.lacunarity);
  options.bind(n::gain, &base.gain);
  options.bind(n::worley_cells, &worley_cells);
  options.bind(n::worley_octaves, &base.worley_octaves);
  options.bind(n::channels, &layout);
  const params::Parameter* channel_parameters[4] = {&n::r, &n::g, &n::b, &n::a};
  for (int k = 0; k < 4; ++k) options.bind(*channel_parameters[k], &channel_text[k]);
  const char* const letters[4] = {"--r", "--g", "--b", "--a"};
  options.bind(n::seed, &request.spec.seed);
  options.bind(n::bits, &request.png_bits);
  options.bind(n::out, &request.out);
  options.bind(n::stretch, &request.stretch);
  options.bind(params::run::quiet, &request.quiet);
  options.bind(params::run::verbose, &request.verbose);
  if (!options.parse(arguments)) {
    request.help = options.help();
    if (help_shown) *help_shown = true;
    return request;
  }
  if (request.png_bits != 8 && request.png_bits != 16)
    throw UsageError("--bits: " + std::to_string(request.png_bits) + " is not allowed (allowed: 8 or 16)");
  if (request.out.empty()) throw UsageError("--out: an output file is required (NAME.png, NAME.exr or NAME.raw)");

  if (!preset.empty()) {
    for (const params::Parameter* o :
         {&n::type, &n::width, &n::height, &n::depth, &n::size, &n::cells, &n::octaves, &n::lacunarity, &n::gain,
          &n::worley_cells, &n::worley_octaves, &n::channels, &n::r, &n::g, &n::b, &n::a})
      if (options.given(*o))
        throw UsageError(
            std::string("--preset fixes the texture's layout; ") + o->option() +
            " cannot be combined with it (allowed with --preset: --seed, --out, --bits, --stretch, --verbose)");
    const std::uint32_t seed = request.spec.seed;
    request.spec = noise::preset(preset, seed);
    request.preset = preset;
  } else {
    if (options.given(n::size)) {
      request.size_given = true;
      for (const params::Parameter* o : {&n::width, &n::height, &n::depth})
        if (options.given(*o)) throw UsageError(std::string("--size and ") + o->option() + " exclude each other");
      width = height = depth = size;
    }
    request.spec.width = width;
    request.spec.height = height;
    request.spec.depth = depth;
    base.type = noise::parse_type(type);
    base.worley_cells = worley_cells > 0 ? worley_cells : base.cells;
    static const char* const layouts[] = {"r", "rg", "rgb", "rgba"};
    int channels = 0;
    for (int k = 0; k < 4; ++k)
      if (layout == layouts[k]) channels = k + 1;
    if (channels == 0) throw UsageError("--channels: '" + layout + "' is not allowed (allowed: r, rg, rgb, rgba)");
    request.spec.channels.clear();
    for (int k = 0; k < 4; ++k) {
      if (k >= channels) {
        if (!channel_text[k].empty())
          throw UsageError(std::string(letters[k]) + ": channel " + (letters[k] + 2) + " is not in --channels " +
                           layout);
        continue;
      }
      noise::ChannelSpec c = noise::default_channel(base, k, width);
      if (!channel_text[k].empty()) c = parse_channel(letters[k], channel_text[k], c);
      request.spec.channels.push_back(c);
    }
  }
  noise::validate(request.spec);
  io::format_for(request.out);
  const std::filesystem::path out(request.out);
  const std::filesystem::path directory = out.has_parent_path() ? out.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(directory))
    throw UsageError("--out: directory '" + directory.string() + "' does not exist");
  if (std::filesystem::is_directory(out)) throw UsageError("--out: '" + request.out + "' is a directory");
  files::check_output_files(directory, {out.filename().string(), out.stem().string() + ".json"}, "--out");
  return request;
}

int run_noise(const std::vector<std::string>& arguments) {
  bool help = false;
  NoiseRequest request = parse_noise_request(arguments, &help);
  if (help) {
    std::cout << request.help;
    return exit_ok;
  }
  gpu::EglContext context;
  if (request.verbose) std::cerr << "renderer: " << context.info().renderer << " (" << context.info().version << ")\n";
  noise::check_noise_fits(request.spec, context, request.size_given ? "--size" : nullptr);
  core::Progress progress("noise", 2, core::Progress::for_stderr(request.quiet));
  progress.update(0, "generating");
  const auto start = std::chrono::steady_clock::now();
  noise::TextureGenerator generator;
  noise::Volume volume = generator.generate(request.spec);
  const double generate_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  json::Value run;
  run.set("renderer", context.info().renderer);
  run.set("generate_ms", generate_ms);
  run.set("compute_ms", generator.timings().compute_ms);
  run.set("patched_segments", static_cast<double>(generator.timings().patched_segments));
  progress.update(1, "writing files");
  const auto write_start = std::chrono::steady_clock::now();
  std::vector<io::ValueRange> stretched_from;
  if (request.stretch) stretched_from = io::stretch_channels(volume);
  const auto sidecar =
      io::write_noise_files(request.out, request.spec, volume, request.png_bits, request.preset, run, stretched_from);
  const double write_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - write_start).count();
  progress.finish();
  if (request.verbose)
    std::cerr << "generate: " << generate_ms << " ms (compute " << generator.timings().compute_ms
              << " ms), write: " << write_ms << " ms\n";
  std::cout << "wrote " << request.out << " and " << sidecar.string() << " (" << request.spec.width << " x "
            << request.spec.height << " x " << request.spec.depth << ", " << request.spec.channels.size()
            << (request.spec.channels.size() == 1 ? " channel)\n" : " channels)\n");
  return exit_ok;
}

}  // namespace nephele::cli
