#include "files/image_files.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <future>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "core/file_descriptor.hpp"
#include "core/input_file.hpp"
#include "files/atomic_output.hpp"
#include "files/image_codecs.hpp"
#include "files/png_encoder.hpp"

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

// Where the module may be: $NEPHELE_IMAGE_CODECS, beside the executable (build/, an installed
// bin/ or a bundle), where the build put it (the test programs in build/tests).
std::vector<std::string> module_candidates() {
  std::vector<std::string> paths;
  if (const char* path = std::getenv("NEPHELE_IMAGE_CODECS"); path && *path) return {path};
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) paths.push_back((executable.parent_path() / image_codecs_file).string());
#ifdef NEPHELE_IMAGE_CODECS_BUILD_PATH
  if (paths.empty() || paths.front() != NEPHELE_IMAGE_CODECS_BUILD_PATH)
    paths.push_back(NEPHELE_IMAGE_CODECS_BUILD_PATH);
#endif
  return paths;
}

struct LoadedCodecs {
  const ImageCodecs* table = nullptr;
  std::string error;  // why none loaded
};

LoadedCodecs load_codecs() {
  std::string tried;
  for (const auto& path : module_candidates()) {
    if (!std::filesystem::exists(path)) {
      tried += "\n  " + path + ": no such file";
      continue;
    }
    // RTLD_NOW: a missing library shows here, not at the first call; never closed.
    void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) {
      const char* why = ::dlerror();
      tried += "\n  " + path + ": " + (why ? why : "dlopen failed");
      continue;
    }
    using Entry = const ImageCodecs* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(module, image_codecs_entry));
    const ImageCodecs* table = entry ? entry() : nullptr;
    if (!table || table->version != image_codecs_version) {
      tried += "\n  " + path + ": not a nephele image codec module of version " + std::to_string(image_codecs_version);
      continue;
    }
    return {table, {}};
  }
  return {nullptr, "image files need the module " + std::string(image_codecs_file) +
                       " (OpenImageIO; set NEPHELE_IMAGE_CODECS to its path), which did not load:" + tried};
}

std::mutex preload_mutex;
std::future<LoadedCodecs> preloading;  // preload_image_codecs' load, until image_codecs takes it
bool preload_started = false;

}  // namespace

const ImageCodecs& image_codecs() {
  static const LoadedCodecs loaded = [] {
    std::future<LoadedCodecs> pending;
    {
      const std::lock_guard<std::mutex> lock(preload_mutex);
      preload_started = true;
      pending = std::move(preloading);
    }
    return pending.valid() ? pending.get() : load_codecs();
  }();
  if (!loaded.table) throw std::runtime_error(loaded.error);
  return *loaded.table;
}

void preload_image_codecs() {
  const std::lock_guard<std::mutex> lock(preload_mutex);
  if (preload_started) return;
  preload_started = true;
  preloading = std::async(std::launch::async, load_codecs);
}

namespace {

// The checks of an encoding that the codecs rely on.
void check_encoding(int channels, const ImageEncoding& encoding, const std::string& what) {
  const bool png = encoding.format == ImageFormat::png;
  if (png ? (encoding.bits != 8 && encoding.bits != 16) : (encoding.bits != 32 && encoding.bits != 16))
    throw std::invalid_argument(what + ": " + std::to_string(encoding.bits) +
                                "-bit images are not written (PNG: 8 or 16, EXR: 16 or 32)");
  if (!png && !is_exr_compression(encoding.compression))
    throw std::invalid_argument(what + ": unknown EXR compression '" + encoding.compression + "'");
  if (!png && !encoding.half_channels.empty() && static_cast<int>(encoding.half_channels.size()) != channels)
    throw std::invalid_argument(what + ": a half_channels flag per channel");
}

}  // namespace

struct ImageRowWriter::State {
  std::filesystem::path path;
  std::string shown;  // the name errors give
  core::FileDescriptor fd;
  std::unique_ptr<PngEncoder> png;                                                            // PNG (libpng)
  std::unique_ptr<ImageWriterHandle, void (*)(ImageWriterHandle*)> writer{nullptr, nullptr};  // else
  int width = 0, height = 0, channels = 0, next_row = 0;
};

ImageRowWriter::ImageRowWriter(const std::filesystem::path& path, int width, int height, int channels,
                               const ImageEncoding& encoding, const std::string& shown_as)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.width = width;
  s.height = height;
  s.channels = channels;
  const std::string shown = shown_as.empty() ? path.string() : shown_as;
  s.shown = shown;
  check_encoding(channels, encoding, shown);
  const ImageCodecs* codecs = encoding.format == ImageFormat::png ? nullptr : &image_codecs();
  s.fd.reset(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666));
  if (s.fd.get() < 0) throw std::runtime_error("could not write " + shown + ": " + std::strerror(errno));
  if (codecs == nullptr) {
    const int fd = s.fd.get();  // libpng writes in order, from the file's start
    s.png = std::make_unique<PngEncoder>(
        [fd](const unsigned char* bytes, std::size_t size) { return core::write_exactly(fd, bytes, size) ? 0 : errno; },
        width, height, channels, encoding, shown);
  } else {
    s.writer = {codecs->open_writer(s.fd.get(), shown, width, height, channels, encoding), codecs->free_writer};
  }
}

ImageRowWriter::~ImageRowWriter() = default;

void ImageRowWriter::write_rows(int rows, const float* pixels) {
  State& s = *state_;
  if (rows < 0 || s.next_row + rows > s.height)
    throw std::logic_error("ImageRowWriter: more rows than the image's " + std::to_string(s.height));
  if (s.png)
    s.png->write_rows(rows, pixels);
  else
    image_codecs().write_rows(s.writer.get(), s.next_row, rows, pixels);
  s.next_row += rows;
}

void ImageRowWriter::close() {
  State& s = *state_;
  if (s.next_row != s.height)
    throw std::logic_error("ImageRowWriter: " + std::to_string(s.next_row) + " of " + std::to_string(s.height) +
                           " rows written to " + s.shown);
  if (s.png)
    s.png->finish();
  else
    image_codecs().finish_writer(s.writer.get());
  if (::fsync(s.fd.get()) != 0)
    throw std::runtime_error("could not write " + s.shown + " (fsync): " + std::strerror(errno));
  if (!s.fd.close()) throw std::runtime_error("could not write " + s.shown + " (close): " + std::strerror(errno));
}

namespace {

using ReaderPointer = std::unique_ptr<ImageReaderHandle, void (*)(ImageReaderHandle*)>;

// The image at `path` opened (a regular file: a FIFO cannot block it), its header in `header`.
ReaderPointer open_image(const std::filesystem::path& path, ImageHeader& header) {
  core::regular_file_size(path.string());
  const ImageCodecs& codecs = image_codecs();
  ReaderPointer reader{codecs.open_reader(path.string(), header), codecs.free_reader};
  if (header.width < 1 || header.height < 1 || header.channels < 1)
    throw core::InputFileError(path.string() + ": declares an empty image (" + std::to_string(header.width) + " x " +
                               std::to_string(header.height) + " x " + std::to_string(header.channels) + ")");
  return reader;
}

}  // namespace

struct ImageRowReader::State {
  std::string shown;
  ReaderPointer reader{nullptr, nullptr};
  ImageHeader header;
};

ImageRowReader::ImageRowReader(const std::filesystem::path& path) : state_(std::make_unique<State>()) {
  state_->shown = path.string();
  state_->reader = open_image(path, state_->header);
}

ImageRowReader::~ImageRowReader() = default;

int ImageRowReader::width() const { return state_->header.width; }
int ImageRowReader::height() const { return state_->header.height; }
int ImageRowReader::channels() const { return state_->header.channels; }

void ImageRowReader::read_rows(int first_row, int rows, float* out) {
  State& s = *state_;
  if (first_row < 0 || rows < 0 || first_row + rows > s.header.height)
    throw std::logic_error("ImageRowReader: rows outside " + s.shown);
  image_codecs().read_rows(s.reader.get(), first_row, rows, out);
}

std::vector<unsigned char> encode_image(const ImageData& image, const ImageEncoding& encoding,
                                        const std::string& what) {
  check_encoding(image.channels, encoding, what);
  if (encoding.format != ImageFormat::png) return image_codecs().encode_image(image, encoding, what);
  std::vector<unsigned char> bytes;
  PngEncoder png(
      [&bytes](const unsigned char* data, std::size_t size) {
        bytes.insert(bytes.end(), data, data + size);
        return 0;
      },
      image.width, image.height, image.channels, encoding, what);
  png.write_rows(image.height, image.pixels.data());
  png.finish();
  return bytes;
}

std::vector<unsigned char> encode_animation(const std::vector<ImageData>& frames, int frames_per_second,
                                            const std::string& what) {
  if (frames.empty()) throw std::invalid_argument(what + ": an animation needs at least one frame");
  for (size_t k = 1; k < frames.size(); ++k)
    if (frames[k].width != frames[0].width || frames[k].height != frames[0].height ||
        frames[k].channels != frames[0].channels)
      throw std::invalid_argument(what + ": frame " + std::to_string(k) + " differs in size from the first");
  return image_codecs().encode_animation(frames, frames_per_second, what);
}

void write_image(const std::filesystem::path& path, const ImageData& image, const ImageEncoding& encoding) {
  const std::vector<unsigned char> bytes = encode_image(image, encoding, path.string());
  write_file(path, bytes.data(), bytes.size());
}

ImageHeader read_image_header(const std::filesystem::path& path) {
  ImageHeader header;
  open_image(path, header);
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
  const ReaderPointer reader = open_image(path, header);
  check_image_budget(path, header, max_bytes);
  if (header_out) *header_out = header;
  ImageData image{header.width, header.height, header.channels, {}};
  image.pixels.resize(static_cast<size_t>(header.width) * header.height * header.channels);
  image_codecs().read_all(reader.get(), image.pixels.data());
  return image;
}

bool draw_text(ImageData& image, int x, int y, const std::string& text, int size, const float rgb[3]) {
  static const char* const font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (image.channels != 3 || !std::filesystem::is_regular_file(font)) return false;
  return image_codecs().draw_text(image, x, y, text, size, rgb, font);
}

}  // namespace nephele::files
