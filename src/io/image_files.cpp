#include "io/image_files.hpp"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace nephele::io {
namespace {

void write_image(const std::filesystem::path& path, const ImageData& image, OIIO::ImageSpec spec,
                 const std::string& format_path) {
  const std::string chooser = format_path.empty() ? path.string() : format_path;
  auto out = OIIO::ImageOutput::create(chooser);
  if (!out) throw std::runtime_error("no image writer for " + chooser + ": " + OIIO::geterror());
  if (!out->open(path.string(), spec))
    throw std::runtime_error("could not open " + path.string() + ": " + out->geterror());
  if (!out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error("could not write " + path.string() + ": " + out->geterror());
  if (!out->close()) throw std::runtime_error("could not close " + path.string() + ": " + out->geterror());
}

}  // namespace

void write_float_image(const std::filesystem::path& path, const ImageData& image,
                       const std::vector<std::string>& channel_names, const std::string& format_path) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = channel_names;
  spec.attribute("compression", "zip");
  spec.attribute("Software", "nephele");
  write_image(path, image, spec, format_path);
}

void write_png8(const std::filesystem::path& path, const ImageData& image, const std::string& format_path) {
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
  spec.attribute("Software", "nephele");
  write_image(path, image, spec, format_path);
}

ImageData read_image(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("could not read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  ImageData image{spec.width, spec.height, spec.nchannels, {}};
  image.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error("could not read " + path.string() + ": " + in->geterror());
  in->close();
  return image;
}

}  // namespace nephele::io
