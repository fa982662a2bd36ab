// nephele bench export COVER_DIR: the error, size and encoding time of each texel format the
// export presets write, on a real cover (studies/compression_error.hpp, docs/export.md).
#include <cstdio>
#include <iostream>

#include "apps/cli/commands.hpp"
#include "apps/cli/options.hpp"
#include "io/export_presets.hpp"
#include "params/table.hpp"
#include "studies/compression_error.hpp"

namespace nephele::cli {

int bench_export(const std::vector<std::string>& arguments) {
  Options options("bench export COVER_DIR",
                  "Prints, for each texel format of the export presets (float, half, 8-bit and the BC block\n"
                  "formats), the bits per texel, the size of the six faces with every mip level, the\n"
                  "encoding time and the coverage error (rms and largest) of the decoded base level against\n"
                  "the float cover of COVER_DIR (nephele generate --files faces).",
                  params::export_cover);
  std::string cover_dir;  // COVER_DIR comes first; the rest are options
  if (!parse_with_cover_dir(options, arguments, cover_dir)) return exit_ok;
  const io::CoverFaces faces = io::read_cover_faces(cover_dir);
  std::printf("cover: %s, %d per face; errors of the base level in coverage units, decoded\n", cover_dir.c_str(),
              faces.size);
  std::printf("%-11s %6s %10s %10s %10s %10s  %s\n", "format", "bits", "MB chain", "encode ms", "rms", "max",
              "written by");
  for (const auto& row : studies::compression_errors(faces))
    std::printf("%-11s %6.1f %10.3f %10.1f %10.2e %10.2e  %s\n", row.format.c_str(), row.bits_per_texel,
                row.megabytes_chain, row.encode_ms, row.rms, row.max, row.used_by.c_str());
  return exit_ok;
}

}  // namespace nephele::cli
