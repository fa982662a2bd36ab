// The export presets of planetaria and simulators: Celestia, FlightGear Earthview and KSP's EVE
// (docs/export.md).
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "cover/equirect.hpp"
#include "cover/streamed_equirect.hpp"
#include "files/image_files.hpp"
#include "files/texture_containers.hpp"
#include "io/cover_files.hpp"
#include "io/cube_frames.hpp"
#include "io/export_writers.hpp"
#include "noise/noise_spec.hpp"

namespace nephele::io {
namespace {

// Until the cover carries a cloud-top height (docs/formats.md), the normal maps take the height
// as cloud_relief_m times the coverage: the step of a cloud deck's top over clear sky is of the
// order of a boundary-layer cloud's depth, 1-3 km (stratocumulus tops at 1-2 km).
constexpr double cloud_relief_m = 2000.0;

}  // namespace

// Celestia's normal-map convention (src/celengine/shadermanager.cpp and the sphere's per-vertex
// tangent (sin theta, 0, -cos theta), render.cpp): red the east component, green the south one
// (down the image: row 0 is north), blue up, each 2 c - 1. For a height field h on the 4N x 2N
// equirect the surface normal in (east, south, up) is (-h_e, h_n, 1) / m with h_e and h_n the
// slopes to the east and north (central differences; longitude wraps, the pole rows take the
// one-sided difference) and m the length. 8-bit RGB, linear.
core::ImageData celestia_normal_map(const core::ImageData& map, double relief_m) {
  constexpr double earth_radius_m = 6371000.0;  // mean radius (IUGG): the map's scale
  const int w = map.width, h = map.height;
  core::ImageData normals{w, h, 3, std::vector<float>(std::size_t(3) * w * h)};
  const double pi = 3.14159265358979323846, step_lon = 2 * pi / w, step_lat = pi / h;
  const auto height = [&](int x, int y) { return relief_m * map.pixels[std::size_t(y) * w + ((x + w) % w)]; };
  for (int y = 0; y < h; ++y) {
    const double latitude = pi / 2 - (y + 0.5) * step_lat;
    const double east_m = earth_radius_m * std::cos(latitude) * step_lon, north_m = earth_radius_m * step_lat;
    const int above = std::max(0, y - 1), below = std::min(h - 1, y + 1);  // above: further north
    for (int x = 0; x < w; ++x) {
      const double slope_east = (height(x + 1, y) - height(x - 1, y)) / (2 * east_m);
      const double slope_north = (height(x, above) - height(x, below)) / ((below - above) * north_m);
      const double length = std::sqrt(1 + slope_east * slope_east + slope_north * slope_north);
      float* n = &normals.pixels[(std::size_t(y) * w + x) * 3];
      n[0] = float(0.5 - 0.5 * slope_east / length);
      n[1] = float(0.5 + 0.5 * slope_north / length);
      n[2] = float(0.5 + 0.5 / length);
    }
  }
  return normals;
}

namespace {

// The CloudMap as a Celestia virtual texture (Celestia's src/celengine/virtualtex.cpp): NAME.ctx
// names the folder NAME beside it, BaseSplit 0 and the tile edge T; folder levelK holds the
// 2^(K+1) x 2^K tiles tx_U_V.dds of level K, the map 2^(K+1) T wide, U from the -180 deg edge
// and V from the north, each T x T DXT5 (white, coverage in alpha) with its mips. The finest
// level is the first at least as wide as the cover's 4 N map (Celestia reads 13 at most); each
// level is sampled on the CPU from the cube box-filtered to a quarter of the level's width per
// face (reduced_faces), so a coarse level averages the texels it covers. Returns the README's
// description of the files.
std::string write_celestia_virtual_texture(files::OutputSet& out, std::vector<std::string>& names,
                                           const CoverFaces& faces, const ExportOptions& options,
                                           const std::string& folder, int tile) {
  int levels = 1;
  while ((static_cast<long long>(tile) << levels) < 4LL * faces.size) ++levels;
  if (levels > 13)
    throw core::InputError("COVER_DIR", "face size " + std::to_string(faces.size),
                           "at most 13 levels of " + std::to_string(tile) + "-texel tiles for preset celestia",
                           "needs " + std::to_string(levels) + " levels (Celestia reads 13)");
  const std::string directory = folder + "textures/hires/" + options.name;
  for (int level = 0; level < levels; ++level) {
    const int width = tile << (level + 1), height = width / 2, face = std::max(1, width / 4);
    // The finest level reads the cover's own faces (no copy: 6.4 GB at 16384).
    const std::vector<float> reduced =
        face < faces.size ? reduced_faces(faces.size, faces.texels, face) : std::vector<float>{};
    const int n = std::min(face, faces.size);
    const std::array<const float*, 6> face_rows =
        face_pointers(n, face < faces.size ? reduced.data() : faces.texels.data());
    const std::vector<glm::vec2> rows = cover::geodetic_row_directions(height);
    std::vector<float> values(static_cast<size_t>(tile) * tile);
    for (int v = 0; v < (1 << level); ++v)
      for (int u = 0; u < (2 << level); ++u) {
        // Level k holds 2^(2k+1) of the (4^levels - 1) 2/3 tiles.
        const double before = 2.0 * ((1 << (2 * level)) - 1) / 3.0 + double(v * (2 << level) + u);
        report_progress(options, before / (2.0 * ((1 << (2 * levels)) - 1) / 3.0), "level " + std::to_string(level));
        cover::equirect_region(n, face_rows.data(), width, rows, cover::PixelTile{u * tile, v * tile, tile, tile},
                               values.data());
        const std::string name = directory + "/level" + std::to_string(level) + "/tx_" + std::to_string(u) + "_" +
                                 std::to_string(v) + ".dds";
        out.write(name, files::encode_dds(files::build_mip_chain(values, tile, tile, 1, 1), files::TexelFormat::bc3,
                                          files::GreyLayout::white_alpha));
      }
  }
  names.push_back(directory + "/level0 .. level" + std::to_string(levels - 1));
  const std::string ctx = directory + ".ctx";
  out.write(ctx, "# nephele cloud cover as a Celestia virtual texture: " + std::to_string(levels) + " levels of " +
                     std::to_string(tile) + "-texel DXT5 tiles in " + options.name +
                     "/levelK/tx_U_V.dds\nVirtualTexture\n{\n\tImageDirectory \"" + options.name +
                     "\"\n\tBaseSplit 0\n\tTileSize " + std::to_string(tile) + "\n\tTileType \"dds\"\n}\n");
  names.push_back(ctx);
  return "Files: " + ctx + " (a Celestia virtual texture, the .ssc's CloudMap) and the folder " + directory +
         "\n(levels 0 to " + std::to_string(levels - 1) + "; level K holds 2^(K+1) x 2^K tiles tx_U_V.dds of " +
         std::to_string(tile) + " x " + std::to_string(tile) +
         " texels, U from longitude -180 deg, V from the\nnorth; DDS DXT5, white with coverage in alpha, with "
         "mips; the finest level " +
         std::to_string(static_cast<long long>(tile) << levels) + " x " +
         std::to_string(static_cast<long long>(tile) << (levels - 1)) + " texels) and " + folder + options.name +
         ".ssc. The map is too wide for one texture,\nso no CloudNormalMap is written.\n";
}

}  // namespace

void write_celestia(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions& options) {
  const std::string folder = "extras/" + options.name + "/";
  const int tile = options.celestia_tile > 0 ? options.celestia_tile : equirect_on_cpu(faces.size, options) ? 1024 : 0;
  if (tile > 0) {
    const std::string files = write_celestia_virtual_texture(out, names, faces, options, folder, tile);
    const std::string ssc = folder + options.name + ".ssc";
    out.write(ssc,
              "# nephele cloud cover for Celestia: copy extras/" + options.name +
                  " into Celestia's extras folder.\nModify \"Earth\" \"Sol\"\n{\n\tAtmosphere\n\t{\n\t\tCloudMap \"" +
                  options.name + ".ctx\"\n\t\tCloudShadowDepth 1\n\t}\n}\n");
    names.push_back(ssc);
    add_readme(out, names, preset, faces,
               files + "Install: copy the folder extras/" + options.name +
                   " into Celestia's extras directory and restart Celestia (the\nvirtual texture's tiles load as "
                   "they come into view).\n");
    return;
  }
  const core::ImageData map = equirect_image(faces, options);
  // White cloud colour, coverage in alpha; the equirect already has the prime meridian at the centre.
  core::ImageData rgba{map.width, map.height, 4, std::vector<float>(std::size_t(4) * map.pixels.size(), 1.0f)};
  for (std::size_t i = 0; i < map.pixels.size(); ++i) rgba.pixels[4 * i + 3] = std::clamp(map.pixels[i], 0.0f, 1.0f);
  const std::string texture = folder + "textures/hires/" + options.name + ".png";
  files::ImageEncoding encoding = files::png_encoding(8);
  encoding.unassociated_alpha = true;  // PNG's alpha is unassociated: the colour stays white
  out.write(texture, files::encode_image(rgba, encoding, texture));
  names.push_back(texture);
  // The same map as DXT5 with every mip level: Celestia's DDS loader (src/celimage/dds.cpp) reads
  // DXT1, DXT3 and DXT5 with their mips; a quarter of the PNG's GPU memory, no shimmer from orbit.
  const std::string compressed = folder + "textures/hires/" + options.name + ".dds";
  out.write(compressed, files::encode_dds(files::build_mip_chain(map.pixels, map.width, map.height, 1, 1),
                                          files::TexelFormat::bc3, files::GreyLayout::white_alpha));
  names.push_back(compressed);
  const std::string normal_map = folder + "textures/hires/" + options.name + "_normal.png";
  out.write(normal_map,
            files::encode_image(celestia_normal_map(map, cloud_relief_m), files::png_encoding(8), normal_map));
  names.push_back(normal_map);
  const std::string ssc = folder + options.name + ".ssc";
  // CloudShadowDepth above 0 turns on the clouds' shadows on the ground, darkened by 0.75 times
  // the cloud map's alpha (Celestia's solarsys.cpp ReadAtmosphere, shadermanager.cpp).
  out.write(ssc, "# nephele cloud cover for Celestia: copy extras/" + options.name +
                     " into Celestia's extras folder.\n"
                     "# CloudMap may name " +
                     options.name +
                     ".png instead (lossless, Celestia makes its mips).\n"
                     "Modify \"Earth\" \"Sol\"\n{\n\tAtmosphere\n\t{\n\t\tCloudMap \"" +
                     options.name + ".dds\"\n\t\tCloudNormalMap \"" + options.name +
                     "_normal.png\"\n\t\tCloudShadowDepth 1\n\t}\n}\n");
  names.push_back(ssc);
  add_readme(out, names, preset, faces,
             "Files: " + texture + " (RGBA 8-bit PNG, " + std::to_string(map.width) + " x " +
                 std::to_string(map.height) +
                 ", white, coverage in alpha, 2:1 with the prime meridian at\n"
                 "the centre and north up), " +
                 compressed +
                 " (the same map as DDS DXT5, BC3, with every\n"
                 "mip level: the .ssc's CloudMap), " +
                 normal_map +
                 " (the clouds' relief as a\n"
                 "tangent-space normal map, red east, green south, blue up, 8-bit linear: the .ssc's\n"
                 "CloudNormalMap; heights 2000 m times the coverage) and " +
                 ssc +
                 ".\n"
                 "Install: copy the folder extras/" +
                 options.name +
                 " into Celestia's extras directory (or the add-on\n"
                 "folder named by ExtrasDirectories in celestia.cfg) and restart Celestia. The .ssc\n"
                 "modifies Earth's atmosphere so that its CloudMap is this texture and the clouds cast\n"
                 "shadows (CloudShadowDepth 1); Celestia looks it up in textures/hires/ when the\n"
                 "high-resolution texture setting is chosen (it falls back to the other resolutions'\n"
                 "folders otherwise).\n");
}

// FlightGear Earthview: eight tiles of 90 x 90 degrees whose shipped models (Models/Astro/
// clouds_*.ac) map UVs 1/128 .. 127/128, so the content fills the inner 126/128 of a tile and
// the border repeats the edge pixels (docs/export.md, "flightgear").
void write_flightgear(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                      const CoverFaces& faces, const ExportOptions& options) {
  const int tile = flightgear_tile_size(faces.size), border = tile / 128, content = tile - 2 * border;
  // The 4 content x 2 content map whole from the GPU pass, or each tile's 90 x 90 degrees from
  // the faces on the CPU where that map is too large (equirect_on_cpu).
  const bool on_cpu = equirect_on_cpu(faces.size, options);
  const core::ImageData map = on_cpu ? core::ImageData{} : equirect_image(faces, options, content);
  const std::vector<glm::vec2> rows = on_cpu ? cover::geodetic_row_directions(2 * content) : std::vector<glm::vec2>{};
  std::vector<float> block(on_cpu ? std::size_t(content) * content : 0);
  files::ImageEncoding encoding = files::png_encoding(8);
  encoding.unassociated_alpha = true;  // grey stays white where the alpha is small
  for (int h = 0; h < 2; ++h)
    for (int q = 0; q < 4; ++q) {
      report_progress(options, (4 * h + q) / 8.0, "tile " + std::to_string(4 * h + q + 1) + " of 8");
      if (on_cpu)
        cover::equirect_region(faces.size, face_pointers(faces.size, faces.texels.data()).data(), 4 * content, rows,
                               cover::PixelTile{q * content, h * content, content, content}, block.data());
      const auto value = [&](int cx, int cy) {  // (cx, cy) in the tile's content
        return on_cpu ? block[std::size_t(cy) * content + cx]
                      : map.pixels[std::size_t(h * content + cy) * map.width + q * content + cx];
      };
      std::vector<float> values(std::size_t(tile) * tile);
      for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x)
          values[std::size_t(y) * tile + x] =
              value(std::clamp(x - border, 0, content - 1), std::clamp(y - border, 0, content - 1));
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

namespace {

// EVE's _DetailTex: one tiling texture projected onto each cube face _DetailScale times, whose
// RGBA multiplies the layer's colour and alpha near the camera (Assets/Shaders/SphereCloud.shader:
// color = _Color main lerp(detail, 1, saturate(2 _DetailDist dist))). A slice of tileable 3D
// Perlin-Worley noise (the noise stage's channel, its GLSL compiled as C++), so it tiles
// seamlessly and looks alike in every direction across face edges, scaled to the statistics of
// the detail texture EVE's own configs ship (BoulderCo detail1: grey mean 0.81, standard
// deviation 0.05, alpha mean 0.87): grey 0.85 + 0.05 z, alpha grey + 0.02, with z the noise's
// standard score, clamped to [0.6, 1].
std::vector<float> eve_detail_texture(int size) {
  noise::TextureSpec spec;
  spec.width = spec.height = spec.depth = size;
  spec.seed = 1;
  spec.channels[0].type = noise::NoiseType::perlin_worley;
  spec.channels[0].cells = 8;
  spec.channels[0].octaves = 4;
  spec.channels[0].worley_cells = 8;
  spec.channels[0].worley_octaves = 3;
  const glsl::NoiseChannel channel = noise::channel_params(spec, 0);
  std::vector<double> values(std::size_t(size) * size);
  double sum = 0, squares = 0;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double v = glsl::perlin_worley_channel_value(glsl::vec3(float(i) + 0.5f, float(j) + 0.5f, 0.5f), channel);
      values[std::size_t(j) * size + i] = v;
      sum += v, squares += v * v;
    }
  const double n = double(values.size()), mean = sum / n;
  const double sd = std::sqrt(std::max(1e-12, squares / n - mean * mean));
  std::vector<float> rgba(4 * values.size());
  for (std::size_t t = 0; t < values.size(); ++t) {
    const double grey = std::clamp(0.85 + 0.05 * (values[t] - mean) / sd, 0.6, 1.0);
    rgba[4 * t] = rgba[4 * t + 1] = rgba[4 * t + 2] = float(grey);
    rgba[4 * t + 3] = float(std::min(1.0, grey + 0.02));
  }
  return rgba;
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

}  // namespace

void write_eve(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
               const CoverFaces& faces, const ExportOptions& options) {
  // EVE re-reads every DDS through its own loader (Utils/TextureConverter.cs, DDSToTexture),
  // which takes the FourCCs DXT1, DXT3 and DXT5 and no DX10 header: BC3 (DXT5) with RGB white
  // and the coverage in its 8-bit interpolated alpha, every mip level (docs/export.md, "eve").
  const auto eve_dds = [](std::vector<float> values, int width, int height) {
    return files::encode_dds(files::build_mip_chain(std::move(values), width, height, 1, 1), files::TexelFormat::bc3,
                             files::GreyLayout::white_alpha);
  };
  const std::string folder = "GameData/" + options.name + "/";
  core::ImageData map = equirect_image(faces, options);  // EVE's equirect: u as nephele's, v = 0 in row 0 (north)
  const std::string equirect = folder + "clouds_equirect.dds";
  out.write(equirect, eve_dds(std::move(map.pixels), map.width, map.height));
  names.push_back(equirect);
  const AxisMap eve_axes{{2, 0, 1}, {1, 1, 1}};  // nephele X = EVE z, Y = EVE x, Z = EVE y
  const char* const keys[6] = {"Xn", "Xp", "Yn", "Yp", "Zn", "Zp"};
  // EVE's managers read the child nodes of EVE_TEXTURE_CONFIG and EVE_CLOUDS, one object each
  // (EveManager/IEVEManager.cs, Apply); OBJECT is the name EVE's own configs give them.
  const std::string cube = options.name + "_cube";
  std::string config =
      "// nephele cloud cover for EVE (LGhassen/EnvironmentalVisualEnhancements): the six\n"
      "// faces as one cube texture, which " +
      options.name +
      "_clouds.cfg names as its layer's _MainTex.\nEVE_TEXTURE_CONFIG\n{\n\tOBJECT\n\t{\n\t\tname = " + cube +
      "\n\t\ttype = TEX_CUBE_6\n";
  const int n = faces.size;
  for (int f = 0; f < 6; ++f) {
    auto values = cover_by_direction(faces, n, n, [&](int i, int j) {
      return eve_axes.to_nephele(eve_face_direction(f, (i + 0.5) / n, (j + 0.5) / n));
    });
    std::string key = keys[f];
    std::string file = "clouds_" + std::string(1, char(std::tolower(key[0]))) + key[1] + ".dds";
    out.write(folder + file, eve_dds(std::move(values), n, n));
    names.push_back(folder + file);
    config += "\t\ttex" + key + " = " + options.name + "/" + file.substr(0, file.size() - 4) + "\n";
  }
  config += "\t}\n}\n";
  const int detail_size = 512;
  const std::string detail = folder + "clouds_detail.dds";
  out.write(detail,
            files::encode_dds(files::build_mip_chain(eve_detail_texture(detail_size), detail_size, detail_size, 1, 4),
                              files::TexelFormat::bc3));
  names.push_back(detail);
  const std::string cfg = folder + options.name + "_textures.cfg";
  out.write(cfg, config);
  names.push_back(cfg);
  // A 2D cloud layer on Kerbin with the cube as its main texture: `type = CubeMap` makes EVE look
  // the value up among the EVE_TEXTURE_CONFIG cubes (Utils/TextureWrapper.cs, isValid).
  const std::string clouds_cfg = folder + options.name + "_clouds.cfg";
  out.write(clouds_cfg,
            "// nephele cloud layer for EVE: Kerbin's 2D clouds from the cube of " + options.name +
                "_textures.cfg.\nEVE_CLOUDS\n{\n\tOBJECT\n\t{\n\t\tname = " + options.name +
                "\n\t\tbody = Kerbin\n\t\taltitude = 5000\n\t\tsettings\n\t\t{\n\t\t\t_MainTex\n\t\t\t{\n"
                "\t\t\t\tvalue = " +
                cube + "\n\t\t\t\ttype = CubeMap\n\t\t\t}\n\t\t\t_DetailTex = " + options.name +
                "/clouds_detail\n\t\t\t_DetailScale = 25\n\t\t}\n\t\tlayer2D\n\t\t{\n\t\t\tmacroCloudMaterial\n"
                "\t\t\t{\n\t\t\t}\n\t\t}\n\t}\n}\n");
  names.push_back(clouds_cfg);
  add_readme(out, names, preset, faces,
             "For Kerbal Space Program's Environmental Visual Enhancements, the fork\n"
             "LGhassen/EnvironmentalVisualEnhancements (its shader Assets/Shaders/cubeMap.cginc).\n"
             "Files (DDS with the legacy FourCC DXT5, BC3: RGB white, coverage in the interpolated\n"
             "alpha, every mip level down to 1 x 1; EVE's DDS reader takes DXT1, DXT3 and DXT5 only):\n"
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
                 detail +
                 "  512 x 512 tiling detail (DXT5 with mips: grey 0.85 +- 0.05,\n"
                 "      alpha 0.02 more), tileable Perlin-Worley noise, the layer's _DetailTex\n"
                 "  " +
                 cfg + "  EVE_TEXTURE_CONFIG with one OBJECT: the cube " + cube +
                 "\n      (type TEX_CUBE_6), its texXn .. texZp the faces (GameData paths without extension)\n"
                 "  " +
                 clouds_cfg +
                 "  EVE_CLOUDS with one OBJECT: a 2D layer on Kerbin at 5000 m\n"
                 "      whose _MainTex is { value = " +
                 cube +
                 ", type = CubeMap }, _DetailTex the detail, _DetailScale 25; edit body, altitude and the\n"
                 "      layer's other settings there, or delete it and name the cube in a layer of your own\n"
                 "KSP's Unity frame is left-handed: the faces are the cover reflected into it (nephele\n"
                 "X, Y, Z = EVE z, x, y), not the GL faces renamed. Install: copy GameData/" +
                 options.name +
                 " into KSP's\n"
                 "GameData. For the equirect instead of the cube, set _MainTex = " +
                 options.name +
                 "/clouds_equirect.\nRows are geodetic latitudes (EVE's v is spherical: at most 0.19 degrees apart).\n"
                 "Not checked in KSP (not available here).\n");
}

}  // namespace nephele::io
