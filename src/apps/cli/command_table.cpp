#include "apps/cli/command_table.hpp"

#include <cstdio>

#include "apps/cli/commands.hpp"
#include "io/export_presets.hpp"

namespace nephele::cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = [] {
    std::string presets;
    for (const io::ExportPreset& p : io::export_presets()) presets += (presets.empty() ? "" : ", ") + p.name;
    return std::vector<Command>{
        {"generate", "make a global cloud cover (cube map faces, equirect map, cover.json)", run_generate},
        {"assemble", "the files of a cover computed in tiles on many machines (generate --tiles --tile)", run_assemble},
        {"render", "cloud layers seen from the ground (Gurten, Bantiger, anywhere) or the planet from orbit",
         run_render},
        {"noise", "tileable 3D noise textures (Worley, Perlin, Perlin-Worley, fBm)", run_noise},
        {"model", "one cloud from implicit primitives: density volume (raw, EXR atlas, OpenVDB)", run_model},
        {"export", "a generated cover as one target's files (" + presets + ")", run_export},
        {"view", "a window on the clouds, with panels, flight and recording (needs a display)", run_view},
        {"bench", "benchmarks that print timings (cover, noise, render, model, view)", run_bench},
        {"report", "error against run time: the warp's integrators and the renderer's steps and qualities", run_report},
        {"stats", "statistics of a cover: coverage by latitude, spectrum, perimeter dimension", run_stats},
    };
  }();
  return table;
}

const Command* find_command(const std::string& name) {
  for (const Command& c : commands())
    if (name == c.name) return &c;
  return nullptr;
}

std::string usage() {
  std::string text = "usage: nephele COMMAND [options]\n\ncommands:\n";
  for (const Command& c : commands()) {
    char name[16];
    std::snprintf(name, sizeof name, "  %-11s", c.name);
    text += name + c.summary + "\n";
  }
  text +=
      "\nnephele COMMAND --help describes each command's options and their ranges.\n"
      "exit codes: 0 success, 1 runtime failure, 2 bad input (the option, key or field is named),\n"
      "            3 environment (no OpenGL 4.5 context; no display for a window)\n";
  return text;
}

}  // namespace nephele::cli
