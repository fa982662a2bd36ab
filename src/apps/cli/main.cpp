// nephele: planetary cloud cover, generated on the GPU.
#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "core/printable_text.hpp"
#include "gpu/compute_program.hpp"
#include "gpu/egl_context.hpp"
#include "nephele/version.hpp"

namespace {

const char* const usage =
    "usage: nephele COMMAND [options]\n\n"
    "commands:\n"
    "  generate   make a global cloud cover (cube map faces, equirect map, cover.json)\n"
    "  render     cloud layers seen from the ground (Gurten, Bantiger, anywhere)\n"
    "  noise      tileable 3D noise textures (Worley, Perlin, Perlin-Worley, fBm)\n"
    "  model      one cloud from implicit primitives: density volume (raw, EXR atlas, OpenVDB)\n"
    "  export     a generated cover as one target's files (equirect, gl-faces, ktx2, dds, celestia, exr-cube)\n"
    "  view       a window on the clouds, with panels, flight and recording (needs a display)\n"
    "  bench      benchmarks that print timings (nephele bench cover)\n"
    "  report     error of the warp's integrators against their run time (work-precision)\n"
    "  stats      statistics of a cover: coverage by latitude, spectrum, perimeter dimension\n\n"
    "nephele COMMAND --help describes each command's options and their ranges.\n"
    "exit codes: 0 success, 1 runtime failure, 2 bad input (the option, key or field is named),\n"
    "            3 environment (no OpenGL 4.5 context; no display for a window)\n";

// Messages quote inputs (paths, values, file fields): printed escaped and cut, so that a crafted
// input cannot send escape sequences to the terminal (core/printable_text.hpp).
std::string shown(const std::exception& e) { return nephele::core::printable(e.what(), 8192, true); }

}  // namespace

int main(int argc, char** argv) {
  using namespace nephele::cli;
  std::vector<std::string> arguments(argv + 1, argv + argc);
  // A write beyond `ulimit -f` then fails with EFBIG, which the checked writes report naming the
  // file (exit code 1), instead of SIGXFSZ ending the run without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    if (arguments.empty()) {
      std::cerr << usage;
      return exit_usage;
    }
    const std::string command = arguments[0];
    const std::vector<std::string> rest(arguments.begin() + 1, arguments.end());
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << usage;
      return exit_ok;
    }
    if (command == "--version") {
      std::cout << "nephele " << nephele::version << "\n";
      return exit_ok;
    }
    if (command == "generate") return run_generate(rest);
    if (command == "bench") return run_bench(rest);
    if (command == "noise") return run_noise(rest);
    if (command == "report") return run_report(rest);
    if (command == "render") return run_render(rest);
    if (command == "model") return run_model(rest);
    if (command == "export") return run_export(rest);
    if (command == "view") return run_view(rest);
    if (command == "stats") return run_stats(rest);
    throw UsageError("unknown command '" + command + "' (allowed: generate, render, noise, model, export, view, bench, report, stats)");
  } catch (const nephele::core::InputError& e) {
    std::cerr << "nephele: " << shown(e) << "\n";
    return exit_usage;
  } catch (const nephele::gpu::ContextError& e) {
    std::cerr << "nephele: " << shown(e) << "\n";
    return exit_no_context;
  } catch (const std::exception& e) {
    std::cerr << "nephele: error: " << shown(e) << "\n";
    return exit_failure;
  }
}
