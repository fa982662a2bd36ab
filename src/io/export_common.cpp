// What the export writers of every target family share (io/export_writers.hpp).
#include <algorithm>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "io/export_writers.hpp"

namespace nephele::io {
namespace {

const char* const coverage_note =
    "Values are cloud coverage in [0, 1], linear data: never sRGB-decode them (import as\n"
    "linear / non-colour / raw).\n";

std::string readme(const ExportPreset& preset, const CoverFaces& faces, const std::string& body) {
  std::ostringstream text;
  text << "nephele export, preset " << preset.name << ": " << preset.summary << "\n"
       << "Cover face size N = " << faces.size << ". Details and orientation: docs/export.md.\n\n"
       << body << "\n"
       << coverage_note;
  return text.str();
}

}  // namespace

files::MipChain cube_mip_chain(const CoverFaces& faces) {
  return files::build_mip_chain(faces.texels, faces.size, faces.size, 6, 1);
}

core::ImageData face_image(const CoverFaces& faces, int face) {
  const std::size_t n = std::size_t(faces.size) * std::size_t(faces.size);
  core::ImageData image{faces.size, faces.size, 1, {}};
  image.pixels.assign(faces.texels.begin() + std::ptrdiff_t(face * n),
                      faces.texels.begin() + std::ptrdiff_t((face + 1) * n));
  return image;
}

core::ImageData equirect_image(const CoverFaces& faces, const ExportOptions& options, int content) {
  if (content == 0) content = faces.size;
  if (options.resample_equirect == nullptr)
    throw std::logic_error("write_export: an equirect preset without ExportOptions::resample_equirect");
  core::ImageData map{4 * content, 2 * content, 1, {}};
  map.pixels = options.resample_equirect(faces.size, faces.texels, map.width, map.height);
  return map;
}

core::ImageData grey_image(int width, int height, std::vector<float> values, bool white_alpha) {
  if (!white_alpha) return core::ImageData{width, height, 1, std::move(values)};
  core::ImageData image{width, height, 2, std::vector<float>(2 * values.size(), 1.0f)};
  for (std::size_t i = 0; i < values.size(); ++i) image.pixels[2 * i + 1] = std::clamp(values[i], 0.0f, 1.0f);
  return image;
}

void check_addon_name(const std::string& name) {
  if (!std::regex_match(name, std::regex("[A-Za-z0-9_-]{1,64}")))
    throw core::InputError("--name", name, "1 to 64 letters, digits, '_' or '-'");
}

void add_readme(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                const CoverFaces& faces, const std::string& body) {
  out.write("README.txt", readme(preset, faces, body));
  names.push_back("README.txt");
}

}  // namespace nephele::io
