// nephele assemble PARTS: the files of a cover computed in tiles (generate --tiles --tile),
// the same files generate writes (docs/scale.md).
#include <cmath>
#include <filesystem>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "apps/cli/cover_exports.hpp"
#include "apps/cli/cover_options.hpp"
#include "apps/cli/options.hpp"
#include "core/memory.hpp"
#include "cover/cover_limits.hpp"
#include "core/progress.hpp"
#include "files/atomic_output.hpp"
#include "gpu/egl_context.hpp"
#include "io/cover_assembly.hpp"
#include "io/cover_files.hpp"
#include "io/cover_tiles.hpp"
#include "core/input_file.hpp"
#include "params/table.hpp"
#include "params/values.hpp"

namespace nephele::cli {

int run_assemble(const std::vector<std::string>& arguments) {
  std::vector<std::string> rest = arguments;
  const std::string parts_dir = take_leading_operand(rest);
  std::string out(params::run::assemble_out.default_text);
  CoverFileOption file_option;
  bool quiet = false, verbose = false;
  int budget_mib = params::run::memory_budget.default_int();
  std::string exports;
  Options options("assemble",
                  "Assembles a cover computed in tiles: nephele assemble PARTS_DIR [options] reads the tile\n"
                  "parts that generate --tiles COUNT --tile A-B wrote (every tile of one cover), calibrates\n"
                  "the coverage over all of them and writes the files generate writes (docs/scale.md).",
                  params::assemble);
  options.bind(params::run::assemble_out, &out);
  file_option.add(options);
  options.bind(params::run::quiet, &quiet);
  options.bind(params::run::verbose, &verbose);
  options.bind(params::run::memory_budget, &budget_mib);
  options.bind(params::run::cover_exports, &exports);
  if (!options.parse(rest)) {
    std::cout << options.help();
    return exit_ok;
  }
  if (parts_dir.empty())
    throw UsageError("PARTS_DIR", "", "the directory of tile parts (generate --tile ... --out DIR)", "is missing");
  const io::CoverFileOptions file_options = file_option.file_options();
  const std::vector<io::TilePart> parts = io::read_all_tile_parts(parts_dir, "PARTS_DIR");
  // The cover's parameters as generate parsed them for the parts.
  std::vector<std::string> cover_arguments;
  const json::Value* list = parts.front().identity.find("arguments");
  if (!list || !list->is_array())
    throw core::InputFileError(parts.front().path.string() + ": 'cover.arguments' is missing or not a list");
  for (const json::Value& a : list->as_array()) {
    if (!a.is_string())
      throw core::InputFileError(parts.front().path.string() + ": 'cover.arguments' holds a non-text");
    cover_arguments.push_back(a.as_string());
  }
  const cover::CoverParameters parameters = parse_generate_parameters(cover_arguments);
  std::vector<const io::ExportPreset*> presets;
  if (options.given(params::run::cover_exports)) presets = parse_cover_exports(exports, parameters.size);
  check_exports_read_faces(presets, file_options);
  const std::filesystem::path directory(out);
  files::check_output_directory(directory, params::run::assemble_out.option());
  files::check_output_files(directory, io::cover_file_names(file_options), params::run::assemble_out.option());
  gpu::EglContext context;
  const double budget = budget_mib > 0 ? budget_mib * 1048576.0 : cover::default_memory_budget_bytes(context);
  io::check_assembly_fits(parameters.size, static_cast<int>(parts.size()), file_options, budget);
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    throw UsageError(params::run::assemble_out.option() + ": cannot create directory '" + out +
                     "': " + error.message());
  files::OutputSet outputs(directory, files::OutputSet::Scope::directory);
  const int count = static_cast<int>(parts.size());
  core::Progress progress("assemble", count + 4, core::Progress::for_stderr(quiet));
  int step = 0;
  const io::AssembledCover assembled =
      io::write_assembled_cover(outputs, parts, parameters, context.info(), file_options, budget,
                                [&](const std::string& what) { progress.update(std::min(step++, count + 3), what); });
  write_cover_exports_from_faces(outputs, presets);
  outputs.commit();
  progress.finish();
  if (verbose) {
    for (const auto& t : assembled.summary.timings) std::cerr << "pass " << t.pass << ": " << t.milliseconds << " ms\n";
    for (const auto& t : assembled.exported.timings)
      std::cerr << "export " << t.pass << ": " << t.milliseconds << " ms\n";
  }
  std::cout << "wrote " << (directory / "cover.json").string() << " from " << count << " tiles; cloud fraction "
            << assembled.summary.calibration.achieved_fraction << " (target " << parameters.coverage << ")\n";
  return exit_ok;
}

}  // namespace nephele::cli
