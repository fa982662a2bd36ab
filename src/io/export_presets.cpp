// The registry of the export presets, the reading of a cover directory and the checks made before
// any work; the writers are in one file per target family (io/export_writers.hpp).
#include "io/export_presets.hpp"

#include <cstdio>
#include <limits>

#include "core/error.hpp"
#include "files/image_files.hpp"
#include "files/texture_containers.hpp"
#include "io/cover_files.hpp"
#include "io/export_writers.hpp"

namespace nephele::io {
namespace {

std::string preset_words() {
  std::string words;
  for (const auto& p : export_presets()) words += (words.empty() ? "" : ", ") + p.name;
  return words;
}

std::filesystem::path face_path(const std::filesystem::path& directory, int f) {
  return directory / (std::string("cover_") + face_suffixes[f] + ".exr");
}

// Where the file's channels hold Y, tau and cloud_top (cover_channels; -1 where absent): Y
// alone, or all three and nothing else; empty for any other set.
std::vector<int> face_channels(const std::vector<std::string>& names) {
  std::vector<int> at(cover_channels.size(), -1);
  for (size_t k = 0; k < names.size(); ++k)
    for (size_t c = 0; c < cover_channels.size(); ++c)
      if (names[k] == cover_channels[c]) at[c] = static_cast<int>(k);
  const bool y_alone = names.size() == 1 && at[0] == 0;
  const bool all = names.size() == cover_channels.size() && at[0] >= 0 && at[1] >= 0 && at[2] >= 0;
  if (!y_alone && !all) return {};
  return at;
}

std::string channel_list(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list.empty() ? "(none)" : list;
}

}  // namespace

int read_cover_face_size(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory))
    throw core::InputError("COVER_DIR", directory.string(), "a directory written by nephele generate",
                           "is not a directory");
  int size = 0;
  for (int f = 0; f < 6; ++f) {
    const std::filesystem::path path = face_path(directory, f);
    std::error_code error;
    if (!std::filesystem::exists(path, error))
      throw core::InputError("COVER_DIR", directory.string(),
                             "a directory with cover_px.exr ... cover_nz.exr (nephele generate --files faces)",
                             "has no " + path.filename().string());
    files::ImageHeader header;
    try {
      header = files::read_image_header(path);
    } catch (const std::exception& e) {
      throw core::InputError("COVER_DIR", path.string(), "an OpenEXR cube face",
                             std::string("cannot be read: ") + e.what());
    }
    if (header.width != header.height || (f > 0 && header.width != size))
      throw core::InputError("COVER_DIR", path.string(), "six square faces of one size",
                             "is " + std::to_string(header.width) + " x " + std::to_string(header.height));
    // A face holds coverage (and the cloud's properties); reading one channel of a colour image
    // would be a guess.
    if (face_channels(header.channel_names).empty())
      throw core::InputError("COVER_DIR", path.string(), "the channel Y of coverage per face, or Y, tau and cloud_top",
                             "has the channels " + channel_list(header.channel_names));
    size = header.width;
  }
  return size;
}

CoverFaces read_cover_faces(const std::filesystem::path& directory) {
  CoverFaces faces;
  faces.size = read_cover_face_size(directory);
  const std::size_t texels = std::size_t(faces.size) * faces.size;
  faces.texels.reserve(6 * texels);
  for (int f = 0; f < 6; ++f) {
    const std::filesystem::path path = face_path(directory, f);
    core::ImageData image;
    files::ImageHeader header;
    try {
      image = files::read_image(path, 0, &header);
    } catch (const std::exception& e) {
      throw core::InputError("COVER_DIR", path.string(), "an OpenEXR cube face",
                             std::string("cannot be read: ") + e.what());
    }
    // The headers were checked; a file replaced meanwhile is caught here.
    const std::vector<int> at = face_channels(header.channel_names);
    if (image.width != faces.size || image.height != faces.size || at.empty() ||
        (f > 0 && (at[1] >= 0) != !faces.optical_thickness.empty()))
      throw core::InputError("COVER_DIR", path.string(), "six square faces of one size and the same channels",
                             "changed while read, or has other channels than cover_px.exr");
    const int stride = image.channels;
    // Each channel's values with its range: the coverage in [0, 1], tau and the top >= 0.
    const auto take = [&](int channel, float most, const char* what, std::vector<float>& out) {
      for (std::size_t i = 0; i < texels; ++i) {
        const float v = image.pixels[i * stride + channel];
        if (!(v >= 0.0f && v <= most)) {  // NaN fails both
          char shown[32];
          std::snprintf(shown, sizeof shown, "%g", double(v));
          throw core::InputError("COVER_DIR", path.string(), what,
                                 std::string("holds ") + shown + " at texel " + std::to_string(i % faces.size) + ", " +
                                     std::to_string(i / faces.size));
        }
        out.push_back(v);
      }
    };
    take(at[0], 1.0f, "coverage values in [0, 1] (channel Y)", faces.texels);
    if (at[1] >= 0) {
      take(at[1], std::numeric_limits<float>::max(), "optical thicknesses (tau) >= 0", faces.optical_thickness);
      take(at[2], std::numeric_limits<float>::max(), "cloud-top heights (cloud_top, km) >= 0", faces.cloud_top);
    }
  }
  return faces;
}

namespace {

// The widest image edge of each kind of preset for face size n: the faces themselves (exr-cube's
// N x 6N strip is an environment file, not one GPU texture), a 4n x 2n equirect, a 6n x n strip,
// FlightGear's tiles.
long long faces_edge(int n) { return n; }
long long equirect_edge(int n) { return 4LL * n; }
long long strip_edge(int n) { return 6LL * n; }
long long tile_edge(int n) { return flightgear_tile_size(n); }
// Celestia: one 4n x 2n map up to the texture limit, a virtual texture of 1024-texel tiles beyond.
long long celestia_edge(int n) { return 4LL * n <= max_texture_edge ? 4LL * n : 1024; }

}  // namespace

const std::vector<ExportPreset>& export_presets() {
  // name, summary, needs_equirect, volume, takes_format, takes_name, writer, widest edge.
  static const std::vector<ExportPreset> presets = {
      {"equirect", "2:1 lat-long map: float EXR, 16-bit PNG, 8-bit PNG", true, false, false, false, write_equirect,
       equirect_edge},
      {"gl-faces", "six OpenEXR cube faces in the OpenGL order and orientation", false, false, false, false,
       write_gl_faces, faces_edge},
      {"ktx2", "KTX 2.0 cube map with mips (R16_SFLOAT, R32_SFLOAT, R8_UNORM or BC4; --format)", false, false, true,
       false, write_ktx2, faces_edge},
      {"dds", "DDS cube maps with mips: BC4, BC3, RGBA8 and DX10 R16_FLOAT / R32_FLOAT", false, false, false, false,
       write_dds, faces_edge},
      {"celestia", "Celestia add-on: cloud map (white, coverage in alpha) as PNG and DXT5 DDS with mips, .ssc", true,
       false, false, true, write_celestia, celestia_edge},
      {"exr-cube", "OpenEXR cube environment map (N x 6N strip, envmap = cube)", false, false, false, false,
       write_exr_cube, faces_edge},
      {"flightgear", "FlightGear Earthview: eight bordered tiles clouds_N1..S4, grey + alpha", true, false, false,
       false, write_flightgear, tile_edge},
      {"eve", "KSP EVE (LGhassen's fork): equirect and six faces as DXT5 DDS with mips, texture and cloud configs",
       true, false, false, true, write_eve, equirect_edge},
      {"unity", "Unity: lat-long map (HDRP cloud map in red) and a 6x1 face strip, reflected", true, false, false,
       false, write_unity, strip_edge},
      {"godot", "Godot 4: 2x3 and 6x1 cubemap images and a panorama equirect", true, false, false, false, write_godot,
       strip_edge},
      {"unreal", "Unreal: linear EXR and 16-bit PNG equirect for a cloud or planet material", true, false, false, false,
       write_unreal, equirect_edge},
      {"blender", "Blender: equirect EXR and a script for an unmirrored World (Mapping Y = -1)", true, false, false,
       false, write_blender, equirect_edge},
      {"atlas", "volume (noise .raw or model density.json): slice atlas in rows and columns", false, true, false, false,
       nullptr, nullptr},
      {"openvdb", "volume (noise .raw or model density.json): OpenVDB FOG_VOLUME grids", false, true, false, false,
       nullptr, nullptr},
  };
  return presets;
}

const ExportPreset& find_export_preset(const std::string& name) {
  for (const auto& p : export_presets())
    if (p.name == name) return p;
  throw core::InputError("--preset", name, preset_words());
}

int flightgear_tile_size(int face_size) {
  int tile = 128;
  while (tile < face_size) tile *= 2;
  return tile;
}

long long widest_image_edge(const ExportPreset& preset, int face_size) {
  return preset.widest_edge != nullptr ? preset.widest_edge(face_size) : 0;  // volumes check their atlas
}

void check_texture_limit(const ExportPreset& preset, int face_size) {
  const long long edge = widest_image_edge(preset, face_size);
  if (edge <= max_texture_edge) return;
  // The largest face size whose widest image fits (the edges grow with n).
  long long largest = 1;
  while (widest_image_edge(preset, static_cast<int>(largest + 1)) <= max_texture_edge) ++largest;
  throw core::InputError("COVER_DIR", "face size " + std::to_string(face_size),
                         "face size at most " + std::to_string(largest) + " for preset " + preset.name,
                         "would make an image " + std::to_string(edge) + " pixels wide, over the " +
                             std::to_string(max_texture_edge) +
                             " pixels engines and GPUs take (GL_MAX_TEXTURE_SIZE); use celestia or "
                             "flightgear (tiles), gl-faces, ktx2, dds or exr-cube (cube faces), or generate a smaller "
                             "--size");
}

void check_export_options(const ExportPreset& preset, const ExportOptions& options) {
  if (preset.takes_name) check_addon_name(options.name);
  if (preset.takes_format) files::parse_ktx2_format(options.ktx2_format);
}

std::vector<std::string> write_export(files::OutputSet& outputs, const ExportPreset& preset, const CoverFaces& faces,
                                      const ExportOptions& options) {
  check_texture_limit(preset, faces.size);
  check_export_options(preset, options);
  std::vector<std::string> names;
  if (preset.write == nullptr)
    throw core::InputError("--preset", preset.name, "a cover preset", "exports a volume (nephele export VOLUME)");
  preset.write(outputs, names, preset, faces, options);
  return names;
}

}  // namespace nephele::io
