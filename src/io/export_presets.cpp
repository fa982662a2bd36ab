#include "io/export_presets.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <sstream>

#include "core/error.hpp"
#include "cover/equirect.hpp"
#include "gpu/textures.hpp"
#include "io/cover_files.hpp"
#include "io/cube_frames.hpp"
#include "files/image_files.hpp"
#include "files/texture_containers.hpp"

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

core::ImageData face_image(const CoverFaces& faces, int face) {
  const std::size_t n = std::size_t(faces.size) * std::size_t(faces.size);
  core::ImageData image{faces.size, faces.size, 1, {}};
  image.pixels.assign(faces.texels.begin() + std::ptrdiff_t(face * n),
                      faces.texels.begin() + std::ptrdiff_t((face + 1) * n));
  return image;
}

// The equirect of docs/conventions.md (4N x 2N, -180 deg at the left edge, geodetic rows),
// resampled on the GPU by the same pass as `generate`, so that both give the same map.
// `content` (default N) is the map's height over two: FlightGear's tiles want another size.
core::ImageData equirect_image(const CoverFaces& faces, int content = 0) {
  if (content == 0) content = faces.size;
  gpu::Texture cube = gpu::Texture::cube(faces.size, GL_R32F);
  cube.write(faces.texels);
  core::ImageData map{4 * content, 2 * content, 1, {}};
  map.pixels = cover::equirect_from_cube(cube, map.width, map.height);
  return map;
}

// One channel of `values` as an image, or white with `values` in alpha (`white_alpha`).
core::ImageData grey_image(int width, int height, std::vector<float> values, bool white_alpha = false) {
  if (!white_alpha) return core::ImageData{width, height, 1, std::move(values)};
  core::ImageData image{width, height, 2, std::vector<float>(2 * values.size(), 1.0f)};
  for (std::size_t i = 0; i < values.size(); ++i) image.pixels[2 * i + 1] = std::clamp(values[i], 0.0f, 1.0f);
  return image;
}

// --name becomes a folder and file names: keep it to a portable word.
void check_addon_name(const std::string& name) {
  if (!std::regex_match(name, std::regex("[A-Za-z0-9_-]{1,64}")))
    throw core::InputError("--name", name, "1 to 64 letters, digits, '_' or '-'");
}

std::string readme(const ExportPreset& preset, const CoverFaces& faces, const std::string& body) {
  std::ostringstream text;
  text << "nephele export, preset " << preset.name << ": " << preset.summary << "\n"
       << "Cover face size N = " << faces.size << ". Details and orientation: docs/export.md.\n\n"
       << body << "\n"
       << coverage_note;
  return text.str();
}

// The preset's README.txt, listed after its files.
void add_readme(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                const CoverFaces& faces, const std::string& body) {
  out.write("README.txt", readme(preset, faces, body));
  names.push_back("README.txt");
}

void write_equirect(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions&) {
  const core::ImageData map = equirect_image(faces);
  const std::pair<std::string, files::ImageEncoding> files[] = {{"cover_equirect.exr", files::exr_encoding({"Y"})},
                                                                {"cover_equirect_16.png", files::png_encoding(16)},
                                                                {"cover_equirect_8.png", files::png_encoding(8)}};
  for (const auto& [name, encoding] : files) {
    out.write(name, files::encode_image(map, encoding, name));
    names.push_back(name);
  }
  const std::string w = std::to_string(map.width), h = std::to_string(map.height);
  add_readme(out, names, preset, faces,
             "Files (" + w + " x " + h +
                 ", one grey channel, 2:1 plate carree):\n"
                 "  cover_equirect.exr     OpenEXR float32, channel Y\n"
                 "  cover_equirect_16.png  PNG 16-bit, value = round(65535 c)\n"
                 "  cover_equirect_8.png   PNG 8-bit, value = round(255 c), no gAMA/sRGB chunk\n"
                 "Orientation: north up, longitude -180 deg at the left edge, 0 at the centre;\n"
                 "column i at longitude -180 + 360 (i + 0.5)/W, row j at geodetic latitude\n"
                 "90 - 180 (j + 0.5)/H (WGS84). Use it wherever a lat-long / equirectangular\n"
                 "map is taken (NASA Blue Marble layout).\n");
}

void write_gl_faces(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions&) {
  for (int f = 0; f < 6; ++f) {
    const std::string name = std::string("cover_") + face_suffixes[f] + ".exr";
    out.write(name, files::encode_image(face_image(faces, f), files::exr_encoding({"Y"}), name));
    names.push_back(name);
  }
  add_readme(out, names, preset, faces,
             "Files: cover_px.exr, cover_nx.exr, cover_py.exr, cover_ny.exr, cover_pz.exr,\n"
             "cover_nz.exr: N x N OpenEXR float32, channel Y, the cube faces +X, -X, +Y, -Y,\n"
             "+Z (north), -Z (south) in the OpenGL convention (OpenGL 4.6 core, section 8.13,\n"
             "table 8.19). Upload face i to GL_TEXTURE_CUBE_MAP_POSITIVE_X + i as stored, row 0\n"
             "first, without flips. World axes: +X to 0 N 0 E, +Y to 0 N 90 E, +Z to the North\n"
             "Pole; a renderer with Y up must rotate its direction into these axes (a rotation,\n"
             "not an exchange of two axes, which would mirror the map).\n");
}

void write_ktx2(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                const CoverFaces& faces, const ExportOptions& options) {
  const files::TextureSample sample = files::parse_texture_sample(options.ktx2_format);
  out.write("cover_cube.ktx2", files::encode_ktx2_cube(faces.texels, faces.size, sample));
  names.push_back("cover_cube.ktx2");
  const std::string format = sample == files::TextureSample::r8     ? "VK_FORMAT_R8_UNORM (9)"
                             : sample == files::TextureSample::r16f ? "VK_FORMAT_R16_SFLOAT (76)"
                                                                    : "VK_FORMAT_R32_SFLOAT (100)";
  add_readme(out, names, preset, faces,
             "File: cover_cube.ktx2, a KTX 2.0 cube map (faceCount 6, one mip level, no\n"
             "supercompression), " +
                 format +
                 ", faces in the order +X, -X, +Y, -Y, +Z, -Z\n"
                 "with the OpenGL/Vulkan face orientation, KTXorientation \"rd\". Load it with\n"
                 "libktx (ktxTexture2_CreateFromNamedFile, then ktxTexture_GLUpload or\n"
                 "ktxTexture_VkUpload) or any KTX2 loader as a cube texture; no flips are needed.\n"
                 "World axes as for gl-faces: +Z is the North Pole.\n");
}

void write_dds(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
               const CoverFaces& faces, const ExportOptions&) {
  const std::pair<std::string, files::DdsVariant> files[] = {{"cover_cube_rgba8.dds", files::DdsVariant::rgba8},
                                                             {"cover_cube_r16f.dds", files::DdsVariant::dx10_r16f},
                                                             {"cover_cube_r32f.dds", files::DdsVariant::dx10_r32f}};
  for (const auto& [name, variant] : files) {
    out.write(name, files::encode_dds_cube(faces.texels, faces.size, variant));
    names.push_back(name);
  }
  add_readme(out, names, preset, faces,
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
             "right-handed axes (+Z north): an axis rename alone mirrors the map.\n");
}

void write_celestia(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions& options) {
  const core::ImageData map = equirect_image(faces);
  // White cloud colour, coverage in alpha; the equirect already has the prime meridian at the centre.
  core::ImageData rgba{map.width, map.height, 4, std::vector<float>(std::size_t(4) * map.pixels.size(), 1.0f)};
  for (std::size_t i = 0; i < map.pixels.size(); ++i) rgba.pixels[4 * i + 3] = std::clamp(map.pixels[i], 0.0f, 1.0f);
  const std::string folder = "extras/" + options.name + "/";
  const std::string texture = folder + "textures/hires/" + options.name + ".png";
  files::ImageEncoding encoding = files::png_encoding(8);
  encoding.unassociated_alpha = true;  // PNG's alpha is unassociated: the colour stays white
  out.write(texture, files::encode_image(rgba, encoding, texture));
  names.push_back(texture);
  const std::string ssc = folder + options.name + ".ssc";
  out.write(ssc, "# nephele cloud cover for Celestia: copy extras/" + options.name +
                     " into Celestia's extras folder.\n"
                     "Modify \"Earth\" \"Sol\"\n{\n\tAtmosphere\n\t{\n\t\tCloudMap \"" +
                     options.name + ".png\"\n\t}\n}\n");
  names.push_back(ssc);
  add_readme(out, names, preset, faces,
             "Files: " + texture + " (RGBA 8-bit PNG, " + std::to_string(map.width) + " x " +
                 std::to_string(map.height) +
                 ", white, coverage in alpha, 2:1 with the prime meridian at\n"
                 "the centre and north up) and " +
                 ssc +
                 ".\n"
                 "Install: copy the folder extras/" +
                 options.name +
                 " into Celestia's extras directory (or the add-on\n"
                 "folder named by ExtrasDirectories in celestia.cfg) and restart Celestia. The .ssc\n"
                 "modifies Earth's atmosphere so that its CloudMap is this texture; Celestia looks it\n"
                 "up in textures/hires/ when the high-resolution texture setting is chosen (it falls\n"
                 "back to the other resolutions' folders otherwise).\n");
}

// OpenEXR's cube environment layout (OpenEXR "envmap" attribute, ENVMAP_CUBE): an N x 6N
// vertical strip +X, -X, +Y, -Y, +Z, -Z with every face mirrored relative to the GL face: the
// X and Z faces left-right, the Y faces top-bottom (docs/conventions.md, "Other programs"; docs/export.md, "exr-cube").
void write_exr_cube(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions&) {
  const int n = faces.size;
  core::ImageData strip{n, 6 * n, 1, std::vector<float>(std::size_t(6) * n * n)};
  for (int f = 0; f < 6; ++f) {
    const bool y_face = f == 2 || f == 3;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int si = y_face ? i : n - 1 - i, sj = y_face ? n - 1 - j : j;
        strip.pixels[(std::size_t(f) * n + j) * n + i] = faces.texels[(std::size_t(f) * n + sj) * n + si];
      }
  }
  files::ImageEncoding encoding = files::exr_encoding({"Y"});
  encoding.attributes.push_back({"textureformat", "CubeFace Environment"});
  out.write("cover_envcube.exr", files::encode_image(strip, encoding, "cover_envcube.exr"));
  names.push_back("cover_envcube.exr");
  add_readme(out, names, preset, faces,
             "File: cover_envcube.exr, an OpenEXR cube environment map (header envmap = cube):\n"
             "an N x 6N vertical strip of the faces +X, -X, +Y, -Y, +Z, -Z, each mirrored as\n"
             "OpenEXR's cube layout wants relative to the GL faces (X and Z faces left-right, Y\n"
             "faces top-bottom). For renderers that take OpenEXR environment cubes (RenderMan-\n"
             "style lookups, OpenEXR's envmap tools). OpenImageIO 2.4 reads the file but cannot\n"
             "sample it as a cube environment. Axes as for gl-faces: +Z is the North Pole.\n");
}

// FlightGear Earthview: eight tiles of 90 x 90 degrees whose shipped models (Models/Astro/
// clouds_*.ac) map UVs 1/128 .. 127/128, so the content fills the inner 126/128 of a tile and
// the border repeats the edge pixels (docs/export.md, "flightgear").
void write_flightgear(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                      const CoverFaces& faces, const ExportOptions&) {
  const int tile = flightgear_tile_size(faces.size), border = tile / 128, content = tile - 2 * border;
  const core::ImageData map = equirect_image(faces, content);
  files::ImageEncoding encoding = files::png_encoding(8);
  encoding.unassociated_alpha = true;  // grey stays white where the alpha is small
  for (int h = 0; h < 2; ++h)
    for (int q = 0; q < 4; ++q) {
      std::vector<float> values(std::size_t(tile) * tile);
      for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x) {
          const int cx = q * content + std::clamp(x - border, 0, content - 1);
          const int cy = h * content + std::clamp(y - border, 0, content - 1);
          values[std::size_t(y) * tile + x] = map.pixels[std::size_t(cy) * map.width + cx];
        }
      const std::string name = std::string("clouds_") + (h ? "S" : "N") + std::to_string(q + 1) + ".png";
      out.write(name, files::encode_image(grey_image(tile, tile, std::move(values), true), encoding, name));
      names.push_back(name);
    }
  const std::string t = std::to_string(tile), b = std::to_string(border), c = std::to_string(content);
  add_readme(out, names, preset, faces,
             "Files: clouds_N1.png .. clouds_N4.png (latitude 90 N to 0) and clouds_S1.png ..\n"
             "clouds_S4.png (0 to 90 S); 1 to 4 are the longitudes 180 W-90 W, 90 W-0, 0-90 E,\n"
             "90 E-180 E. Each is " +
                 t + " x " + t +
                 " PNG grey + alpha, 8-bit: grey white, coverage in\n"
                 "alpha (unassociated), as FlightGear's shipped cloud tiles. The 90 degrees fill the\n"
                 "inner " +
                 c + " x " + c + " pixels; the " + b +
                 "-pixel border repeats the edge pixels, because the\n"
                 "shipped models Models/Astro/clouds_*.ac map their UVs from 1/128 to 127/128 of a tile.\n"
                 "Rows are geodetic latitudes, north up. Install: replace the files of the same names\n"
                 "in $FG_ROOT/Models/Astro/Textures/ (keep a copy of the shipped ones) or put them in\n"
                 "an aircraft's or a scenery overlay's Models/Astro/Textures/; Earthview shows them\n"
                 "when started (Menu: View > Earthview, or --prop:/earthview/show-clouds=1).\n");
}

// KSP's Environmental Visual Enhancements, the fork LGhassen/EnvironmentalVisualEnhancements
// (EVE Redux / Volumetrics; its Assets/Shaders/cubeMap.cginc keeps rbray89's 1.x mapping).
// EVE looks up an equirect with u = 0.5 + atan2(x, z)/2pi, v = acos(y)/pi in the body's frame,
// so that frame's geography is: +Z longitude 0, +X longitude 90 E, +Y north; for the six
// faces it inverts GetCubeCubeUV below. KSP's DDS loader puts the file's first row at v = 0.
Direction eve_face_direction(int face, double u, double v) {
  // face: 0 xn, 1 xp, 2 yn, 3 yp, 4 zn, 5 zp (EVE's key order texXn .. texZp).
  switch (face) {
    case 0: return {-1, 1 - 2 * v, 2 * u - 1};
    case 1: return {1, 1 - 2 * v, 1 - 2 * u};
    case 2: return {2 * u - 1, -1, 1 - 2 * v};
    case 3: return {2 * u - 1, 1, 2 * v - 1};
    case 4: return {1 - 2 * u, 1 - 2 * v, -1};
    default: return {2 * u - 1, 1 - 2 * v, 1};
  }
}

void write_eve(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
               const CoverFaces& faces, const ExportOptions& options) {
  const std::string folder = "GameData/" + options.name + "/";
  const core::ImageData map = equirect_image(faces);  // EVE's equirect: u as nephele's, v = 0 in row 0 (north)
  const std::string equirect = folder + "clouds_equirect.dds";
  out.write(equirect, files::encode_dds_2d(map.pixels, map.width, map.height, files::DdsVariant::rgba8_white));
  names.push_back(equirect);
  const AxisMap eve_axes{{2, 0, 1}, {1, 1, 1}};  // nephele X = EVE z, Y = EVE x, Z = EVE y
  const char* const keys[6] = {"Xn", "Xp", "Yn", "Yp", "Zn", "Zp"};
  std::string config =
      "// nephele cloud cover for EVE (LGhassen/EnvironmentalVisualEnhancements): the six\n"
      "// faces as one cube texture; name it as a layer's _MainTex.\n"
      "EVE_TEXTURE_CONFIG\n{\n\tname = " +
      options.name + "_cube\n\ttype = TEX_CUBE_6\n";
  const int n = faces.size;
  for (int f = 0; f < 6; ++f) {
    const auto values = cover_by_direction(faces, n, n, [&](int i, int j) {
      return eve_axes.to_nephele(eve_face_direction(f, (i + 0.5) / n, (j + 0.5) / n));
    });
    std::string key = keys[f];
    std::string file = "clouds_" + std::string(1, char(std::tolower(key[0]))) + key[1] + ".dds";
    out.write(folder + file, files::encode_dds_2d(values, n, n, files::DdsVariant::rgba8_white));
    names.push_back(folder + file);
    config += "\ttex" + key + " = " + options.name + "/" + file.substr(0, file.size() - 4) + "\n";
  }
  config += "}\n";
  const std::string cfg = folder + options.name + "_textures.cfg";
  out.write(cfg, config);
  names.push_back(cfg);
  add_readme(out, names, preset, faces,
             "For Kerbal Space Program's Environmental Visual Enhancements, the fork\n"
             "LGhassen/EnvironmentalVisualEnhancements (its shader Assets/Shaders/cubeMap.cginc).\n"
             "Files (legacy RGBA8 DDS, RGB white, coverage in alpha, one mip level):\n"
             "  " +
                 equirect + "  " + std::to_string(map.width) + " x " + std::to_string(map.height) +
                 " equirect in EVE's mapping\n"
                 "      u = 0.5 + atan2(x, z)/2pi, v = acos(y)/pi: column i at longitude -180 + 360 (i + 0.5)/W\n"
                 "      (+Z of the body is longitude 0, +X 90 E), row j at v = (j + 0.5)/H (north first:\n"
                 "      KSP's DDS loader puts a file's first row at v = 0)\n"
                 "  " +
                 folder +
                 "clouds_xn.dds .. clouds_zp.dds  the six faces as EVE's GetCubeCubeUV samples\n"
                 "      them (texXn .. texZp), same frame\n"
                 "  " +
                 cfg +
                 "  an EVE_TEXTURE_CONFIG node (type TEX_CUBE_6) whose texXn .. texZp\n"
                 "      keys name the faces (GameData paths without extension)\n"
                 "KSP's Unity frame is left-handed: the faces are the cover reflected into it (nephele\n"
                 "X, Y, Z = EVE z, x, y), not the GL faces renamed. Install: copy GameData/" +
                 options.name +
                 " into KSP's\n"
                 "GameData; in a cloud layer's config set _MainTex to " +
                 options.name +
                 "/clouds_equirect (one texture) or\n"
                 "to " +
                 options.name +
                 "_cube (the faces). Rows are geodetic latitudes (EVE's v is spherical: at most\n"
                 "0.19 degrees apart). Not checked in KSP (not available here).\n");
}

// A face strip or grid for an engine's cube importer, 16-bit grey PNG.
void write_cube_layout(files::OutputSet& out, std::vector<std::string>& names, const std::vector<float>& engine_faces,
                       int n, int columns, const std::string& name) {
  const core::ImageData image{columns * n, 6 / columns * n, 1, face_layout(engine_faces, n, columns)};
  out.write(name, files::encode_image(image, files::png_encoding(16), name));
  names.push_back(name);
}

void write_map_files(files::OutputSet& out, std::vector<std::string>& names, const core::ImageData& map,
                     const std::string& stem) {
  out.write(stem + ".exr", files::encode_image(map, files::exr_encoding({"Y"}), stem + ".exr"));
  names.push_back(stem + ".exr");
  out.write(stem + "_16.png", files::encode_image(map, files::png_encoding(16), stem + "_16.png"));
  names.push_back(stem + "_16.png");
}

const char* const map_orientation =
    "north up, longitude -180 at the left edge and 0 at the centre, column i at\n"
    "-180 + 360 (i + 0.5)/W, row j at geodetic latitude 90 - 180 (j + 0.5)/H";

// Unity: left-handed, Y up. Its frame for the cover: +Y north, +X longitude 0, +Z 90 E (so
// that the planet is seen unmirrored from outside): nephele X, Y, Z = Unity x, z, y, a
// reflection (the same swap as KSP's planetarium frame).
void write_unity(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                 const CoverFaces& faces, const ExportOptions&) {
  const core::ImageData map = equirect_image(faces);
  write_map_files(out, names, map, "cover_latlong");
  core::ImageData hdrp{map.width, map.height, 3, std::vector<float>(3 * map.pixels.size(), 0.0f)};
  for (std::size_t i = 0; i < map.pixels.size(); ++i) hdrp.pixels[3 * i] = map.pixels[i];
  out.write("cover_latlong_hdrp.png", files::encode_image(hdrp, files::png_encoding(16), "cover_latlong_hdrp.png"));
  names.push_back("cover_latlong_hdrp.png");
  write_cube_layout(out, names, faces_for_axes(faces, AxisMap{{0, 2, 1}, {1, 1, 1}}), faces.size, 6,
                    "cover_cube_6x1.png");
  add_readme(out, names, preset, faces,
             "Files:\n"
             "  cover_latlong.exr, cover_latlong_16.png  the lat-long map (float, 16-bit grey): " +
                 std::string(map_orientation) +
                 "\n"
                 "  cover_latlong_hdrp.png  the same map in red (16-bit RGB, G = B = 0): HDRP's Cloud Layer\n"
                 "      reads opacity from the red channel of its Cloud Map\n"
                 "  cover_cube_6x1.png  a horizontal strip of six faces +X, -X, +Y, -Y, +Z, -Z for\n"
                 "      Unity's cubemap import (Texture Shape Cube, Mapping 6 Frames Layout)\n"
                 "Unity is left-handed with +Y up; the faces hold the cover in the frame +Y north, +X\n"
                 "longitude 0, +Z 90 E (nephele X, Y, Z = Unity x, z, y): a reflection of nephele's\n"
                 "right-handed axes, which is what makes the planet unmirrored in Unity; renaming\n"
                 "axes alone would mirror it. Import settings: sRGB (Color Texture) off, Single\n"
                 "Channel Red or R16, no compression for data. Not checked in Unity (not available here).\n");
}

// Godot 4: right-handed, Y up, -Z forward. Frame for the cover: +Y north, +Z longitude 0,
// +X 90 E: nephele X, Y, Z = Godot z, x, y, a rotation.
void write_godot(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                 const CoverFaces& faces, const ExportOptions&) {
  const std::vector<float> godot_faces = faces_for_axes(faces, AxisMap{{2, 0, 1}, {1, 1, 1}});
  write_cube_layout(out, names, godot_faces, faces.size, 2, "cover_cube_2x3.png");
  write_cube_layout(out, names, godot_faces, faces.size, 6, "cover_cube_6x1.png");
  write_map_files(out, names, equirect_image(faces), "cover_panorama");
  add_readme(out, names, preset, faces,
             "Files:\n"
             "  cover_cube_2x3.png  six faces, 2 columns x 3 rows: +X -X / +Y -Y / +Z -Z (Godot's\n"
             "      default Cubemap import layout, 2x3), 16-bit grey\n"
             "  cover_cube_6x1.png  the same faces in one row (import layout 6x1)\n"
             "  cover_panorama.exr, cover_panorama_16.png  the equirect for a PanoramaSkyMaterial or\n"
             "      a sphere's material: " +
                 std::string(map_orientation) +
                 "\n"
                 "Godot is right-handed like OpenGL (Y up, -Z forward): the faces hold the cover in the\n"
                 "frame +Y north, +Z longitude 0, +X 90 E (nephele X, Y, Z = Godot z, x, y), a rotation,\n"
                 "so nothing is mirrored. Import as Cubemap with Compress Mode Lossless and no sRGB\n"
                 "(data). Not checked in Godot (not in Debian bookworm).\n");
}

void write_unreal(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                  const CoverFaces& faces, const ExportOptions&) {
  write_map_files(out, names, equirect_image(faces), "cover_equirect");
  add_readme(out, names, preset, faces,
             "Files: cover_equirect.exr (float) and cover_equirect_16.png (16-bit grey), linear 2D\n"
             "maps for a Volumetric Cloud material or a planet material: " +
                 std::string(map_orientation) +
                 ".\n"
                 "Import: sRGB off, Compression Settings HDR (EXR) or Grayscale / Alpha (16-bit PNG),\n"
                 "Texture Group World, no mip-gen bias. Unreal is left-handed with Z up (X forward,\n"
                 "Y right): for a unit direction (x, y, z) from the planet's centre in Unreal's frame,\n"
                 "the map's UV is u = 0.5 + atan2(-y, x)/(2 pi), v = 0.5 - asin(z)/pi: the minus sign on\n"
                 "y is the reflection between Unreal's left-handed axes and nephele's right-handed\n"
                 "ones (+X longitude 0, -Y 90 E, +Z north). Not the HDRI Backdrop (a sky dome for\n"
                 "product shots). Not checked in Unreal (not available here).\n");
}

// Blender (right-handed, Z up) maps an equirect with u = 0.5 - atan2(y, x)/2pi: a north-up,
// east-right map appears mirrored unless the Mapping node scales Y by -1.
void write_blender(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                   const CoverFaces& faces, const ExportOptions&) {
  const core::ImageData map = equirect_image(faces);
  out.write("cover_equirect.exr", files::encode_image(map, files::exr_encoding({"Y"}), "cover_equirect.exr"));
  names.push_back("cover_equirect.exr");
  out.write(
      "nephele_world.py",
      "# Sets cover_equirect.exr (next to this script, or the path after --) as the World of\n"
      "# the current Blender scene, unmirrored: blender -b FILE.blend --python nephele_world.py\n"
      "# or Scripting > Run Script. Blender maps an equirect with u = 0.5 - atan2(y, x)/2pi, so\n"
      "# the Mapping node scales Y by -1 to put 90 E on +Y (nephele's axes: +X 0 N 0 E, +Z north).\n"
      "import os, sys\nimport bpy\n\n"
      "args = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []\n"
      "path = args[0] if args else os.path.join(os.path.dirname(os.path.abspath(__file__)), 'cover_equirect.exr')\n"
      "world = bpy.context.scene.world or bpy.data.worlds.new('nephele')\n"
      "bpy.context.scene.world = world\nworld.use_nodes = True\nnodes, links = world.node_tree.nodes, "
      "world.node_tree.links\n"
      "nodes.clear()\n"
      "coords = nodes.new('ShaderNodeTexCoord')\nmapping = nodes.new('ShaderNodeMapping')\n"
      "mapping.inputs['Scale'].default_value = (1.0, -1.0, 1.0)\n"
      "texture = nodes.new('ShaderNodeTexEnvironment')\ntexture.projection = 'EQUIRECTANGULAR'\n"
      "texture.image = bpy.data.images.load(path, check_existing=True)\n"
      "texture.image.colorspace_settings.name = 'Non-Color'  # coverage is data\n"
      "background = nodes.new('ShaderNodeBackground')\noutput = nodes.new('ShaderNodeOutputWorld')\n"
      "links.new(coords.outputs['Generated'], mapping.inputs['Vector'])\n"
      "links.new(mapping.outputs['Vector'], texture.inputs['Vector'])\n"
      "links.new(texture.outputs['Color'], background.inputs['Color'])\n"
      "links.new(background.outputs['Background'], output.inputs['Surface'])\n");
  names.push_back("nephele_world.py");
  add_readme(out, names, preset, faces,
             "Files: cover_equirect.exr (float, channel Y; " + std::string(map_orientation) +
                 ")\n"
                 "and nephele_world.py. Blender is right-handed with Z up like nephele, but its\n"
                 "Environment Texture maps an equirect with u = 0.5 - atan2(y, x)/(2 pi): the map\n"
                 "appears mirrored (90 E on -Y) unless the vector is reflected first. Steps (World):\n"
                 "  1. Shading > World: add Texture Coordinate, Mapping, Environment Texture.\n"
                 "  2. Texture Coordinate Generated -> Mapping Vector; Mapping Scale X 1, Y -1, Z 1\n"
                 "     (scaling X instead would turn the map by 180 degrees of longitude).\n"
                 "  3. Mapping -> Environment Texture Vector; open cover_equirect.exr, Color Space\n"
                 "     Non-Color; Color -> Background.\n"
                 "or run nephele_world.py (blender -b FILE.blend --python nephele_world.py). For a\n"
                 "planet: the same chain in the sphere's material, fed by the object's direction\n"
                 "(Texture Coordinate Object -> Mapping Y -1 -> Environment Texture, which takes\n"
                 "any vector; see scripts/blender_planet.py). Checked in Blender 3.4.1:\n"
                 "scripts/check-blender-export.sh (docs/export.md, \"blender\").\n");
}

}  // namespace

namespace {

std::filesystem::path face_path(const std::filesystem::path& directory, int f) {
  return directory / (std::string("cover_") + face_suffixes[f] + ".exr");
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
    // A face holds coverage alone; reading one channel of a colour image would be a guess.
    if (header.channels != 1)
      throw core::InputError("COVER_DIR", path.string(), "one channel (Y) of coverage per face",
                             "has " + std::to_string(header.channels) + " channels");
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
    try {
      image = files::read_image(path);
    } catch (const std::exception& e) {
      throw core::InputError("COVER_DIR", path.string(), "an OpenEXR cube face",
                             std::string("cannot be read: ") + e.what());
    }
    // The headers were checked; a file replaced meanwhile is caught here.
    if (image.width != faces.size || image.height != faces.size || image.channels != 1)
      throw core::InputError("COVER_DIR", path.string(), "six square one-channel faces of one size",
                             "changed while read");
    for (std::size_t i = 0; i < texels; ++i) {
      const float v = image.pixels[i];
      if (!(v >= 0.0f && v <= 1.0f)) {  // NaN fails both
        char shown[32];
        std::snprintf(shown, sizeof shown, "%g", double(v));
        throw core::InputError("COVER_DIR", path.string(), "coverage values in [0, 1]",
                               std::string("holds ") + shown + " at texel " + std::to_string(i % faces.size) + ", " +
                                   std::to_string(i / faces.size));
      }
      faces.texels.push_back(v);
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

}  // namespace

const std::vector<ExportPreset>& export_presets() {
  // name, summary, needs_equirect, volume, takes_format, takes_name, writer, widest edge.
  static const std::vector<ExportPreset> presets = {
      {"equirect", "2:1 lat-long map: float EXR, 16-bit PNG, 8-bit PNG", true, false, false, false, write_equirect,
       equirect_edge},
      {"gl-faces", "six OpenEXR cube faces in the OpenGL order and orientation", false, false, false, false,
       write_gl_faces, faces_edge},
      {"ktx2", "KTX 2.0 cube map (R16_SFLOAT, R32_SFLOAT or R8_UNORM; --format)", false, false, true, false, write_ktx2,
       faces_edge},
      {"dds", "DDS cube maps: legacy RGBA8 and DX10 R16_FLOAT / R32_FLOAT", false, false, false, false, write_dds,
       faces_edge},
      {"celestia", "Celestia add-on: RGBA cloud map (white, coverage in alpha) and .ssc", true, false, false, true,
       write_celestia, equirect_edge},
      {"exr-cube", "OpenEXR cube environment map (N x 6N strip, envmap = cube)", false, false, false, false,
       write_exr_cube, faces_edge},
      {"flightgear", "FlightGear Earthview: eight bordered tiles clouds_N1..S4, grey + alpha", true, false, false,
       false, write_flightgear, tile_edge},
      {"eve", "KSP EVE (LGhassen's fork): equirect and six faces as DDS, EVE_TEXTURE_CONFIG", true, false, false, true,
       write_eve, equirect_edge},
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
                             " pixels engines and GPUs take (GL_MAX_TEXTURE_SIZE); use flightgear (tiles) or "
                             "gl-faces, ktx2, dds (cube faces), or generate a smaller --size");
}

void check_export_options(const ExportPreset& preset, const ExportOptions& options) {
  if (preset.takes_name) check_addon_name(options.name);
  if (preset.takes_format) files::parse_texture_sample(options.ktx2_format);
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
