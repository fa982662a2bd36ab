// The image codecs through OpenImageIO, built as the module nephele_image_codecs.so that
// image_files.cpp loads on first use (files/image_codecs.hpp says why). It links nothing of
// nephele's: its arguments come checked, its files open.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "core/file_descriptor.hpp"
#include "files/image_codecs.hpp"

namespace nephele::files {
namespace {

// The writer and the header of an EXR image as `encoding` says (PNGs are libpng's:
// files/png_encoder.hpp); encode_image and the row writer share them, so that both give the same
// bytes.
std::pair<std::unique_ptr<OIIO::ImageOutput>, OIIO::ImageSpec> image_writer(int width, int height, int channels,
                                                                            const ImageEncoding& encoding,
                                                                            const std::string& what) {
  if (encoding.format != ImageFormat::exr) throw std::invalid_argument(what + ": the codec module writes EXR only");
  auto out = OIIO::ImageOutput::create("openexr");
  if (!out) throw std::runtime_error("no image writer for " + what + ": " + OIIO::geterror());
  if (!out->supports("ioproxy")) throw std::runtime_error("the openexr writer cannot write through a proxy");
  const OIIO::TypeDesc type = encoding.bits == 16 ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(width, height, channels, type);
  if (!encoding.channel_names.empty()) spec.channelnames = encoding.channel_names;
  if (!encoding.half_channels.empty()) {
    // Channels of their own precision: the file's format per channel, half where asked.
    for (int c = 0; c < channels; ++c)
      spec.channelformats.push_back(encoding.half_channels[static_cast<size_t>(c)] ? OIIO::TypeDesc::HALF : type);
  }
  spec.attribute("compression", encoding.compression);
  spec.attribute("Software", "nephele");
  spec.attribute("DateTime", "");
  for (const auto& [name, value] : encoding.attributes) spec.attribute(name, value);
  if (encoding.unassociated_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
  return {std::move(out), spec};
}

// Writes through a file descriptor, every write checked: a failed or short write is kept and
// reported by error_number() (OpenImageIO's own file proxy does not report a failed fwrite).
class CheckedFileProxy : public OIIO::Filesystem::IOProxy {
 public:
  CheckedFileProxy(const std::string& path, int fd) : IOProxy(path, Write), fd_(fd) {}
  const char* proxytype() const override { return "nephele-fd"; }
  size_t write(const void* buf, size_t size) override {
    const size_t n = pwrite(buf, size, m_pos);
    m_pos += static_cast<int64_t>(n);
    return n;
  }
  size_t pwrite(const void* buf, size_t size, int64_t offset) override {
    if (!core::write_exactly_at(fd_, buf, size, static_cast<off_t>(offset))) {
      error_ = errno;
      return 0;
    }
    end_ = std::max<int64_t>(end_, offset + static_cast<int64_t>(size));
    return size;
  }
  size_t size() const override { return static_cast<size_t>(end_); }
  int error_number() const { return error_; }

 private:
  int fd_;
  int error_ = 0;
  int64_t end_ = 0;
};

std::vector<unsigned char> encode_image(const ImageData& image, const ImageEncoding& encoding,
                                        const std::string& what) {
  auto [out, spec] = image_writer(image.width, image.height, image.channels, encoding, what);
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  const auto fail = [&](const char* step) {
    return std::runtime_error("could not " + std::string(step) + " " + what + ": " + out->geterror());
  };
  if (!out->set_ioproxy(&memory)) throw fail("encode");
  if (!out->open(what, spec)) throw fail("open");
  if (!out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data())) throw fail("encode");
  if (!out->close()) throw fail("close");
  if (out->has_error()) throw fail("encode");
  return bytes;
}

std::vector<unsigned char> encode_animation(const std::vector<ImageData>& frames, int frames_per_second,
                                            const std::string& what) {
  auto out = OIIO::ImageOutput::create("gif");
  if (!out || !out->supports("ioproxy") || !out->supports("appendsubimage"))
    throw std::runtime_error("no animated GIF writer for " + what + ": " + OIIO::geterror());
  const ImageData& first = frames.front();
  OIIO::ImageSpec spec(first.width, first.height, first.channels, OIIO::TypeDesc::UINT8);
  const int rate[2] = {frames_per_second, 1};
  spec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
  spec.attribute("oiio:LoopCount", 0);  // forever
  std::vector<OIIO::ImageSpec> specs(frames.size(), spec);
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  const auto fail = [&](const char* step) {
    return std::runtime_error("could not " + std::string(step) + " " + what + ": " + out->geterror());
  };
  if (!out->set_ioproxy(&memory)) throw fail("encode");
  if (!out->open(what, static_cast<int>(specs.size()), specs.data())) throw fail("open");
  for (size_t k = 0; k < frames.size(); ++k) {
    if (k > 0 && !out->open(what, spec, OIIO::ImageOutput::AppendSubimage)) throw fail("append a frame to");
    if (!out->write_image(OIIO::TypeDesc::FLOAT, frames[k].pixels.data())) throw fail("encode");
  }
  if (!out->close()) throw fail("close");
  if (out->has_error()) throw fail("encode");
  return bytes;
}

}  // namespace

struct ImageWriterHandle {
  std::string what;
  std::unique_ptr<CheckedFileProxy> proxy;
  std::unique_ptr<OIIO::ImageOutput> out;
  bool finished = false;
};

struct ImageReaderHandle {
  std::string path;
  std::unique_ptr<OIIO::ImageInput> in;
};

namespace {

// A failed write names the proxy's error where it has one (a full disk), else the writer's.
void check_written(const ImageWriterHandle& w) {
  if (w.proxy->error_number() != 0)
    throw std::runtime_error("could not write " + w.what + ": " + std::strerror(w.proxy->error_number()));
}

ImageWriterHandle* open_writer(int fd, const std::string& what, int width, int height, int channels,
                               const ImageEncoding& encoding) {
  auto w = std::make_unique<ImageWriterHandle>();
  w->what = what;
  auto [out, spec] = image_writer(width, height, channels, encoding, what);
  w->out = std::move(out);
  w->proxy = std::make_unique<CheckedFileProxy>(what, fd);
  if (!w->out->set_ioproxy(w->proxy.get()) || !w->out->open(what, spec))
    throw std::runtime_error("could not open " + what + ": " + w->out->geterror());
  return w.release();
}

void write_rows(ImageWriterHandle* w, int first_row, int rows, const float* pixels) {
  const bool written =
      rows <= 0 || w->out->write_scanlines(first_row, first_row + rows, 0, OIIO::TypeDesc::FLOAT, pixels);
  check_written(*w);  // the system's reason first ("File too large"), OpenEXR's words hide it
  if (!written) throw std::runtime_error("could not write " + w->what + ": " + w->out->geterror());
}

void finish_writer(ImageWriterHandle* w) {
  const bool closed = w->out->close();
  w->finished = true;
  check_written(*w);
  if (!closed || w->out->has_error())
    throw std::runtime_error("could not close " + w->what + ": " + w->out->geterror());
}

void free_writer(ImageWriterHandle* w) {
  if (w && w->out && !w->finished) w->out->close();
  delete w;
}

ImageReaderHandle* open_reader(const std::string& path, ImageHeader& header) {
  auto r = std::make_unique<ImageReaderHandle>();
  r->path = path;
  r->in = OIIO::ImageInput::open(path);
  if (!r->in) throw std::runtime_error("could not read " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = r->in->spec();
  const auto base = spec.format.basetype;
  header = {spec.width, spec.height, spec.nchannels,
            base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE,
            std::vector<std::string>(spec.channelnames.begin(), spec.channelnames.end())};
  return r.release();
}

void read_rows(ImageReaderHandle* r, int first_row, int rows, float* out) {
  const int channels = r->in->spec().nchannels;
  if (rows > 0 && !r->in->read_scanlines(0, 0, first_row, first_row + rows, 0, 0, channels, OIIO::TypeDesc::FLOAT, out))
    throw std::runtime_error("could not read " + r->path + ": " + r->in->geterror());
}

void read_all(ImageReaderHandle* r, float* out) {
  if (!r->in->read_image(0, 0, 0, r->in->spec().nchannels, OIIO::TypeDesc::FLOAT, out))
    throw std::runtime_error("could not read " + r->path + ": " + r->in->geterror());
}

void free_reader(ImageReaderHandle* r) {
  if (r && r->in) r->in->close();
  delete r;
}

bool draw_text(ImageData& image, int x, int y, const std::string& text, int size, const float rgb[3],
               const char* font) {
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec, image.pixels.data());  // draws into the image's own pixels
  return OIIO::ImageBufAlgo::render_text(buffer, x, y, text, size, font, OIIO::cspan<float>(rgb, 3));
}

const ImageCodecs table = {image_codecs_version, encode_image, encode_animation, open_writer, write_rows,
                           finish_writer,        free_writer,  open_reader,      read_rows,   read_all,
                           free_reader,          draw_text};

}  // namespace
}  // namespace nephele::files

extern "C" __attribute__((visibility("default"))) const nephele::files::ImageCodecs* nephele_image_codecs() {
  return &nephele::files::table;
}
