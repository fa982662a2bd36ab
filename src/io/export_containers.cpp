// The export presets of texture containers: KTX 2.0 and DDS cube maps, the OpenEXR cube
// environment map (docs/export.md).
#include "core/error.hpp"
#include "files/image_files.hpp"
#include "files/texture_containers.hpp"
#include "io/export_writers.hpp"

namespace nephele::io {

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

}  // namespace nephele::io
