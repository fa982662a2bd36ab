// The export presets of plain images: the equirect map and the six GL faces (docs/export.md).
#include "core/error.hpp"
#include "files/image_files.hpp"
#include "io/cover_files.hpp"
#include "io/export_writers.hpp"

namespace nephele::io {

void write_equirect(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                    const CoverFaces& faces, const ExportOptions& options) {
  const core::ImageData map = equirect_image(faces, options);
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
                    const CoverFaces& faces, const ExportOptions& options) {
  for (int f = 0; f < 6; ++f) {
    report_progress(options, f / 6.0, "face " + std::to_string(f + 1) + " of 6");
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

}  // namespace nephele::io
