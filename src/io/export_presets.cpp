#include "io/export_presets.hpp"

#include <algorithm>
#include <regex>
#include <sstream>

#include "core/error.hpp"
#include "cover/equirect.hpp"
#include "gpu/textures.hpp"
#include "io/cover_files.hpp"
#include "io/image_files.hpp"
#include "io/texture_containers.hpp"

namespace nephele::io {
namespace {

const char* const coverage_note =
    "Values are cloud coverage in [0, 1], linear data: never sRGB-decode them (import as\n"
    "linear / non-colour / raw).\n";

std::string preset_words() {
  std::string words;
  for (const auto& p : export_presets()) words += (words.empty() ? "" : ", ") + p.name;
  return words;
}

ImageData face_image(const CoverFaces& faces, int face) {
  const std::size_t n = std::size_t(faces.size) * std::size_t(faces.size);
  ImageData image{faces.size, faces.size, 1, {}};
  image.pixels.assign(faces.texels.begin() + std::ptrdiff_t(face * n), faces.texels.begin() + std::ptrdiff_t((face + 1) * n));
  return image;
}

// The equirect of docs/conventions.md (4N x 2N, -180 deg at the left edge, geodetic rows),
// resampled on the GPU by the same pass as `generate`, so that both give the same map.
ImageData equirect_image(const CoverFaces& faces) {
  gpu::Texture cube = gpu::Texture::cube(faces.size, GL_R32F);
  cube.write(faces.texels);
  ImageData map{4 * faces.size, 2 * faces.size, 1, {}};
  map.pixels = cover::equirect_from_cube(cube, map.width, map.height);
  return map;
}

std::string readme(const ExportPreset& preset, const CoverFaces& faces, const std::string& body) {
  std::ostringstream text;
  text << "nephele export, preset " << preset.name << ": " << preset.summary << "\n"
       << "Cover face size N = " << faces.size << ". Details and orientation: docs/export.md.\n\n"
       << body << "\n" << coverage_note;
  return text.str();
}

void write_equirect(OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces) {
  const ImageData map = equirect_image(faces);
  const std::pair<std::string, ImageEncoding> files[] = {{"cover_equirect.exr", exr_encoding({"Y"})},
                                                         {"cover_equirect_16.png", png_encoding(16)},
                                                         {"cover_equirect_8.png", png_encoding(8)}};
  for (const auto& [name, encoding] : files) {
    out.write(name, encode_image(map, encoding, name));
    names.push_back(name);
  }
  const std::string w = std::to_string(map.width), h = std::to_string(map.height);
  out.write("README.txt", readme(preset, faces,
                                 "Files (" + w + " x " + h + ", one grey channel, 2:1 plate carree):\n"
                                 "  cover_equirect.exr     OpenEXR float32, channel Y\n"
                                 "  cover_equirect_16.png  PNG 16-bit, value = round(65535 c)\n"
                                 "  cover_equirect_8.png   PNG 8-bit, value = round(255 c), no gAMA/sRGB chunk\n"
                                 "Orientation: north up, longitude -180 deg at the left edge, 0 at the centre;\n"
                                 "column i at longitude -180 + 360 (i + 0.5)/W, row j at geodetic latitude\n"
                                 "90 - 180 (j + 0.5)/H (WGS84). Use it wherever a lat-long / equirectangular\n"
                                 "map is taken (NASA Blue Marble layout).\n"));
  names.push_back("README.txt");
}

void write_gl_faces(OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces) {
  for (int f = 0; f < 6; ++f) {
    const std::string name = std::string("cover_") + face_suffixes[f] + ".exr";
    out.write(name, encode_image(face_image(faces, f), exr_encoding({"Y"}), name));
    names.push_back(name);
  }
  out.write("README.txt", readme(preset, faces,
                                 "Files: cover_px.exr, cover_nx.exr, cover_py.exr, cover_ny.exr, cover_pz.exr,\n"
                                 "cover_nz.exr: N x N OpenEXR float32, channel Y, the cube faces +X, -X, +Y, -Y,\n"
                                 "+Z (north), -Z (south) in the OpenGL convention (OpenGL 4.6 core, section 8.13,\n"
                                 "table 8.19). Upload face i to GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as stored, row 0\n"
                                 "first, without flips. World axes: +X to 0 N 0 E, +Y to 0 N 90 E, +Z to the North\n"
                                 "Pole; a renderer with Y up must rotate its direction into these axes (a rotation,\n"
                                 "not an exchange of two axes, which would mirror the map).\n"));
  names.push_back("README.txt");
}

void write_ktx2(OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset, const CoverFaces& faces,
                const ExportOptions& options) {
  const TextureSample sample = parse_texture_sample(options.ktx2_format);
  out.write("cover_cube.ktx2", encode_ktx2_cube(faces.texels, faces.size, sample));
  names.push_back("cover_cube.ktx2");
  const std::string format = sample == TextureSample::r8     ? "VK_FORMAT_R8_UNORM (9)"
                             : sample == TextureSample::r16f ? "VK_FORMAT_R16_SFLOAT (76)"
                                                             : "VK_FORMAT_R32_SFLOAT (100)";
  out.write("README.txt", readme(preset, faces,
                                 "File: cover_cube.ktx2, a KTX 2.0 cube map (faceCount 6, one mip level, no\n"
                                 "supercompression), " + format + ", faces in the order +X, -X, +Y, -Y, +Z, -Z\n"
                                 "with the OpenGL/Vulkan face orientation, KTXorientation \"rd\". Load it with\n"
                                 "libktx (ktxTexture2_CreateFromNamedFile, then ktxTexture_GLUpload or\n"
                                 "ktxTexture_VkUpload) or any KTX2 loader as a cube texture; no flips are needed.\n"
                                 "World axes as for gl-faces: +Z is the North Pole.\n"));
  names.push_back("README.txt");
}

void write_dds(OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset, const CoverFaces& faces) {
  const std::pair<std::string, DdsVariant> files[] = {{"cover_cube_rgba8.dds", DdsVariant::rgba8},
                                                      {"cover_cube_r16f.dds", DdsVariant::dx10_r16f},
                                                      {"cover_cube_r32f.dds", DdsVariant::dx10_r32f}};
  for (const auto& [name, variant] : files) {
    out.write(name, encode_dds_cube(faces.texels, faces.size, variant));
    names.push_back(name);
  }
  out.write("README.txt",
            readme(preset, faces,
                   "Files (DDS cube maps, one mip level, faces +X, -X, +Y, -Y, +Z, -Z, rows top-down):\n"
                   "  cover_cube_rgba8.dds  legacy header, uncompressed 32-bit RGBA, coverage in R, G, B\n"
                   "                        and A: for loaders that read only legacy DDS (KSP's texture\n"
                   "                        loader, Unity's DDS importer, OpenImageIO, GIMP)\n"
                   "  cover_cube_r16f.dds   DX10 header, DXGI_FORMAT_R16_FLOAT (54)\n"
                   "  cover_cube_r32f.dds   DX10 header, DXGI_FORMAT_R32_FLOAT (41): for Direct3D 10+\n"
                   "                        engines and DirectXTex (texconv, texassemble); OpenImageIO\n"
                   "                        2.4 does not read these\n"
                   "Faces are addressed as in OpenGL (Direct3D's cube addressing is the same). In a\n"
                   "left-handed engine (Unity, Unreal, KSP) the world must be reflected into nephele's\n"
                   "right-handed axes (+Z north): an axis rename alone mirrors the map.\n"));
  names.push_back("README.txt");
}

void write_celestia(OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions& options) {
  if (!std::regex_match(options.name, std::regex("[A-Za-z0-9_-]{1,64}")))
    throw core::InputError("--name", options.name, "1 to 64 letters, digits, '_' or '-'");
  const ImageData map = equirect_image(faces);
  // White cloud colour, coverage in alpha; the equirect already has the prime meridian at the centre.
  ImageData rgba{map.width, map.height, 4, std::vector<float>(std::size_t(4) * map.pixels.size(), 1.0f)};
  for (std::size_t i = 0; i < map.pixels.size(); ++i) rgba.pixels[4 * i + 3] = std::clamp(map.pixels[i], 0.0f, 1.0f);
  const std::string folder = "extras/" + options.name + "/";
  const std::string texture = folder + "textures/hires/" + options.name + ".png";
  ImageEncoding encoding = png_encoding(8);
  encoding.unassociated_alpha = true;  // PNG's alpha is unassociated: the colour stays white
  out.write(texture, encode_image(rgba, encoding, texture));
  names.push_back(texture);
  const std::string ssc = folder + options.name + ".ssc";
  out.write(ssc, "# nephele cloud cover for Celestia: copy extras/" + options.name +
                     " into Celestia's extras folder.\n"
                     "Modify \"Earth\" \"Sol\"\n{\n\tAtmosphere\n\t{\n\t\tCloudMap \"" + options.name +
                     ".png\"\n\t}\n}\n");
  names.push_back(ssc);
  out.write("README.txt",
            readme(preset, faces,
                   "Files: " + texture + " (RGBA 8-bit PNG, " + std::to_string(map.width) + " x " +
                       std::to_string(map.height) +
                       ", white, coverage in alpha, 2:1 with the prime meridian at\n"
                       "the centre and north up) and " + ssc + ".\n"
                       "Install: copy the folder extras/" + options.name +
                       " into Celestia's extras directory (or the add-on\n"
                       "folder named by ExtrasDirectories in celestia.cfg) and restart Celestia. The .ssc\n"
                       "modifies Earth's atmosphere so that its CloudMap is this texture; Celestia looks it\n"
                       "up in textures/hires/ when the high-resolution texture setting is chosen (it falls\n"
                       "back to the other resolutions' folders otherwise).\n"));
  names.push_back("README.txt");
}

// OpenEXR's cube environment layout (OpenEXR "envmap" attribute, ENVMAP_CUBE): an N x 6N
// vertical strip +X, -X, +Y, -Y, +Z, -Z with every face mirrored relative to the GL face: the
// X and Z faces left-right, the Y faces top-bottom (/work/shared/REFERENCE.md, "Cubemap faces").
void write_exr_cube(OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces) {
  const int n = faces.size;
  ImageData strip{n, 6 * n, 1, std::vector<float>(std::size_t(6) * n * n)};
  for (int f = 0; f < 6; ++f) {
    const bool y_face = f == 2 || f == 3;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int si = y_face ? i : n - 1 - i, sj = y_face ? n - 1 - j : j;
        strip.pixels[(std::size_t(f) * n + j) * n + i] = faces.texels[(std::size_t(f) * n + sj) * n + si];
      }
  }
  ImageEncoding encoding = exr_encoding({"Y"});
  encoding.attributes.push_back({"textureformat", "CubeFace Environment"});
  out.write("cover_envcube.exr", encode_image(strip, encoding, "cover_envcube.exr"));
  names.push_back("cover_envcube.exr");
  out.write("README.txt",
            readme(preset, faces,
                   "File: cover_envcube.exr, an OpenEXR cube environment map (header envmap = cube):\n"
                   "an N x 6N vertical strip of the faces +X, -X, +Y, -Y, +Z, -Z, each mirrored as\n"
                   "OpenEXR's cube layout wants relative to the GL faces (X and Z faces left-right, Y\n"
                   "faces top-bottom). For renderers that take OpenEXR environment cubes (RenderMan-\n"
                   "style lookups, OpenEXR's envmap tools). OpenImageIO 2.4 reads the file but cannot\n"
                   "sample it as a cube environment. Axes as for gl-faces: +Z is the North Pole.\n"));
  names.push_back("README.txt");
}

}  // namespace

CoverFaces read_cover_faces(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory))
    throw core::InputError("COVER_DIR", directory.string(), "a directory written by nephele generate", "is not a directory");
  CoverFaces faces;
  for (int f = 0; f < 6; ++f) {
    const std::filesystem::path path = directory / (std::string("cover_") + face_suffixes[f] + ".exr");
    if (!std::filesystem::is_regular_file(path))
      throw core::InputError("COVER_DIR", directory.string(),
                             "a directory with cover_px.exr ... cover_nz.exr (nephele generate --files faces)",
                             "has no " + path.filename().string());
    ImageData image;
    try {
      image = read_image(path);
    } catch (const std::exception& e) {
      throw core::InputError("COVER_DIR", path.string(), "an OpenEXR cube face", std::string("cannot be read: ") + e.what());
    }
    if (image.width != image.height || image.width < 1 || (f > 0 && image.width != faces.size))
      throw core::InputError("COVER_DIR", path.string(), "six square faces of one size",
                             "is " + std::to_string(image.width) + " x " + std::to_string(image.height));
    faces.size = image.width;
    for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i)
      faces.texels.push_back(image.pixels[i * std::size_t(image.channels)]);
  }
  return faces;
}

const std::vector<ExportPreset>& export_presets() {
  static const std::vector<ExportPreset> presets = {
      {"equirect", "2:1 lat-long map: float EXR, 16-bit PNG, 8-bit PNG", true},
      {"gl-faces", "six OpenEXR cube faces in the OpenGL order and orientation", false},
      {"ktx2", "KTX 2.0 cube map (R16_SFLOAT, R32_SFLOAT or R8_UNORM; --format)", false},
      {"dds", "DDS cube maps: legacy RGBA8 and DX10 R16_FLOAT / R32_FLOAT", false},
      {"celestia", "Celestia add-on: RGBA cloud map (white, coverage in alpha) and .ssc", true},
      {"exr-cube", "OpenEXR cube environment map (N x 6N strip, envmap = cube)", false},
  };
  return presets;
}

const ExportPreset& find_export_preset(const std::string& name) {
  for (const auto& p : export_presets())
    if (p.name == name) return p;
  throw core::InputError("--preset", name, preset_words());
}

std::vector<std::string> write_export(OutputSet& outputs, const ExportPreset& preset, const CoverFaces& faces,
                                      const ExportOptions& options) {
  std::vector<std::string> names;
  if (preset.name == "equirect") write_equirect(outputs, names, preset, faces);
  else if (preset.name == "gl-faces") write_gl_faces(outputs, names, preset, faces);
  else if (preset.name == "ktx2") write_ktx2(outputs, names, preset, faces, options);
  else if (preset.name == "dds") write_dds(outputs, names, preset, faces);
  else if (preset.name == "celestia") write_celestia(outputs, names, preset, faces, options);
  else if (preset.name == "exr-cube") write_exr_cube(outputs, names, preset, faces);
  else throw core::InputError("--preset", preset.name, preset_words());
  return names;
}

}  // namespace nephele::io
