#pragma once
// Image files through OpenImageIO, which is loaded on first use (files/image_codecs.hpp). Coverage
// is data, not colour: nothing is sRGB-encoded.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/image.hpp"

namespace nephele::files {

using core::ImageData;

enum class ImageFormat { png, exr };

// How an image is stored. PNG (libpng, files/png_encoder.hpp): 8 or 16 bits of values in [0, 1],
// quantised linearly (round((2^bits - 1) v)), no gamma or sRGB chunk. EXR (OpenImageIO): 32-bit
// float or 16-bit half, zip-compressed unless another of OpenEXR's compressions is named.
struct ImageEncoding {
  ImageFormat format = ImageFormat::png;
  int bits = 8;                            // png: 8 or 16; exr: 32 (float) or 16 (half)
  std::vector<std::string> channel_names;  // empty: OpenImageIO's defaults (Y, RGB, RGBA ...)
  // exr: per channel, true stores it as 16-bit half whatever `bits` says (empty: all as `bits`).
  std::vector<bool> half_channels;
  std::string compression = "zip";                              // exr: none, rle, zips, zip, piz, pxr24, b44, dwaa
  std::vector<std::pair<std::string, std::string>> attributes;  // extra string metadata (OpenImageIO names)
  // With 4 channels: the colour is not premultiplied by alpha (white clouds with coverage in
  // alpha are stored as given; a PNG's colour would otherwise be divided by its alpha).
  bool unassociated_alpha = false;
  // png: zlib's level, 0 (none) .. 9 (smallest); 6 is zlib's default. The same pixels at any level.
  int png_compression_level = 6;
  // png: the row filters libpng may choose from, as libpng's PNG_FILTER_* bits (NONE 8, SUB 16,
  // UP 32, AVG 64, PAETH 128); 0 leaves libpng's default, which tries all five on every row.
  // One filter encodes faster; the pixels are the same with any.
  int png_filters = 0;
};

// libpng's PNG_FILTER_AVG bit, for ImageEncoding::png_filters.
inline constexpr int png_filter_average = 64;

inline ImageEncoding png_encoding(int bits = 8) {
  ImageEncoding e;
  e.bits = bits;
  return e;
}
inline ImageEncoding exr_encoding(std::vector<std::string> channel_names, int bits = 32,
                                  std::string compression = "zip") {
  ImageEncoding e;
  e.format = ImageFormat::exr;
  e.bits = bits;
  e.channel_names = std::move(channel_names);
  e.compression = std::move(compression);
  return e;
}

// OpenEXR's compressions that nephele offers (params::run::exr_compression lists the same).
bool is_exr_compression(const std::string& name);
// Whether OpenEXR's compression `name` gives back every value exactly: none, rle, zips, zip,
// piz (pxr24, b44 and dwaa round them).
bool is_lossless_exr_compression(const std::string& name);

// The file's bytes, encoded in memory, so that the caller writes them with every write, fsync
// and close checked (OpenImageIO's writers do not report a failed fwrite). Throws
// std::runtime_error naming `what` (the file's name) when encoding fails. Safe to call from
// several threads at once (each call has its own writer).
std::vector<unsigned char> encode_image(const ImageData& image, const ImageEncoding& encoding, const std::string& what);

// An image written row by row straight into its file, for images too large to hold whole (the
// faces of a cover in tiles, nephele assemble): the same bytes as encode_image gives for the same
// rows. Rows come in order, from row 0; close() checks that all came and fsyncs the file. Every
// write is checked (a full disk fails, naming the path); an image not closed leaves its file
// for the caller's output set to remove.
class ImageRowWriter {
 public:
  // Errors name `shown` where it is given (the final path of a file written aside), else `path`.
  ImageRowWriter(const std::filesystem::path& path, int width, int height, int channels, const ImageEncoding& encoding,
                 const std::string& shown = "");
  ~ImageRowWriter();
  ImageRowWriter(const ImageRowWriter&) = delete;
  ImageRowWriter& operator=(const ImageRowWriter&) = delete;
  // `rows` rows of width x channels floats from the next row on.
  void write_rows(int rows, const float* pixels);
  void close();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Rows of an image file read on demand, as floats (the streamed equirect map reads the faces
// of a cover too large to hold whole). Throws std::runtime_error naming the path.
class ImageRowReader {
 public:
  explicit ImageRowReader(const std::filesystem::path& path);
  ~ImageRowReader();
  ImageRowReader(const ImageRowReader&) = delete;
  ImageRowReader& operator=(const ImageRowReader&) = delete;
  int width() const;
  int height() const;
  int channels() const;
  // `rows` rows from `first_row` on, width x channels floats a row.
  void read_rows(int first_row, int rows, float* out);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// An animated GIF of `frames` (one size, 1 or 3 channels in [0, 1]) shown at `frames_per_second`
// and looping, in memory: the previews of frame sequences (generate --sequence).
std::vector<unsigned char> encode_animation(const std::vector<ImageData>& frames, int frames_per_second,
                                            const std::string& what);

// The one image writer: encodes and writes `path` (replacing it in place; output sets write
// through OutputSet::write instead).
void write_image(const std::filesystem::path& path, const ImageData& image, const ImageEncoding& encoding);

// What a file's header declares, read without its pixels. float_samples: the file stores float
// or half samples (linear values), else integers (display-encoded colour in JPEG and PNG).
struct ImageHeader {
  int width = 0, height = 0, channels = 0;
  bool float_samples = false;
  // In the order read_image gives the channels (OpenEXR stores them sorted by name; OpenImageIO
  // puts R, G, B, A first).
  std::vector<std::string> channel_names;
};

// The one image reader. The path must be a regular file (core::regular_file_size: a FIFO cannot
// block it) and the header's width x height x channels as floats must fit `max_bytes`
// (0: core::input_memory_budget_bytes()), checked before any pixel is allocated; a header that
// declares 40000 x 40000 is refused, not attempted. Throws core::InputFileError (the caller names
// the option) or std::runtime_error naming the path.
ImageHeader read_image_header(const std::filesystem::path& path);
// Throws core::InputFileError naming the path when an image of `header`'s size would take more
// than `max_bytes` as floats (0: half the available memory): read_image's check before it reads.
void check_image_budget(const std::filesystem::path& path, const ImageHeader& header, std::uint64_t max_bytes = 0);
ImageData read_image(const std::filesystem::path& path, std::uint64_t max_bytes = 0, ImageHeader* header = nullptr);

// Starts loading OpenImageIO's module on another thread, so that the first image read or write
// finds it loaded: for a command that will write images, once its OpenGL context is made (both
// load libraries, and the loader takes one library at a time). A load that fails reports at that
// first use. Calls after the first, or after an image was read or written, do nothing.
void preload_image_codecs();

// Draws `text` into an RGB image with its baseline's left end at (x, y), `size` pixels high,
// in DejaVu Sans (fonts-dejavu-core) through OpenImageIO's FreeType text. Returns false and
// leaves the image as it was when the font or FreeType is not there (a plot then has no labels).
bool draw_text(ImageData& image, int x, int y, const std::string& text, int size, const float rgb[3]);

}  // namespace nephele::files
