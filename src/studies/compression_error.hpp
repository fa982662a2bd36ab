#pragma once
// The error of each texel format the export presets write, against the float cover: what
// `nephele bench export` prints and docs/export.md quotes (numerical honesty for the lossy
// formats: 8-bit, binary16 and the BC block formats).
#include <string>
#include <vector>

#include "io/export_presets.hpp"

namespace nephele::studies {

struct CompressionRow {
  std::string format;          // "bc4", "bc3 alpha", ...
  std::string used_by;         // the presets that write it
  double bits_per_texel = 0;   // of the base level
  double megabytes_chain = 0;  // the six faces with every mip level
  double rms = 0, max = 0;     // coverage error of the base level, decoded
  double encode_ms = 0;        // encoding the six faces' chains (wall clock)
};

// Encodes the six faces with their mip chains in each format and measures the base level's
// error after decoding it with OpenImageIO's DDS reader (the BC decoder most tools share,
// bcdec) for the block formats and by the formats' definitions otherwise.
std::vector<CompressionRow> compression_errors(const io::CoverFaces& faces);

}  // namespace nephele::studies
