#include "io/planet_textures.hpp"

#include <cmath>
#include <system_error>

#include "core/error.hpp"
#include "io/export_presets.hpp"
#include "files/image_files.hpp"

namespace nephele::io {
namespace {

float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

core::ImageData read_equirect(const std::string& path, const std::string& option) {
  core::ImageData image;
  files::ImageHeader header;
  try {
    image = files::read_image(path, 0, &header);
  } catch (const std::exception& e) {
    throw core::InputError(option, path, "an equirect image file OpenImageIO reads (JPEG, PNG, EXR, ...)",
                           std::string("could not be read: ") + e.what());
  }
  if (image.width < 2) throw core::InputError(option, path, "an image of at least 2 x 1 pixels", "is too small");
  // Integer formats hold display-encoded (sRGB) colour; float formats hold linear values.
  if (!header.float_samples)
    for (size_t k = 0; k < image.pixels.size(); ++k)
      if (k % size_t(image.channels) < 3) image.pixels[k] = srgb_to_linear(image.pixels[k]);
  return image;
}

}  // namespace

PlanetTextures read_planet_textures(const std::string& day, const std::string& night, const std::string& option) {
  PlanetTextures out;
  std::error_code error;
  if (!day.empty()) {
    out.images.day = read_equirect(day, option);
    out.day_source = day;
    if (out.images.day.width != 2 * out.images.day.height)
      out.warnings.push_back(option + ": '" + day + "' is " + std::to_string(out.images.day.width) + " x " +
                             std::to_string(out.images.day.height) + ", not 2:1; it is stretched over the sphere");
  } else if (std::filesystem::is_regular_file(default_earth_texture, error)) {
    out.images.day = read_equirect(default_earth_texture, option);
    out.day_source = default_earth_texture;
  } else {
    out.images = render::procedural_planet();
    out.day_source = "procedural";
    out.warnings.push_back(std::string(default_earth_texture) +
                           " is missing (Debian package xplanet-images): a procedural ocean and land map stands in");
  }
  const std::string night_file = !night.empty() ? night
                                 : day.empty() && std::filesystem::is_regular_file(default_night_texture, error)
                                     ? std::string(default_night_texture)
                                     : std::string();
  if (!night_file.empty()) {
    out.images.night = read_equirect(night_file, "--night-texture");
    out.night_source = night_file;
  } else {
    out.night_source = "none";
  }
  return out;
}

render::CoverCube read_cover_cube(const std::filesystem::path& directory) {
  CoverFaces faces = read_cover_faces(directory);
  return {faces.size, std::move(faces.texels)};
}

}  // namespace nephele::io
