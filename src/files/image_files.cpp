#include "files/image_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <memory>

#include "core/file_descriptor.hpp"
#include "core/input_file.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <stdexcept>

#include "files/atomic_output.hpp"

namespace nephele::files {

bool is_lossless_exr_compression(const std::string& name) {
  for (const char* lossless : {"none", "rle", "zips", "zip", "piz"})
    if (name == lossless) return true;
  return false;
}

bool is_exr_compression(const std::string& name) {
  return is_lossless_exr_compression(name) || name == "pxr24" || name == "b44" || name == "dwaa";
}

namespace {

// The writer and the header of an image as `encoding` says; encode_image and ImageRowWriter share
// them, so that both give the same bytes.
std::pair<std::unique_ptr<OIIO::ImageOutput>, OIIO::ImageSpec> image_writer(int width, int height, int channels,
                                                                            const ImageEncoding& encoding,
                                                                            const std::string& what) {
  const bool png = encoding.format == ImageFormat::png;
  if (png ? (encoding.bits != 8 && encoding.bits != 16) : (encoding.bits != 32 && encoding.bits != 16))
    throw std::invalid_argument(what + ": " + std::to_string(encoding.bits) +
                                "-bit images are not written (PNG: 8 or 16, EXR: 16 or 32)");
  if (!png && !is_exr_compression(encoding.compression))
    throw std::invalid_argument(what + ": unknown EXR compression '" + encoding.compression + "'");
  const char* format = png ? "png" : "openexr";
  auto out = OIIO::ImageOutput::create(format);
  if (!out) throw std::runtime_error("no image writer for " + what + ": " + OIIO::geterror());
  if (!out->supports("ioproxy"))
    throw std::runtime_error("the " + std::string(format) + " writer cannot write through a proxy");
  const OIIO::TypeDesc type = !png ? (encoding.bits == 16 ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT)
                              : encoding.bits == 16 ? OIIO::TypeDesc::UINT16
                                                    : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(width, height, channels, type);
  if (!encoding.channel_names.empty()) spec.channelnames = encoding.channel_names;
  if (!png && !encoding.half_channels.empty()) {
    // Channels of their own precision: the file's format per channel, half where asked.
    if (static_cast<int>(encoding.half_channels.size()) != channels)
      throw std::invalid_argument(what + ": a half_channels flag per channel");
    for (int c = 0; c < channels; ++c)
      spec.channelformats.push_back(encoding.half_channels[static_cast<size_t>(c)] ? OIIO::TypeDesc::HALF : type);
  }
  if (!png) spec.attribute("compression", encoding.compression);
  if (png) spec.attribute("png:compressionLevel", encoding.png_compression_level);
  if (png && encoding.png_filters != 0) spec.attribute("png:filter", encoding.png_filters);
  spec.attribute("Software", "nephele");
  spec.attribute("DateTime", "");
  for (const auto& [name, value] : encoding.attributes) spec.attribute(name, value);
  if (encoding.unassociated_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
  return {std::move(out), spec};
}

// Writes through a file descriptor, every write checked: a failed or short write is kept and
// reported by failed() (OpenImageIO's own file proxy does not report a failed fwrite).
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
    const auto* p = static_cast<const char*>(buf);
    size_t done = 0;
    while (done < size) {
      const ssize_t n = ::pwrite(fd_, p + done, size - done, static_cast<off_t>(offset) + static_cast<off_t>(done));
      if (n <= 0) {
        if (n < 0 && errno == EINTR) continue;
        error_ = n < 0 ? errno : ENOSPC;
        break;
      }
      done += static_cast<size_t>(n);
    }
    end_ = std::max<int64_t>(end_, offset + static_cast<int64_t>(done));
    return done;
  }
  size_t size() const override { return static_cast<size_t>(end_); }
  int error_number() const { return error_; }

 private:
  int fd_;
  int error_ = 0;
  int64_t end_ = 0;
};

}  // namespace

struct ImageRowWriter::State {
  std::filesystem::path path;
  core::FileDescriptor fd;
  std::unique_ptr<CheckedFileProxy> proxy;
  std::unique_ptr<OIIO::ImageOutput> out;
  int width = 0, height = 0, channels = 0, next_row = 0;
  bool closed = false;
};

ImageRowWriter::ImageRowWriter(const std::filesystem::path& path, int width, int height, int channels,
                               const ImageEncoding& encoding)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.width = width;
  s.height = height;
  s.channels = channels;
  const std::string shown = path.string();
  s.fd.reset(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666));
  if (s.fd.get() < 0) throw std::runtime_error("could not write " + shown + ": " + std::strerror(errno));
  auto [out, spec] = image_writer(width, height, channels, encoding, shown);
  s.out = std::move(out);
  s.proxy = std::make_unique<CheckedFileProxy>(shown, s.fd.get());
  if (!s.out->set_ioproxy(s.proxy.get()) || !s.out->open(shown, spec))
    throw std::runtime_error("could not open " + shown + ": " + s.out->geterror());
}

ImageRowWriter::~ImageRowWriter() {
  if (state_ && state_->out && !state_->closed) state_->out->close();
}

void ImageRowWriter::write_rows(int rows, const float* pixels) {
  State& s = *state_;
  if (rows < 0 || s.next_row + rows > s.height)
    throw std::logic_error("ImageRowWriter: more rows than the image's " + std::to_string(s.height));
  if (rows > 0 && !s.out->write_scanlines(s.next_row, s.next_row + rows, 0, OIIO::TypeDesc::FLOAT, pixels))
    throw std::runtime_error("could not write " + s.path.string() + ": " + s.out->geterror());
  if (s.proxy->error_number() != 0)
    throw std::runtime_error("could not write " + s.path.string() + ": " + std::strerror(s.proxy->error_number()));
  s.next_row += rows;
}

void ImageRowWriter::close() {
  State& s = *state_;
  if (s.next_row != s.height)
    throw std::logic_error("ImageRowWriter: " + std::to_string(s.next_row) + " of " + std::to_string(s.height) +
                           " rows written to " + s.path.string());
  const bool closed = s.out->close();
  s.closed = true;
  if (!closed || s.out->has_error())
    throw std::runtime_error("could not close " + s.path.string() + ": " + s.out->geterror());
  if (s.proxy->error_number() != 0)
    throw std::runtime_error("could not write " + s.path.string() + ": " + std::strerror(s.proxy->error_number()));
  if (::fsync(s.fd.get()) != 0) throw std::runtime_error("could not write " + s.path.string() + " (fsync)");
  if (!s.fd.close()) throw std::runtime_error("could not write " + s.path.string() + " (close)");
}

struct ImageRowReader::State {
  std::string shown;
  std::unique_ptr<OIIO::ImageInput> in;
  int width = 0, height = 0, channels = 0;
};

ImageRowReader::ImageRowReader(const std::filesystem::path& path) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.shown = path.string();
  core::regular_file_size(s.shown);  // a regular file, not a FIFO or device
  s.in = OIIO::ImageInput::open(s.shown);
  if (!s.in) throw std::runtime_error("could not read " + s.shown + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = s.in->spec();
  s.width = spec.width;
  s.height = spec.height;
  s.channels = spec.nchannels;
}

ImageRowReader::~ImageRowReader() {
  if (state_ && state_->in) state_->in->close();
}

int ImageRowReader::width() const { return state_->width; }
int ImageRowReader::height() const { return state_->height; }
int ImageRowReader::channels() const { return state_->channels; }

void ImageRowReader::read_rows(int first_row, int rows, float* out) {
  State& s = *state_;
  if (first_row < 0 || rows < 0 || first_row + rows > s.height)
    throw std::logic_error("ImageRowReader: rows outside " + s.shown);
  if (rows > 0 &&
      !s.in->read_scanlines(0, 0, first_row, first_row + rows, 0, 0, s.channels, OIIO::TypeDesc::FLOAT, out))
    throw std::runtime_error("could not read " + s.shown + ": " + s.in->geterror());
}

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
  if (frames.empty()) throw std::invalid_argument(what + ": an animation needs at least one frame");
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
    const ImageData& frame = frames[k];
    if (frame.width != first.width || frame.height != first.height || frame.channels != first.channels)
      throw std::invalid_argument(what + ": frame " + std::to_string(k) + " differs in size from the first");
    if (k > 0 && !out->open(what, spec, OIIO::ImageOutput::AppendSubimage)) throw fail("append a frame to");
    if (!out->write_image(OIIO::TypeDesc::FLOAT, frame.pixels.data())) throw fail("encode");
  }
  if (!out->close()) throw fail("close");
  if (out->has_error()) throw fail("encode");
  return bytes;
}

void write_image(const std::filesystem::path& path, const ImageData& image, const ImageEncoding& encoding) {
  const std::vector<unsigned char> bytes = encode_image(image, encoding, path.string());
  write_file(path, bytes.data(), bytes.size());
}

namespace {

std::unique_ptr<OIIO::ImageInput> open_image(const std::filesystem::path& path, ImageHeader& header) {
  core::regular_file_size(path.string());
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw std::runtime_error("could not read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  const auto base = spec.format.basetype;
  header = {spec.width, spec.height, spec.nchannels,
            base == OIIO::TypeDesc::FLOAT || base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::DOUBLE,
            std::vector<std::string>(spec.channelnames.begin(), spec.channelnames.end())};
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
    throw core::InputFileError(path.string() + ": declares an empty image (" + std::to_string(spec.width) + " x " +
                               std::to_string(spec.height) + " x " + std::to_string(spec.nchannels) + ")");
  return in;
}

}  // namespace

ImageHeader read_image_header(const std::filesystem::path& path) {
  ImageHeader header;
  open_image(path, header)->close();
  return header;
}

void check_image_budget(const std::filesystem::path& path, const ImageHeader& header, std::uint64_t max_bytes) {
  if (max_bytes == 0) max_bytes = core::input_memory_budget_bytes();
  const double bytes = 4.0 * header.width * double(header.height) * header.channels;
  if (bytes > double(max_bytes))
    throw core::InputFileError(path.string() + ": declares " + std::to_string(header.width) + " x " +
                               std::to_string(header.height) + " x " + std::to_string(header.channels) + " samples, " +
                               std::to_string(static_cast<std::uint64_t>(bytes) >> 20) + " MiB as float; at most " +
                               std::to_string(max_bytes >> 20) + " MiB (half the available memory) are read");
}

ImageData read_image(const std::filesystem::path& path, std::uint64_t max_bytes, ImageHeader* header_out) {
  ImageHeader header;
  auto in = open_image(path, header);
  const OIIO::ImageSpec& spec = in->spec();
  check_image_budget(path, header, max_bytes);
  if (header_out) *header_out = header;
  ImageData image{spec.width, spec.height, spec.nchannels, {}};
  image.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw std::runtime_error("could not read " + path.string() + ": " + in->geterror());
  in->close();
  return image;
}

bool draw_text(ImageData& image, int x, int y, const std::string& text, int size, const float rgb[3]) {
  static const char* const font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (image.channels != 3 || !std::filesystem::is_regular_file(font)) return false;
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec, image.pixels.data());  // draws into the image's own pixels
  return OIIO::ImageBufAlgo::render_text(buffer, x, y, text, size, font, OIIO::cspan<float>(rgb, 3));
}

}  // namespace nephele::files
