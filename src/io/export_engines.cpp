// The export presets of game engines and renderers: Unity, Godot, Unreal and Blender
// (docs/export.md).
#include "core/error.hpp"
#include "files/image_files.hpp"
#include "io/cube_frames.hpp"
#include "io/export_writers.hpp"

namespace nephele::io {

namespace {

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

}  // namespace

// Unity: left-handed, Y up. Its frame for the cover: +Y north, +X longitude 0, +Z 90 E (so
// that the planet is seen unmirrored from outside): nephele X, Y, Z = Unity x, z, y, a
// reflection (the same swap as KSP's planetarium frame).
void write_unity(files::OutputSet& out, std::vector<std::string>& names, const ExportPreset& preset,
                 const CoverFaces& faces, const ExportOptions& options) {
  const core::ImageData map = equirect_image(faces, options);
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
                 const CoverFaces& faces, const ExportOptions& options) {
  const std::vector<float> godot_faces = faces_for_axes(faces, AxisMap{{2, 0, 1}, {1, 1, 1}});
  write_cube_layout(out, names, godot_faces, faces.size, 2, "cover_cube_2x3.png");
  write_cube_layout(out, names, godot_faces, faces.size, 6, "cover_cube_6x1.png");
  write_map_files(out, names, equirect_image(faces, options), "cover_panorama");
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
                  const CoverFaces& faces, const ExportOptions& options) {
  write_map_files(out, names, equirect_image(faces, options), "cover_equirect");
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
                   const CoverFaces& faces, const ExportOptions& options) {
  const core::ImageData map = equirect_image(faces, options);
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

}  // namespace nephele::io
