// The export presets of texture containers: KTX 2.0 and DDS cube maps, the OpenEXR cube
// environment map (docs/export.md).
#include <algorithm>

#include "core/error.hpp"
#include "core/parallel_rows.hpp"
#include "files/image_files.hpp"
#include "files/mip_chain.hpp"
#include "files/texture_containers.hpp"
#include "io/export_writers.hpp"
#include "shader_math/shader_math.hpp"

namespace nephele::io {

void write_ktx2(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                const CoverFaces& faces, const ExportOptions& options) {
  const files::TexelFormat format = files::parse_ktx2_format(options.ktx2_format);
  write_cube_containers(out, names, faces, {{"cover_cube.ktx2", true, format}}, options);
  add_readme(out, names, preset, faces,
             "File: cover_cube.ktx2, a KTX 2.0 cube map (faceCount 6, " +
                 std::to_string(files::full_mip_count(faces.size, faces.size)) + " mip levels from\n" +
                 std::to_string(faces.size) + " to 1, each the area mean of the level above; no supercompression), " +
                 files::vk_format_name(format) +
                 ",\nfaces in the order +X, -X, +Y, -Y, +Z, -Z with the OpenGL/Vulkan face orientation,\n"
                 "KTXorientation \"rd\". Load it with libktx (ktxTexture2_CreateFromNamedFile, then\n"
                 "ktxTexture_GLUpload or ktxTexture_VkUpload) or any KTX2 loader as a cube texture; no\n"
                 "flips are needed. World axes as for gl-faces: +Z is the North Pole.\n");
}

void write_dds(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
               const CoverFaces& faces, const ExportOptions& options) {
  write_cube_containers(out, names, faces,
                        {{"cover_cube_bc4.dds", false, files::TexelFormat::bc4},
                         {"cover_cube_bc3.dds", false, files::TexelFormat::bc3},
                         {"cover_cube_rgba8.dds", false, files::TexelFormat::rgba8},
                         {"cover_cube_r16f.dds", false, files::TexelFormat::r16f},
                         {"cover_cube_r32f.dds", false, files::TexelFormat::r32f}},
                        options);
  add_readme(out, names, preset, faces,
             "Files (DDS cube maps, faces +X, -X, +Y, -Y, +Z, -Z, rows top-down, each face with " +
                 std::to_string(files::full_mip_count(faces.size, faces.size)) +
                 "\nmip levels down to 1 x 1):\n"
                 "  cover_cube_bc4.dds    legacy header, FourCC ATI1 (BC4, one channel, 0.5 byte a\n"
                 "                        texel): Godot, Direct3D 10+ engines, DirectXTex\n"
                 "  cover_cube_bc3.dds    legacy header, FourCC DXT5 (BC3), coverage in R, G, B and A:\n"
                 "                        for loaders that read only DXT1/DXT5 (KSP, Unity, Blender)\n"
                 "  cover_cube_rgba8.dds  legacy header, uncompressed 32-bit RGBA, coverage in R, G, B\n"
                 "                        and A (KSP's texture loader, Unity's DDS importer,\n"
                 "                        OpenImageIO, GIMP)\n"
                 "  cover_cube_r16f.dds   DX10 header, DXGI_FORMAT_R16_FLOAT (54)\n"
                 "  cover_cube_r32f.dds   DX10 header, DXGI_FORMAT_R32_FLOAT (41): for Direct3D 10+\n"
                 "                        engines and DirectXTex (texconv, texassemble)\n"
                 "docs/export.md gives each block format's error against the float cover.\n"
                 "Faces are addressed as in OpenGL (Direct3D's cube addressing is the same). In a\n"
                 "left-handed engine (Unity, Unreal, KSP) the world must be reflected into nephele's\n"
                 "right-handed axes (+Z north): an axis rename alone mirrors the map.\n");
}

namespace {

// The direction of pixel (column c, row r) of `face` in OpenEXR's cube environment strip
// (OpenEXR, src/lib/OpenEXR/ImfEnvmap.cpp, CubeMap::pixelPosition and CubeMap::direction):
// positions run from face edge to face edge, 2 i/(n - 1) - 1, so the first and last pixels'
// centres lie on the cube's edges (not half a texel inside, as in OpenGL). OpenEXR's axes are
// nephele's (both right-handed; docs/export.md, "exr-cube").
glsl::vec3 openexr_pixel_direction(int face, int c, int r, int n) {
  const float s = n > 1 ? float(n - 1) : 1.0f;
  const float a = n > 1 ? 2.0f * float(c) / s - 1.0f : 0.0f, b = n > 1 ? 1.0f - 2.0f * float(r) / s : 0.0f;
  switch (face) {
    case 0: return {1.0f, b, a};    // +X
    case 1: return {-1.0f, b, -a};  // -X
    case 2: return {a, 1.0f, b};    // +Y
    case 3: return {a, -1.0f, -b};  // -Y
    case 4: return {-a, b, 1.0f};   // +Z
    default: return {a, b, -1.0f};  // -Z
  }
}

}  // namespace

// OpenEXR's cube environment map (header envmap = cube): an N x 6N vertical strip +X, -X, +Y,
// -Y, +Z, -Z whose pixels lie where openexr_pixel_direction says. Those are not the GL texel
// centres (and every face is mirrored relative to the GL face), so each pixel is the cover
// sampled bilinearly in its direction, seamless across face edges (shaders/lib/cube_sampling.glsl).
void write_exr_cube(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions& options) {
  const int n = faces.size;
  // The faces as one-channel rows (CubeSource's second form), the strip written row by row: a
  // cover of any size needs one row of the strip beside its faces.
  const std::array<const float*, 6> face_rows = face_pointers(n, faces.texels.data());
  const int first_row[6] = {0, 0, 0, 0, 0, 0};
  const glsl::CubeSource cube{n, nullptr, face_rows.data(), first_row};
  files::ImageEncoding encoding = files::exr_encoding({"Y"});
  encoding.attributes.push_back({"textureformat", "CubeFace Environment"});
  files::ImageRowWriter strip(out.reserve("cover_envcube.exr"), n, 6 * n, 1, encoding);
  const int band = std::max(1, std::min(n, (1 << 22) / n));  // rows of about 4 M pixels
  std::vector<float> rows(static_cast<std::size_t>(band) * n);
  for (int f = 0; f < 6; ++f)
    for (int r0 = 0; r0 < n; r0 += band) {
      report_progress(options, (f + double(r0) / n) / 6.0, "face " + std::to_string(f + 1) + " of 6");
      const int count = std::min(band, n - r0);
      core::parallel_rows(count, [&](int begin, int end) {
        for (int r = begin; r < end; ++r)
          for (int c = 0; c < n; ++c)
            rows[std::size_t(r) * n + c] =
                glsl::sample_cube_bilinear(glsl::normalize(openexr_pixel_direction(f, c, r0 + r, n)), cube).x;
      });
      strip.write_rows(count, rows.data());
    }
  strip.close();
  names.push_back("cover_envcube.exr");
  add_readme(out, names, preset, faces,
             "File: cover_envcube.exr, an OpenEXR cube environment map (header envmap = cube):\n"
             "an N x 6N vertical strip of the faces +X, -X, +Y, -Y, +Z, -Z in OpenEXR's layout\n"
             "(ImfEnvmap.cpp): a face's first and last pixels lie on the cube's edges, 2 i/(N - 1) - 1,\n"
             "so each pixel is the cover resampled bilinearly in its direction (the GL faces' texel\n"
             "centres lie half a texel inside). For renderers that take OpenEXR environment cubes\n"
             "(OpenEXR's envmap tools, RenderMan-style lookups). OpenImageIO 2.4 reads the file but\n"
             "cannot sample it as a cube environment. Axes as for gl-faces: +Z is the North Pole.\n");
}

}  // namespace nephele::io
