// What the export writers of every target family share (io/export_writers.hpp).
#include <algorithm>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "files/texture_containers.hpp"
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

void write_cube_containers(files::OutputSet& out, std::vector<std::string>& names, const CoverFaces& faces,
                           const std::vector<CubeContainer>& containers, const ExportOptions& options) {
  const int n = faces.size, levels = files::full_mip_count(n, n);
  std::vector<files::ContainerWriter> writers;
  writers.reserve(containers.size());
  for (const CubeContainer& c : containers) {
    const files::ContainerLayout layout =
        c.ktx2 ? files::ktx2_layout(n, n, 6, levels, c.format) : files::dds_layout(n, n, 6, levels, c.format);
    writers.emplace_back(out.reserve(c.name), layout, c.format, c.layout);
  }
  // Face by face: one face's chain (4/3 of a face) at a time, shared by every container.
  const std::size_t texels = std::size_t(n) * std::size_t(n);
  for (int f = 0; f < 6; ++f) {
    report_progress(options, f / 6.0, "face " + std::to_string(f + 1) + " of 6");
    const float* face = faces.texels.data() + texels * std::size_t(f);
    const files::MipChain chain = files::build_mip_chain(std::vector<float>(face, face + texels), n, n, 1, 1);
    for (files::ContainerWriter& writer : writers) writer.write_layer(f, chain);
  }
  for (std::size_t i = 0; i < writers.size(); ++i) {
    writers[i].close();
    names.push_back(containers[i].name);
  }
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

void report_progress(const ExportOptions& options, double done, const std::string& stage) {
  if (options.progress) options.progress(done, stage);
}

bool equirect_on_cpu(int face_size, const ExportOptions& options) { return face_size > options.gpu_equirect_faces; }

std::array<const float*, 6> face_pointers(int face_size, const float* texels) {
  std::array<const float*, 6> faces{};
  for (int f = 0; f < 6; ++f) faces[f] = texels + std::size_t(f) * std::size_t(face_size) * std::size_t(face_size);
  return faces;
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
